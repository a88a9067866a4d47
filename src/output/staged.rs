//! New directories of an output directory, built under a hidden stage
//! inside it while the compiles that fill them are still running, then
//! renamed into place.
//!
//! A cold run with variants writes hundreds of directories of new files.
//! Through [`super::write_outputs`] each file costs a lookup, a temporary
//! and a rename, and all of it waits until every variant has compiled (a
//! run is all or nothing). Staged, each variant's files are written under
//! their own names as soon as it compiles, and at the end one rename per
//! variant directory publishes them; none replaces anything
//! (`RENAME_NOREPLACE`). Should one fail (another process made that
//! directory meanwhile), those already published are moved back and the
//! caller writes everything the usual way. A failed run removes the stage,
//! and the output directory too if the stage made it, so it leaves nothing
//! but what it found.
//!
//! Only directories that did not exist when the stage was made are staged
//! ([`Staged::takes`]); the others are written in place, the usual way.
//!
//! The stage is `.umbrac-PID-N.stage` in the output directory. A process
//! killed before publishing leaves its stage behind; the next stage made in
//! the same directory removes those whose process is gone.

use std::collections::HashSet;
use std::ffi::OsString;
use std::io::Write;
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::Mutex;

use crate::target::Artifact;

const STAGE_PREFIX: &str = ".umbrac-";
const STAGE_SUFFIX: &str = ".stage";

/// A hidden directory in `root` whose entries become `root`'s when
/// [`Staged::publish`]ed; removed with everything in it if dropped
/// unpublished.
#[derive(Debug)]
pub struct Staged {
    root: PathBuf,
    stage: PathBuf,
    /// `root`'s entries when the stage was made: these are not staged.
    existing: HashSet<OsString>,
    /// `root` was made for the stage (and goes with it, if still empty).
    made_root: bool,
    /// The directories written into the stage ([`Staged::holds`]).
    held: Mutex<HashSet<PathBuf>>,
    /// A write failed: the stage is not published, and takes no more.
    spoiled: AtomicBool,
    published: bool,
}

impl Staged {
    /// A stage in `root`, made if missing where its parent exists (a stage
    /// creates no directory it could not remove again). `None` where it
    /// cannot be made; the caller then writes the usual way.
    pub fn begin(root: &Path) -> Option<Staged> {
        let made_root = match std::fs::symlink_metadata(root) {
            Ok(m) if m.is_dir() => false,
            Ok(_) => return None,
            Err(_) => {
                let parent = match root.parent() {
                    Some(p) if !p.as_os_str().is_empty() => p,
                    _ => Path::new("."),
                };
                if !std::fs::metadata(parent).is_ok_and(|m| m.is_dir()) {
                    return None;
                }
                match std::fs::create_dir(root) {
                    Ok(()) => true,
                    // Made by another process meanwhile: it is theirs too.
                    Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && root.is_dir() => false,
                    Err(_) => return None,
                }
            }
        };
        let mut existing = HashSet::new();
        if !made_root {
            let entries = std::fs::read_dir(root).ok()?;
            for e in entries.flatten() {
                let name = e.file_name();
                if is_stale_stage(&name, &e) {
                    let _ = std::fs::remove_dir_all(e.path());
                    continue;
                }
                existing.insert(name);
            }
        }
        static COUNTER: AtomicU32 = AtomicU32::new(0);
        let pid = std::process::id();
        let mut staged = Staged { root: root.to_path_buf(), stage: PathBuf::new(), existing, made_root, held: Mutex::default(), spoiled: AtomicBool::new(false), published: false };
        for _ in 0..1000 {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let stage = root.join(format!("{STAGE_PREFIX}{pid}-{n:06x}{STAGE_SUFFIX}"));
            match std::fs::create_dir(&stage) {
                Ok(()) => {
                    staged.stage = stage;
                    return Some(staged);
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(_) => break,
            }
        }
        None // dropping `staged` removes `root` if it was made here
    }

    /// Whether outputs for `rel` (a directory relative to the root) go to
    /// the stage: its first component is a plain name that was not in the
    /// root when the stage was made.
    pub fn takes(&self, rel: &Path) -> bool {
        let mut parts = rel.components();
        match parts.next() {
            Some(Component::Normal(first)) => !self.existing.contains(first) && parts.all(|c| matches!(c, Component::Normal(_))),
            _ => false,
        }
    }

    /// Writes `artifacts` into `rel` inside the stage (made if missing),
    /// for a `rel` the stage [`takes`](Staged::takes). A file that is
    /// already there is an error (two jobs with one output): nothing is
    /// ever overwritten in a stage. After any error the stage is spoiled:
    /// later writes fail at once and it is never published (the caller
    /// writes the usual way, which reports why). Safe to call from many
    /// threads at once.
    pub fn write(&self, rel: &Path, artifacts: &[Artifact]) -> std::io::Result<()> {
        if self.spoiled.load(Ordering::Relaxed) {
            return Err(std::io::Error::other("an earlier write into the stage failed"));
        }
        let written = self.write_files(rel, artifacts);
        match &written {
            Ok(()) => {
                if let Ok(mut held) = self.held.lock() {
                    held.insert(rel.to_path_buf());
                }
            }
            Err(_) => self.spoiled.store(true, Ordering::Relaxed),
        }
        written
    }

    /// Whether outputs for `rel` were written into the stage.
    pub fn holds(&self, rel: &Path) -> bool {
        self.held.lock().is_ok_and(|held| held.contains(rel))
    }

    fn write_files(&self, rel: &Path, artifacts: &[Artifact]) -> std::io::Result<()> {
        if !self.takes(rel) {
            return Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a new directory of the output directory"));
        }
        let dir = self.stage.join(rel);
        std::fs::create_dir_all(&dir)?;
        for a in artifacts {
            super::check_file_name(&a.file_name).map_err(|m| std::io::Error::new(std::io::ErrorKind::InvalidInput, m))?;
            let mut file = super::create_output_file(&dir.join(&a.file_name))?;
            file.write_all(&a.contents)?;
            super::give_output_mode(&file)?;
        }
        Ok(())
    }

    /// Renames every directory in the stage into the root, none over
    /// anything that is there (then those already moved go back, and the
    /// stage is handed back as it was). A spoiled stage is handed back.
    pub fn publish(mut self) -> Result<(), Staged> {
        if self.spoiled.load(Ordering::Relaxed) {
            return Err(self);
        }
        let names: Vec<OsString> = match std::fs::read_dir(&self.stage) {
            Ok(entries) => entries.flatten().map(|e| e.file_name()).collect(),
            Err(_) => return Err(self),
        };
        for (i, name) in names.iter().enumerate() {
            if rename_no_replace(&self.stage.join(name), &self.root.join(name)).is_err() {
                for done in &names[..i] {
                    let _ = std::fs::rename(self.root.join(done), self.stage.join(done));
                }
                return Err(self);
            }
        }
        self.published = true;
        let _ = std::fs::remove_dir(&self.stage);
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if self.published {
            return;
        }
        if !self.stage.as_os_str().is_empty() {
            let _ = std::fs::remove_dir_all(&self.stage);
        }
        if self.made_root {
            // Only if nothing else was written there meanwhile.
            let _ = std::fs::remove_dir(&self.root);
        }
    }
}

/// Whether `name` is a stage of an umbrac process that no longer runs.
fn is_stale_stage(name: &std::ffi::OsStr, e: &std::fs::DirEntry) -> bool {
    let Some(rest) = name.to_str().and_then(|n| n.strip_prefix(STAGE_PREFIX)).and_then(|r| r.strip_suffix(STAGE_SUFFIX)) else { return false };
    let Some(pid) = rest.split('-').next().and_then(|p| p.parse::<u32>().ok()) else { return false };
    pid != std::process::id() && !super::process_alive(pid, e)
}

/// `rename(from, to)` that fails, never replaces, where `to` exists (an
/// empty directory included, which a plain rename would replace).
fn rename_no_replace(from: &Path, to: &Path) -> std::io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::ffi::OsStrExt;
        let c = |p: &Path| std::ffi::CString::new(p.as_os_str().as_bytes()).map_err(|_| std::io::Error::from(std::io::ErrorKind::InvalidInput));
        let (f, t) = (c(from)?, c(to)?);
        // SAFETY: both are NUL-terminated paths that outlive the call.
        let r = unsafe { libc::renameat2(libc::AT_FDCWD, f.as_ptr(), libc::AT_FDCWD, t.as_ptr(), libc::RENAME_NOREPLACE) };
        if r == 0 {
            return Ok(());
        }
        let e = std::io::Error::last_os_error();
        // File systems without the flag say EINVAL; check, then rename.
        if e.raw_os_error() != Some(libc::EINVAL) {
            return Err(e);
        }
    }
    if std::fs::symlink_metadata(to).is_ok() {
        return Err(std::io::Error::from(std::io::ErrorKind::AlreadyExists));
    }
    std::fs::rename(from, to)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn art(name: &str, text: &str) -> Artifact {
        Artifact { file_name: name.into(), target: None, entry: None, contents: text.as_bytes().to_vec() }
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn published_directories_appear_whole_and_an_unpublished_stage_leaves_nothing() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("out");
        let s = Staged::begin(&out).unwrap();
        s.write(Path::new("a"), &[art("x.wgsl", "1"), art("y.wgsl", "2")]).unwrap();
        s.write(Path::new("b/sub"), &[art("z.wgsl", "3")]).unwrap();
        assert_eq!(entries(&out).len(), 1, "only the hidden stage before publishing");
        s.publish().unwrap();
        assert_eq!(std::fs::read_to_string(out.join("a/y.wgsl")).unwrap(), "2");
        assert_eq!(std::fs::read_to_string(out.join("b/sub/z.wgsl")).unwrap(), "3");
        assert_eq!(entries(&out), ["a", "b"]);

        // Into a directory made for the stage: removed with it.
        let other = root.path().join("other");
        let s = Staged::begin(&other).unwrap();
        s.write(Path::new("a"), &[art("x.wgsl", "1")]).unwrap();
        drop(s);
        assert_eq!(entries(root.path()), ["out"]);
        // Into an existing one: it stays, as it was.
        let s = Staged::begin(&out).unwrap();
        s.write(Path::new("c"), &[art("x.wgsl", "1")]).unwrap();
        drop(s);
        assert_eq!(entries(&out), ["a", "b"]);
    }

    #[test]
    fn only_directories_that_did_not_exist_are_staged() {
        let root = tempfile::tempdir().unwrap();
        std::fs::create_dir(root.path().join("old")).unwrap();
        let s = Staged::begin(root.path()).unwrap();
        assert!(s.takes(Path::new("new")) && s.takes(Path::new("new/sub")));
        assert!(!s.takes(Path::new("old")) && !s.takes(Path::new("old/sub")));
        assert!(!s.takes(Path::new("")) && !s.takes(Path::new("../x")) && !s.takes(Path::new("new/../old")) && !s.takes(Path::new("/abs")));
        s.write(Path::new("new"), &[art("x.wgsl", "1")]).unwrap();
        assert!(s.holds(Path::new("new")) && !s.holds(Path::new("new2")));
        assert!(s.write(Path::new("old"), &[art("x.wgsl", "1")]).is_err());
        assert!(s.publish().is_err(), "a failed write spoils the stage");
        for bad in [("new", "x.wgsl"), ("new2", "../x.wgsl")] {
            let s = Staged::begin(root.path()).unwrap();
            s.write(Path::new("new"), &[art("x.wgsl", "1")]).unwrap();
            assert!(s.write(Path::new(bad.0), &[art(bad.1, "2")]).is_err(), "{bad:?}");
            assert!(s.write(Path::new("new3"), &[art("x.wgsl", "3")]).is_err(), "spoiled: no more writes");
        }
    }

    #[test]
    fn no_stage_without_a_parent_or_over_a_file() {
        let root = tempfile::tempdir().unwrap();
        assert!(Staged::begin(&root.path().join("missing/out")).is_none());
        std::fs::write(root.path().join("file"), "").unwrap();
        assert!(Staged::begin(&root.path().join("file")).is_none());
        assert_eq!(entries(root.path()), ["file"]);
    }

    #[test]
    fn publishing_never_replaces_what_appeared_meanwhile_and_moves_back_what_it_did() {
        let root = tempfile::tempdir().unwrap();
        let s = Staged::begin(root.path()).unwrap();
        for v in ["a", "b", "c", "d"] {
            s.write(Path::new(v), &[art("x.wgsl", v)]).unwrap();
        }
        // Another process made one of them meanwhile, empty.
        std::fs::create_dir(root.path().join("c")).unwrap();
        let s = s.publish().unwrap_err();
        let mut left = entries(root.path());
        left.retain(|n| !n.ends_with(STAGE_SUFFIX));
        assert_eq!(left, ["c"], "the others moved back into the stage");
        assert_eq!(entries(&root.path().join("c")), Vec::<String>::new());
        drop(s);
        assert_eq!(entries(root.path()), ["c"]);
    }

    #[test]
    fn stages_of_dead_processes_are_removed() {
        let root = tempfile::tempdir().unwrap();
        // pid 0 is never a process that made a stage.
        let stale = root.path().join(format!("{STAGE_PREFIX}0-000000{STAGE_SUFFIX}"));
        std::fs::create_dir_all(stale.join("v")).unwrap();
        std::fs::write(stale.join("v/x.wgsl"), "old").unwrap();
        let s = Staged::begin(root.path()).unwrap();
        assert!(!stale.exists());
        assert!(s.takes(Path::new("v")), "a stale stage is not an existing entry");
        drop(s);
        assert_eq!(entries(root.path()), Vec::<String>::new());
    }
}
