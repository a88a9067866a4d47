//! Make-syntax dependency files (`--depfile`), as `gcc -MD` and `slangc
//! -depfile` write them: one rule naming every output as a target and every
//! file read (inputs, `#include`s) as a prerequisite, then an empty rule
//! for each prerequisite (`gcc -MP`), so that make does not fail when an
//! included file is deleted. ninja reads the same file (`deps = gcc`).

use std::path::{Path, PathBuf};

/// The depfile text. Paths are written as given; each list is sorted and
/// without repeats, so the text does not depend on the order of the jobs.
pub fn render(targets: &[PathBuf], prerequisites: &[PathBuf]) -> String {
    let sorted = |v: &[PathBuf]| {
        let mut v: Vec<String> = v.iter().map(|p| escape(p)).collect();
        v.sort();
        v.dedup();
        v
    };
    let targets = sorted(targets);
    let prerequisites = sorted(prerequisites);
    let mut out = targets.join(" \\\n");
    out.push(':');
    for p in &prerequisites {
        out.push_str(" \\\n  ");
        out.push_str(p);
    }
    out.push('\n');
    for p in &prerequisites {
        out.push('\n');
        out.push_str(p);
        out.push_str(":\n");
    }
    out
}

/// A path as make reads it: spaces, `#`, `:` and `\` before them escaped
/// with a backslash, `$` doubled.
fn escape(p: &Path) -> String {
    let s = p.to_string_lossy();
    let mut out = String::with_capacity(s.len());
    let chars: Vec<char> = s.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        match c {
            ' ' | '#' | '\t' => {
                // Backslashes right before an escaped character are doubled.
                let mut k = i;
                while k > 0 && chars[k - 1] == '\\' {
                    out.push('\\');
                    k -= 1;
                }
                out.push('\\');
                out.push(c);
            }
            '$' => out.push_str("$$"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_rule_sorted_with_phony_prerequisites() {
        let t = render(&["out/b.wgsl".into(), "out/a.spv".into()], &["x.das".into(), "inc/c.das".into(), "x.das".into()]);
        assert_eq!(t, "out/a.spv \\\nout/b.wgsl: \\\n  inc/c.das \\\n  x.das\n\ninc/c.das:\n\nx.das:\n");
    }

    #[test]
    fn special_characters_are_escaped() {
        assert_eq!(escape(Path::new("my dir/a#1$.das")), "my\\ dir/a\\#1$$.das");
        assert_eq!(escape(Path::new("a\\ b")), "a\\\\\\ b");
    }
}
