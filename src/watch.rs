//! `--watch`: run a step, then again whenever a file it read changes
//! (feature `cli`; the notify crate: inotify on Linux, FSEvents on macOS,
//! ReadDirectoryChangesW on Windows).
//!
//! The parent directory of each file is watched, not the file: editors
//! save by writing a new file and renaming it over the old one, which a
//! watch on the old file would not see. Events come in bursts (truncate,
//! write, rename); a step runs once the files it read have been quiet
//! for [`QUIET`] (at most [`MAX_WAIT`] after the first change). A step
//! prints its own diagnostics; its outputs are written only when it
//! succeeds, so a failed edit leaves the last good ones.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use notify::{RecursiveMode, Watcher};

/// How long the files must be quiet before a step runs again.
pub const QUIET: Duration = Duration::from_millis(25);

/// The longest a step waits for quiet once a change came.
pub const MAX_WAIT: Duration = Duration::from_millis(500);

pub use crate::run::Watched;

/// Runs `step` now and after every change to what its last run read, until
/// the process is interrupted. `step` returns its exit code (printed when
/// not 0) and what to watch. Returns only if watching fails.
pub fn watch(mut step: impl FnMut() -> (u8, Watched)) -> Result<(), String> {
    let (tx, rx) = mpsc::channel();
    let mut watcher = notify::recommended_watcher(move |e: notify::Result<notify::Event>| {
        let _ = tx.send(e);
    })
    .map_err(|e| format!("cannot watch files: {e}"))?;
    let mut watching: HashSet<(PathBuf, bool)> = HashSet::new();
    loop {
        let started = Instant::now();
        let (code, what) = step();
        let took = started.elapsed();
        let files: HashSet<PathBuf> = what.files.iter().map(|f| absolute(f)).collect();
        let dirs: Vec<PathBuf> = what.dirs.iter().map(|d| absolute(d)).collect();
        // Watch each file's directory and each directory argument (recursively).
        let mut wanted: HashSet<(PathBuf, bool)> = files.iter().filter_map(|f| f.parent().map(|p| (p.to_path_buf(), false))).collect();
        wanted.extend(dirs.iter().map(|d| (d.clone(), true)));
        for (dir, recursive) in watching.difference(&wanted) {
            let _ = watcher.unwatch(dir);
            let _ = recursive;
        }
        for (dir, recursive) in wanted.difference(&watching) {
            let mode = if *recursive { RecursiveMode::Recursive } else { RecursiveMode::NonRecursive };
            if let Err(e) = watcher.watch(dir, mode) {
                eprintln!("warning: cannot watch `{}`: {e}", dir.display());
            }
        }
        watching = wanted;
        let status = if code == 0 { "ok".to_string() } else { format!("failed (exit status {code})") };
        eprintln!("[watch] {status} in {:.1} ms; watching {} files, Ctrl-C to stop", took.as_secs_f64() * 1e3, files.len());

        // Wait for a change to something read, then for quiet.
        let relevant = |e: &notify::Event| {
            !matches!(e.kind, notify::EventKind::Access(_))
                && e.paths.iter().any(|p| files.contains(p) || (p.extension().is_some_and(|x| x == "das") && dirs.iter().any(|d| p.starts_with(d))))
        };
        loop {
            match rx.recv() {
                Ok(Ok(e)) if relevant(&e) => break,
                Ok(_) => continue,
                Err(_) => return Err("the file watcher stopped".into()),
            }
        }
        // Only changes to what was read extend the quiet wait: reads of
        // other files in the same directory (a log another program polls)
        // come every few milliseconds and would hold the step off for ever.
        // A file that never stops changing still gets a step every
        // `MAX_WAIT`.
        let first = Instant::now();
        let mut last = first;
        while first.elapsed() < MAX_WAIT {
            let left = QUIET.saturating_sub(last.elapsed());
            if left.is_zero() {
                break;
            }
            match rx.recv_timeout(left) {
                Ok(Ok(e)) if relevant(&e) => last = Instant::now(),
                Ok(_) => {}
                Err(mpsc::RecvTimeoutError::Timeout) => break,
                Err(mpsc::RecvTimeoutError::Disconnected) => return Err("the file watcher stopped".into()),
            }
        }
    }
}

fn absolute(p: &Path) -> PathBuf {
    std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf())
}
