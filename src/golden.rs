//! Golden-output checks: compare freshly compiled artifacts with the copies
//! checked into a directory, and re-bless them on request. Feature `golden`
//! (on by default, and in `cli` for `umbrac compile --check`).
//!
//! Used by umbrac's own tests, by `umbrac compile --check`, and by users'
//! `#[test]`s:
//!
//! ```no_run
//! let c = umbrac::compile_file("shaders/shadow.das".as_ref(), &Default::default());
//! let compiled = c.result.expect("compiles");
//! // Fails with a unified diff per changed file; UMBRAC_BLESS=1 rewrites them.
//! umbrac::golden::check_or_bless(&compiled.artifacts, "tests/golden/shadow".as_ref()).unwrap();
//! ```

use std::fmt;
use std::path::{Path, PathBuf};

use crate::target::Artifact;

/// Environment variable that turns a check into a re-bless.
pub const BLESS_ENV: &str = "UMBRAC_BLESS";

/// One way the directory disagrees with the artifacts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Difference {
    /// The file exists with other contents; `diff` is a unified diff (or a
    /// note for binary files).
    Changed { file: PathBuf, diff: String },
    /// The compiler produces this file but the directory lacks it.
    Missing { file: PathBuf },
    /// The directory holds an output file the compiler no longer produces.
    Stale { file: PathBuf },
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Difference::Changed { diff, .. } => f.write_str(diff),
            Difference::Missing { file } => writeln!(f, "missing: {} (the compiler produces it)", file.display()),
            Difference::Stale { file } => writeln!(f, "stale: {} (the compiler no longer produces it)", file.display()),
        }
    }
}

/// A unified diff of two texts, with `name` in the headers.
pub fn unified_diff(old: &str, new: &str, name: &str) -> String {
    similar::TextDiff::from_lines(old, new).unified_diff().context_radius(3).header(&format!("a/{name}"), &format!("b/{name}")).to_string()
}

pub use crate::output::is_output_name;

/// Compares artifacts with the files in `dir`.
pub fn compare(artifacts: &[Artifact], dir: &Path) -> std::io::Result<Vec<Difference>> {
    let mut out = Vec::new();
    for a in artifacts {
        let path = dir.join(&a.file_name);
        match std::fs::read(&path) {
            Ok(old) if old == a.contents => {}
            Ok(old) => {
                let diff = match (std::str::from_utf8(&old), std::str::from_utf8(&a.contents)) {
                    (Ok(o), Ok(n)) if !a.file_name.ends_with(".spv") => unified_diff(o, n, &path.display().to_string()),
                    _ => format!("binary file {} differs ({} bytes checked in, {} bytes now)\n", path.display(), old.len(), a.contents.len()),
                };
                out.push(Difference::Changed { file: path, diff });
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => out.push(Difference::Missing { file: path }),
            Err(e) => return Err(e),
        }
    }
    out.extend(crate::output::stale_outputs(dir, artifacts).into_iter().map(|file| Difference::Stale { file }));
    Ok(out)
}

/// Rewrites `dir` to hold exactly the artifacts (stale outputs removed).
pub fn bless(artifacts: &[Artifact], dir: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for d in compare(artifacts, dir)? {
        if let Difference::Stale { file } = d {
            std::fs::remove_file(file)?;
        }
    }
    crate::output::write_artifacts(dir, artifacts).map_err(std::io::Error::other)
}

/// Checks the artifacts against `dir`; with `UMBRAC_BLESS=1` in the
/// environment, rewrites `dir` instead. The error text lists every
/// difference and says how to re-bless.
pub fn check_or_bless(artifacts: &[Artifact], dir: &Path) -> Result<(), String> {
    if std::env::var(BLESS_ENV).is_ok_and(|v| v == "1") {
        return bless(artifacts, dir).map_err(|e| format!("cannot bless {}: {e}", dir.display()));
    }
    let diffs = compare(artifacts, dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    if diffs.is_empty() {
        return Ok(());
    }
    let mut msg = format!("{} golden file(s) in {} differ from the compiler's output:\n", diffs.len(), dir.display());
    for d in &diffs {
        msg.push_str(&d.to_string());
    }
    msg.push_str(&format!("\nIf the change is intended, re-bless with {BLESS_ENV}=1 and review the diff.\n"));
    Err(msg)
}
