//! Many files at once: which files under a directory are programs, and
//! compiling many of them on a bounded pool of compiler threads. The CLI,
//! [`crate::build`] and the golden tests all go through here, so they agree
//! on both.

use std::collections::HashSet;
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use crate::{Compilation, Diagnostic, Options, SourceMap};

/// A program found under a directory.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    pub path: PathBuf,
    /// The directory holding it, relative to the directory searched (empty
    /// for a file directly in it): where its outputs go under an output
    /// directory.
    pub subdir: PathBuf,
}

/// Why a directory could not be listed.
#[derive(Clone, Debug)]
pub struct ListError {
    pub path: PathBuf,
    pub message: String,
}

impl fmt::Display for ListError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: {}", self.path.display(), self.message)
    }
}

impl std::error::Error for ListError {}

/// The programs under `dir`: every `.das` file in it and in its
/// subdirectories, sorted by path. Directories named `include` hold shared
/// `#include`s, not programs, and are skipped, as are hidden files and
/// directories (names starting with `.`: editors' lock and backup files).
/// A symbolic link is followed, but each directory is visited once, so
/// links that form a cycle end the walk instead of repeating it. A `.das`
/// entry that is not a regular file (a FIFO, a device, a dangling link) is
/// an error: reading it could block or never end.
pub fn programs_under(dir: &Path) -> Result<Vec<Found>, ListError> {
    let err = |path: &Path, message: String| ListError { path: path.to_path_buf(), message };
    let mut found = Vec::new();
    let mut visited = HashSet::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(d) = pending.pop() {
        let canonical = d.canonicalize().map_err(|e| err(&d, format!("cannot read directory: {e}")))?;
        if !visited.insert(canonical) {
            continue;
        }
        let entries = std::fs::read_dir(&d).map_err(|e| err(&d, format!("cannot read directory: {e}")))?;
        for entry in entries {
            let path = entry.map_err(|e| err(&d, format!("cannot read directory: {e}")))?.path();
            let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            if name.starts_with('.') {
                continue;
            }
            // Follows links: what the entry is, not what names it.
            let meta = std::fs::metadata(&path);
            let is_das = path.extension().is_some_and(|x| x == "das");
            match meta {
                Ok(m) if m.is_dir() => {
                    if name != "include" {
                        pending.push(path);
                    }
                }
                Ok(m) if m.is_file() => {
                    if is_das {
                        found.push(path);
                    }
                }
                Ok(_) if is_das => return Err(err(&path, "is not a regular file (a FIFO, socket or device?)".into())),
                Err(e) if is_das => return Err(err(&path, format!("cannot read: {e}"))),
                _ => {}
            }
        }
    }
    found.sort();
    Ok(found
        .into_iter()
        .map(|path| {
            let subdir = path.parent().and_then(|p| p.strip_prefix(dir).ok()).map(Path::to_path_buf).unwrap_or_default();
            Found { path, subdir }
        })
        .collect())
}

/// One file to compile, and how.
#[derive(Clone, Copy, Debug)]
pub struct Job<'a> {
    pub path: &'a Path,
    pub opts: &'a Options,
}

/// How many compilations to run at once by default: the cores available.
pub fn default_workers() -> usize {
    std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
}

/// Compiles every job, at most `workers` at a time, each on a compiler
/// thread (see [`crate::spawn_compiler_thread`]); the results come back in
/// the jobs' order. A panic in one compilation is an internal-error
/// diagnostic naming its file and does not stop the others. If no thread
/// can be started, the jobs left run on the calling thread.
pub fn compile_many(jobs: &[Job<'_>], workers: usize) -> Vec<Compilation> {
    let results: Vec<Mutex<Option<Compilation>>> = jobs.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let run_next = || loop {
        let i = next.fetch_add(1, Ordering::Relaxed);
        let Some(job) = jobs.get(i) else { break };
        let c = compile_caught(job);
        if let Ok(mut slot) = results[i].lock() {
            *slot = Some(c);
        }
    };
    let workers = workers.clamp(1, jobs.len().max(1));
    std::thread::scope(|s| {
        for _ in 0..workers {
            if crate::spawn_compiler_thread(s, run_next).is_err() {
                break;
            }
        }
    });
    results.into_iter().zip(jobs).map(|(slot, job)| slot.into_inner().ok().flatten().unwrap_or_else(|| compile_caught(job))).collect()
}

fn compile_caught(job: &Job<'_>) -> Compilation {
    std::panic::catch_unwind(|| crate::compile_file(job.path, job.opts)).unwrap_or_else(|payload| {
        let msg = format!("the compiler panicked while compiling `{}`: {}", job.path.display(), crate::diag::panic_message(&*payload));
        Compilation { sources: SourceMap::new(), diagnostics: vec![Diagnostic::bug(msg, None)], suppressed_errors: 0, result: None }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(found: &[Found]) -> Vec<String> {
        found.iter().map(|f| f.path.file_name().unwrap().to_string_lossy().into_owned()).collect()
    }

    #[test]
    fn lists_programs_recursively_skipping_includes_and_hidden_entries() {
        let t = tempfile::tempdir().unwrap();
        let root = t.path();
        for f in ["b.das", "a.das", "notes.txt", "sub/c.das", "include/common.das", ".hidden/d.das", ".#lock.das", "sub/include/e.das"] {
            let p = root.join(f);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(p, "").unwrap();
        }
        let found = programs_under(root).unwrap();
        assert_eq!(names(&found), ["a.das", "b.das", "c.das"]);
        assert_eq!(found[2].subdir, Path::new("sub"));
        assert_eq!(found[0].subdir, Path::new(""));
    }

    #[cfg(unix)]
    #[test]
    fn symlink_cycles_end_and_fifos_are_refused() {
        let t = tempfile::tempdir().unwrap();
        let root = t.path();
        std::fs::create_dir_all(root.join("inner")).unwrap();
        std::fs::write(root.join("inner/x.das"), "").unwrap();
        std::os::unix::fs::symlink(".", root.join("self")).unwrap();
        std::os::unix::fs::symlink("..", root.join("inner/up")).unwrap();
        let found = programs_under(root).unwrap();
        assert_eq!(names(&found), ["x.das"], "each directory once");

        let fifo = root.join("inner/pipe.das");
        let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        // SAFETY: a valid NUL-terminated path; mkfifo only creates a file.
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        let e = programs_under(root).unwrap_err();
        assert!(e.path.ends_with("pipe.das") && e.message.contains("not a regular file"), "{e}");
    }

    #[test]
    fn compiles_in_job_order_on_any_number_of_workers() {
        let t = tempfile::tempdir().unwrap();
        let good = t.path().join("good.das");
        let bad = t.path().join("bad.das");
        std::fs::write(&good, "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n").unwrap();
        std::fs::write(&bad, "[fragment_program]\ndef fs {\n    nope = 1\n}\n").unwrap();
        let opts = Options::default();
        let jobs = [Job { path: &good, opts: &opts }, Job { path: &bad, opts: &opts }, Job { path: &good, opts: &opts }];
        for workers in [1, 2, 8] {
            let out = compile_many(&jobs, workers);
            let ok: Vec<bool> = out.iter().map(|c| !c.has_errors()).collect();
            assert_eq!(ok, [true, false, true], "{workers} workers");
        }
        assert!(compile_many(&[], 4).is_empty());
    }
}
