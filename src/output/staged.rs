//! An output directory that does not exist yet, built whole under a hidden
//! name beside it while the compiles that fill it are still running, then
//! renamed into place in one step.
//!
//! A cold run with variants writes hundreds of directories of new files.
//! Through [`super::write_outputs`] each file costs a lookup, a temporary
//! and a rename, and all of it waits until every variant has compiled
//! (a run is all or nothing). Staged, each variant's files are written
//! under their own names as soon as it compiles, on the thread that
//! compiled it, and the one rename at the end publishes them all: a reader
//! (or a crash) sees either no output directory or the complete one, and a
//! failed run leaves nothing but what it found.
//!
//! The stage is `.umbrac-PID-N.stage` in the output directory's parent. A
//! process killed before publishing leaves its stage behind; the next
//! stage made in the same parent removes those whose process is gone.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

use crate::target::Artifact;

const STAGE_PREFIX: &str = ".umbrac-";
const STAGE_SUFFIX: &str = ".stage";

/// A hidden directory that becomes `dest` when [`Staged::publish`]ed, and is
/// removed with everything in it if dropped unpublished.
#[derive(Debug)]
pub struct Staged {
    stage: PathBuf,
    dest: PathBuf,
    published: bool,
}

impl Staged {
    /// A stage for `dest`, if `dest` does not exist and its parent
    /// directory does (a stage never creates directories outside itself: a
    /// failed run must not leave new empty ones). `None` where it cannot be
    /// made; the caller then writes the usual way.
    pub fn begin(dest: &Path) -> Option<Staged> {
        if std::fs::symlink_metadata(dest).is_ok() {
            return None;
        }
        let name = dest.file_name()?;
        if name == "." || name == ".." {
            return None;
        }
        let parent = match dest.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if !std::fs::metadata(parent).is_ok_and(|m| m.is_dir()) {
            return None;
        }
        remove_stale_stages(parent);
        static COUNTER: AtomicU32 = AtomicU32::new(0);
        let pid = std::process::id();
        for _ in 0..1000 {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let stage = parent.join(format!("{STAGE_PREFIX}{pid}-{n:06x}{STAGE_SUFFIX}"));
            match std::fs::create_dir(&stage) {
                Ok(()) => return Some(Staged { stage, dest: dest.to_path_buf(), published: false }),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(_) => return None,
            }
        }
        None
    }

    /// The directory it will become.
    pub fn dest(&self) -> &Path {
        &self.dest
    }

    /// Writes `artifacts` into `rel` (a relative directory, made if
    /// missing) inside the stage. A file that is already there is an error
    /// (two jobs with one output): nothing is ever overwritten in a stage.
    /// Safe to call from many threads at once.
    pub fn write(&self, rel: &Path, artifacts: &[Artifact]) -> std::io::Result<()> {
        if rel.is_absolute() || rel.components().any(|c| !matches!(c, std::path::Component::Normal(_))) {
            return Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a plain relative directory"));
        }
        let dir = self.stage.join(rel);
        if !rel.as_os_str().is_empty() {
            std::fs::create_dir_all(&dir)?;
        }
        for a in artifacts {
            super::check_file_name(&a.file_name).map_err(|m| std::io::Error::new(std::io::ErrorKind::InvalidInput, m))?;
            let mut file = super::create_output_file(&dir.join(&a.file_name))?;
            file.write_all(&a.contents)?;
            super::give_output_mode(&file)?;
        }
        Ok(())
    }

    /// Renames the stage to its destination, unless something appeared
    /// there meanwhile (then the stage is handed back, untouched).
    pub fn publish(mut self) -> Result<(), Staged> {
        match rename_no_replace(&self.stage, &self.dest) {
            Ok(()) => {
                self.published = true;
                Ok(())
            }
            Err(_) => Err(self),
        }
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.published {
            let _ = std::fs::remove_dir_all(&self.stage);
        }
    }
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

/// Removes stages left in `parent` by umbrac processes that no longer run.
fn remove_stale_stages(parent: &Path) {
    let Ok(entries) = std::fs::read_dir(parent) else { return };
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(name) = name.to_str() else { continue };
        let Some(rest) = name.strip_prefix(STAGE_PREFIX).and_then(|r| r.strip_suffix(STAGE_SUFFIX)) else { continue };
        let Some(pid) = rest.split('-').next().and_then(|p| p.parse::<u32>().ok()) else { continue };
        if pid != std::process::id() && !super::process_alive(pid, &e) {
            let _ = std::fs::remove_dir_all(e.path());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn art(name: &str, text: &str) -> Artifact {
        Artifact { file_name: name.into(), target: None, entry: None, contents: text.as_bytes().to_vec() }
    }

    fn hidden_entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn a_published_stage_is_the_whole_directory_and_an_unpublished_one_leaves_nothing() {
        let root = tempfile::tempdir().unwrap();
        let dest = root.path().join("out");
        let s = Staged::begin(&dest).unwrap();
        s.write(Path::new("a"), &[art("x.wgsl", "1"), art("y.wgsl", "2")]).unwrap();
        s.write(Path::new(""), &[art("variants.json", "{}")]).unwrap();
        assert!(!dest.exists(), "nothing is visible before publishing");
        s.publish().unwrap();
        assert_eq!(std::fs::read_to_string(dest.join("a/y.wgsl")).unwrap(), "2");
        assert_eq!(std::fs::read_to_string(dest.join("variants.json")).unwrap(), "{}");
        assert_eq!(hidden_entries(root.path()), ["out"]);

        let other = root.path().join("other");
        let s = Staged::begin(&other).unwrap();
        s.write(Path::new("a"), &[art("x.wgsl", "1")]).unwrap();
        drop(s);
        assert_eq!(hidden_entries(root.path()), ["out"], "a dropped stage is removed");
    }

    #[test]
    fn no_stage_over_an_existing_path_or_without_a_parent() {
        let root = tempfile::tempdir().unwrap();
        assert!(Staged::begin(root.path()).is_none());
        assert!(Staged::begin(&root.path().join("missing/out")).is_none());
        assert_eq!(hidden_entries(root.path()), Vec::<String>::new());
    }

    #[test]
    fn publishing_never_replaces_what_appeared_meanwhile_even_an_empty_directory() {
        let root = tempfile::tempdir().unwrap();
        let dest = root.path().join("out");
        let s = Staged::begin(&dest).unwrap();
        s.write(Path::new(""), &[art("x.wgsl", "1")]).unwrap();
        std::fs::create_dir(&dest).unwrap();
        let s = s.publish().unwrap_err();
        assert_eq!(hidden_entries(&dest), Vec::<String>::new());
        drop(s);
        assert_eq!(hidden_entries(root.path()), ["out"]);
    }

    #[test]
    fn one_output_written_twice_is_an_error_and_bad_names_are_refused() {
        let root = tempfile::tempdir().unwrap();
        let s = Staged::begin(&root.path().join("out")).unwrap();
        s.write(Path::new("v"), &[art("x.wgsl", "1")]).unwrap();
        assert!(s.write(Path::new("v"), &[art("x.wgsl", "2")]).is_err());
        assert!(s.write(Path::new("../v"), &[art("x.wgsl", "1")]).is_err());
        assert!(s.write(Path::new("w"), &[art("../x.wgsl", "1")]).is_err());
    }

    #[test]
    fn stages_of_dead_processes_are_removed() {
        let root = tempfile::tempdir().unwrap();
        // pid 0 is never a process that made a stage.
        let stale = root.path().join(format!("{STAGE_PREFIX}0-000000{STAGE_SUFFIX}"));
        std::fs::create_dir_all(stale.join("v")).unwrap();
        std::fs::write(stale.join("v/x.wgsl"), "old").unwrap();
        let s = Staged::begin(&root.path().join("out")).unwrap();
        assert!(!stale.exists());
        drop(s);
    }
}
