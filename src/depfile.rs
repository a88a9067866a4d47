//! Make-syntax dependency files (`--depfile`), as `gcc -MD` and `slangc
//! -depfile` write them: one rule naming every output as a target and every
//! file read (inputs, `#include`s) as a prerequisite, then an empty rule
//! for each prerequisite (`gcc -MP`), so that make does not fail when an
//! included file is deleted. ninja reads the same file (`deps = gcc`).

use std::path::{Path, PathBuf};

/// A path make cannot read back: a line break ends a rule, and no escape
/// brings it back (the run is refused before anything is written).
pub fn unwritable(paths: &[PathBuf]) -> Option<&Path> {
    paths.iter().map(PathBuf::as_path).find(|p| p.to_string_lossy().contains(['\n', '\r']))
}

/// A depfile written before the outputs, under a temporary name beside
/// where it goes, and renamed into place once they are: a depfile that
/// cannot be written fails the run before any output changes, and a run
/// that fails later leaves the old depfile (dropping it removes the
/// temporary).
pub struct Pending {
    temp: PathBuf,
    path: PathBuf,
    /// The directories made for it (a depfile inside the output directory
    /// of a first run), deepest first: removed again, when empty, if the
    /// run fails.
    made: Vec<PathBuf>,
    done: bool,
}

impl Pending {
    pub fn write(path: &Path, text: &[u8]) -> Result<Pending, String> {
        let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let name = path.file_name().ok_or_else(|| format!("cannot write the depfile `{}`: not a file name", path.display()))?;
        let temp = dir.join(format!(".{}.umbrac-{}.tmp", name.to_string_lossy(), std::process::id()));
        let made: Vec<PathBuf> = dir.ancestors().take_while(|d| !d.as_os_str().is_empty() && !d.exists()).map(Path::to_path_buf).collect();
        let mut pending = Pending { temp, path: path.to_path_buf(), made, done: false };
        let written = std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&pending.temp, text));
        if let Err(e) = written {
            pending.remove();
            return Err(format!("cannot write the depfile `{}`: {e}; nothing was written", path.display()));
        }
        Ok(pending)
    }

    fn remove(&mut self) {
        self.done = true;
        let _ = std::fs::remove_file(&self.temp);
        for d in &self.made {
            let _ = std::fs::remove_dir(d);
        }
    }

    /// Puts the depfile in place (the outputs are written).
    pub fn commit(mut self) -> Result<(), String> {
        self.done = true;
        std::fs::rename(&self.temp, &self.path).map_err(|e| {
            let _ = std::fs::remove_file(&self.temp);
            format!("cannot write the depfile `{}`: {e}", self.path.display())
        })
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        if !self.done {
            self.remove();
        }
    }
}

/// The depfile text. Paths are normalised (`stable`); each list is sorted
/// and without repeats, so the text does not depend on the order of the
/// jobs. With `base` (the working directory, when the inputs were named
/// relative to it) an absolute path under it is written relative.
pub fn render(targets: &[PathBuf], prerequisites: &[PathBuf], base: Option<&Path>) -> String {
    let sorted = |v: &[PathBuf]| {
        let mut v: Vec<String> = v.iter().map(|p| escape(&stable(p, base))).collect();
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

/// `p` without `.` and `..` components (`inc/lib/../palette.das` is
/// `inc/palette.das`: Bazel, ninja and make compare paths by their text),
/// unless a `..` crosses a symbolic link and the short path names another
/// file; relative to `base` when under it.
fn stable(p: &Path, base: Option<&Path>) -> PathBuf {
    let mut short = crate::syntax::normalize(p);
    if short != p && !same_file(&short, p) {
        short = p.to_path_buf();
    }
    match base.and_then(|b| short.strip_prefix(crate::syntax::normalize(b)).ok()) {
        Some(rel) if !rel.as_os_str().is_empty() => rel.to_path_buf(),
        _ => short,
    }
}

/// Whether two paths reach one file; two that do not exist yet (outputs)
/// are taken as the same when neither has a `..` to cross a link by.
fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        (Err(_), Err(_)) => !b.components().any(|c| c == std::path::Component::ParentDir),
        _ => false,
    }
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
        let t = render(&["out/b.wgsl".into(), "./out/a.spv".into()], &["x.das".into(), "inc/c.das".into(), "x.das".into()], None);
        assert_eq!(t, "out/a.spv \\\nout/b.wgsl: \\\n  inc/c.das \\\n  x.das\n\ninc/c.das:\n\nx.das:\n");
    }

    #[test]
    fn paths_are_normalised_and_made_relative_to_the_base() {
        let base = std::env::temp_dir();
        let abs = base.join("umbrac-no-such-dir/o.wgsl");
        let t = render(&[abs.clone(), "/elsewhere/./p.wgsl".into()], &[], Some(&base));
        assert_eq!(t, "/elsewhere/p.wgsl \\\numbrac-no-such-dir/o.wgsl:\n", "{t}");
        // An output path with `..` that exists nowhere yet is kept as given.
        let t = render(&["a/../b.wgsl".into()], &[], None);
        assert_eq!(t, "a/../b.wgsl:\n");
    }

    #[test]
    fn special_characters_are_escaped() {
        assert_eq!(escape(Path::new("my dir/a#1$.das")), "my\\ dir/a\\#1$$.das");
        assert_eq!(escape(Path::new("a\\ b")), "a\\\\\\ b");
    }
}
