//! Writing outputs to disk atomically.
//!
//! [`write_artifacts`] writes one compilation's files as a unit:
//! 1. the output directory is created if missing (with its parents, like
//!    `mkdir -p`; build scripts and `-o build/shaders` expect that);
//! 2. every destination is checked: an existing path that is not a regular
//!    file (a directory, say) is an error before anything is written;
//! 3. with the directory locked against other writers (`flock`), each
//!    destination's present contents are read; each file to be replaced is
//!    written to a temporary file in the destination directory; with every
//!    temporary whole, a commit record says which becomes which
//!    ([`journal`]), then the temporaries are renamed over the
//!    destinations and the record is removed. Should a rename fail
//!    part-way, the files already replaced are restored from their
//!    previous contents (or removed, if they are new), so a failed write
//!    leaves the directory as it was. A file that already holds its bytes
//!    can be left as it is ([`Unchanged`]).
//!
//! Each rename is atomic, so a reader (or a crash) never sees a half-written
//! file, and two compiles into one directory leave the whole set of one of
//! them, never a mix. A process killed between two renames leaves its
//! commit record, and whoever next takes the lock (the next write, or
//! [`settle`]) finishes the renames first: no lock holder sees a mix. Temporaries are removed on every error path. They are named
//! `.umbrac-PID-XXXXXX.tmp`: hidden, and never the name of an output. A
//! process killed mid-write (SIGKILL, power loss) can leave one behind; the
//! next write into the same directory removes those whose process is gone.
//!
//! Directories that do not exist yet can instead be built under a hidden
//! stage and renamed into place ([`staged`]).
//!
//! Outputs are not fsynced, as no compiler or build tool (gcc, clang,
//! rustc, cargo, ninja) fsyncs its outputs: a sync costs about half a
//! millisecond per file here, which was three quarters of a cold compile
//! of 256 variants (docs/performance.md). Against a killed process the
//! renames are enough; against power loss a file replaced by rename is as
//! durable as the file system makes it (ext4 and btrfs write a replaced
//! file's data before the rename commits), and a build redoes what it
//! cannot trust after a crash.

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

use crate::target::Artifact;

pub mod journal;
pub mod staged;
pub mod stamps;

/// What a destination held before a write.
enum Previous {
    /// Nothing: the file is new.
    Absent,
    /// These bytes.
    Held(Vec<u8>),
    /// Exactly the artifact's bytes, by a trusted stamp (not read; never
    /// replaced, so never restored).
    Same,
}

/// Why outputs could not be written. Nothing was changed on disk.
#[derive(Debug)]
pub struct OutputError {
    pub path: PathBuf,
    pub message: String,
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write `{}`: {}", self.path.display(), self.message)
    }
}

impl std::error::Error for OutputError {}

fn err(path: &Path, message: impl Into<String>) -> OutputError {
    OutputError { path: path.to_path_buf(), message: message.into() }
}

/// What [`write_outputs`] does with an output whose file already holds
/// exactly its bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unchanged {
    /// Replace it all the same.
    Rewrite,
    /// Leave its bytes and give it a new modification time, as if
    /// rewritten: make and ninja compare times, and would otherwise run the
    /// compile again on every build.
    Touch,
    /// [`Unchanged::Touch`] where the file is not newer than the given
    /// time (the newest of the files the compile read), and left alone
    /// where it is: make and ninja already see it as up to date, and a
    /// warm run then changes nothing on disk.
    TouchUnlessNewerThan(std::time::SystemTime),
    /// Leave it alone, modification time too: cargo rebuilds a crate whose
    /// `include_str!`ed files have a new time.
    Leave,
}

/// What a caller already knows of the artifacts it writes: the hash of
/// each one's contents (in order), and the [`stamps::Stamps`] of the
/// files already there, so that a file known to hold those bytes is not
/// read back.
pub struct Known<'a> {
    pub hashes: &'a [crate::cache::Key],
    pub stamps: &'a stamps::Stamps,
}

/// Writes every artifact into `dir`, all or nothing (see the module docs).
pub fn write_artifacts(dir: &Path, artifacts: &[Artifact]) -> Result<(), OutputError> {
    write_outputs(dir, artifacts, Unchanged::Rewrite)
}

/// Writes every artifact into `dir`, all or nothing (see the module docs),
/// doing with those already on disk as they are what `unchanged` says.
/// Which files are unchanged is decided under the directory's lock: two
/// compiles of different versions decide against each other's finished
/// output, never against a set another one is halfway through replacing.
pub fn write_outputs(dir: &Path, artifacts: &[Artifact], unchanged: Unchanged) -> Result<(), OutputError> {
    write_outputs_known(dir, artifacts, unchanged, None)
}

/// [`write_outputs`], with what the caller knows of the artifacts (see
/// [`Known`]): an existing file a trusted stamp says holds an artifact's
/// bytes is not read, and a file read and found to hold them is stamped.
pub fn write_outputs_known(dir: &Path, artifacts: &[Artifact], unchanged: Unchanged, known: Option<&Known<'_>>) -> Result<(), OutputError> {
    if let Some(k) = known {
        assert_eq!(k.hashes.len(), artifacts.len(), "one hash per artifact");
    }
    // Names come from entry point names; refuse anything that is not a
    // plain file name so nothing is ever written outside `dir`.
    for a in artifacts {
        check_file_name(&a.file_name).map_err(|m| err(&dir.join(&a.file_name), m))?;
    }
    let mut seen = std::collections::HashSet::new();
    for a in artifacts {
        if !seen.insert(&a.file_name) {
            return Err(err(&dir.join(&a.file_name), "two outputs have this name"));
        }
    }

    // A directory made here holds no temporaries of killed processes.
    let made_here = match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => false,
        Ok(_) => return Err(err(dir, "the output path exists and is not a directory")),
        Err(_) => {
            std::fs::create_dir_all(dir).map_err(|e| err(dir, format!("cannot create the output directory: {e}")))?;
            true
        }
    };

    // From here to the last rename, no other writer (another process
    // compiling into the same directory) can rename in between: one
    // compile's outputs replace another's as a set.
    let _lock = DirLock::acquire(dir).map_err(|e| err(dir, format!("cannot lock the output directory: {e}")))?;
    // A writer killed after its commit point: its set is finished first,
    // so the files read below are one whole set.
    if !made_here {
        complete_killed(dir)?;
    }

    // What each destination holds now, for rollback and to see which are
    // unchanged.
    let mut previous: Vec<Previous> = Vec::with_capacity(artifacts.len());
    let mut modified: Vec<Option<std::time::SystemTime>> = Vec::with_capacity(artifacts.len());
    for (i, a) in artifacts.iter().enumerate() {
        let dest = dir.join(&a.file_name);
        let taken = stamps::now_ns();
        match std::fs::symlink_metadata(&dest) {
            Ok(m) if m.is_file() => {
                modified.push(m.modified().ok());
                let state = stamps::FileState::of(&m);
                let hash = known.map(|k| k.hashes[i]);
                if let (Some(k), Some(state), Some(hash)) = (known, state, hash) {
                    if k.stamps.hash_of(&dest, &state) == Some(hash) {
                        previous.push(Previous::Same);
                        continue;
                    }
                }
                let bytes = std::fs::read(&dest).map_err(|e| err(&dest, e.to_string()))?;
                if let (Some(k), Some(state), Some(hash)) = (known, state, hash) {
                    if bytes == a.contents {
                        k.stamps.record(&dest, state, hash, taken);
                    }
                }
                previous.push(Previous::Held(bytes));
            }
            Ok(_) => return Err(err(&dest, "exists and is not a regular file")),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                modified.push(None);
                previous.push(Previous::Absent);
            }
            Err(e) => return Err(err(&dest, e.to_string())),
        }
    }
    let now = std::time::SystemTime::now();
    let todo: Vec<usize> = (0..artifacts.len())
        .filter(|&i| {
            let same = match &previous[i] {
                Previous::Same => true,
                Previous::Held(bytes) => bytes[..] == artifacts[i].contents[..],
                Previous::Absent => false,
            };
            let touch = match (same, unchanged) {
                (false, _) | (true, Unchanged::Rewrite) => return true,
                (true, Unchanged::Leave) => return false,
                (true, Unchanged::Touch) => true,
                (true, Unchanged::TouchUnlessNewerThan(newest)) => modified[i].is_none_or(|m| m <= newest),
            };
            if !touch {
                return false;
            }
            // A file that cannot be touched is rewritten instead. Its
            // status-change time moves, so an old stamp no longer holds.
            let dest = dir.join(&artifacts[i].file_name);
            if let Some(k) = known {
                k.stamps.forget(&dest);
            }
            std::fs::File::options().write(true).open(&dest).and_then(|f| f.set_modified(now)).is_err()
        })
        .collect();
    if !todo.is_empty() && !made_here {
        remove_stale_temps(dir);
    }

    // Write every temporary before touching any destination. A `TempFile`
    // deletes itself when dropped, so every early return below cleans up.
    let mut temps = Vec::with_capacity(todo.len());
    for &i in &todo {
        let dest = dir.join(&artifacts[i].file_name);
        let temp = write_temp(dir, &artifacts[i].contents).map_err(|e| err(&dest, e.to_string()))?;
        temps.push(temp);
    }

    // The commit point (journal.rs): from the record on, the new set is
    // what the directory holds, even if this process dies between renames.
    // One rename is atomic by itself and needs no record.
    let recorded = todo.len() > 1;
    if recorded {
        let dests: Vec<PathBuf> = todo.iter().map(|&i| dir.join(&artifacts[i].file_name)).collect();
        let pairs: Vec<(&Path, &Path)> = temps.iter().map(|t| t.path.as_path()).zip(dests.iter().map(PathBuf::as_path)).collect();
        journal::commit(dir, &pairs).map_err(|e| err(&dir.join(journal::RECORD), e.to_string()))?;
    }
    let mut done: Vec<usize> = Vec::new();
    for (&i, temp) in todo.iter().zip(temps) {
        let dest = dir.join(&artifacts[i].file_name);
        #[cfg(test)]
        let result = match fault::rename_fails(i) {
            Some(error) => Err(error), // `temp` is dropped, which removes it
            None => temp.persist(&dest),
        };
        #[cfg(not(test))]
        let result = temp.persist(&dest);
        if let Err(e) = result {
            // The new set is abandoned: no later run may finish it.
            journal::finish(dir);
            rollback(dir, artifacts, &previous, &done);
            return Err(err(&dest, e.to_string()));
        }
        if let Some(k) = known {
            k.stamps.forget(&dest);
        }
        done.push(i);
    }
    if recorded {
        journal::finish(dir);
    }
    Ok(())
}

/// Finishes, under the directory's lock, the set of a writer killed
/// between its commit point and its last rename (journal.rs). What a
/// reader that needs one whole set does first: with the lock held and no
/// record left, the files are one set. Returns how many renames it
/// finished (`None`: no writer had been killed there).
pub fn settle(dir: &Path) -> Result<Option<usize>, OutputError> {
    let _lock = DirLock::acquire(dir).map_err(|e| err(dir, format!("cannot lock the output directory: {e}")))?;
    complete_killed(dir)
}

fn complete_killed(dir: &Path) -> Result<Option<usize>, OutputError> {
    journal::complete(dir).map_err(|e| err(&dir.join(journal::RECORD), format!("cannot finish the outputs of a killed run: {e}")))
}

/// An exclusive advisory lock (`flock`) on an output directory, held by
/// [`write_artifacts`] around its renames and released when dropped, or
/// by the OS when the process dies (a killed compile never leaves the
/// directory locked). It locks the directory itself, so no lock file is
/// left among the outputs. Where a directory cannot be opened as a file
/// (not on Unix), there is no lock.
struct DirLock {
    _dir: Option<std::fs::File>,
}

impl DirLock {
    fn acquire(dir: &Path) -> std::io::Result<DirLock> {
        if !cfg!(unix) {
            return Ok(DirLock { _dir: None });
        }
        let d = std::fs::File::open(dir)?;
        d.lock()?;
        Ok(DirLock { _dir: Some(d) })
    }
}

const TEMP_PREFIX: &str = ".umbrac-";
const TEMP_SUFFIX: &str = ".tmp";

/// A temporary file in an output directory, removed when dropped unless
/// [`TempFile::persist`] renamed it onto its destination. std only: a
/// build-dependency should not need a crate (and its platform layer) for
/// this.
struct TempFile {
    path: PathBuf,
    /// Open until the rename.
    file: Option<std::fs::File>,
    renamed: bool,
}

impl TempFile {
    /// Creates a new, empty `.umbrac-PID-XXXXXX.tmp` in `dir`. Names come
    /// from a counter shared by every thread of the process, so threads
    /// writing into one directory never pick the same one; a name that
    /// exists anyway (a leftover of an earlier process with this pid, say)
    /// is skipped, never opened.
    fn new_in(dir: &Path) -> std::io::Result<TempFile> {
        static COUNTER: AtomicU32 = AtomicU32::new(0);
        // One `getpid` per process, not per file.
        static PID: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
        let pid = *PID.get_or_init(std::process::id);
        Self::create_first_free(dir, || {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            format!("{TEMP_PREFIX}{pid}-{n:06x}{TEMP_SUFFIX}")
        })
    }

    /// Creates the first name `next_name` gives that does not exist yet.
    fn create_first_free(dir: &Path, mut next_name: impl FnMut() -> String) -> std::io::Result<TempFile> {
        const ATTEMPTS: u32 = 1000;
        for _ in 0..ATTEMPTS {
            let path = dir.join(next_name());
            match create_output_file(&path) {
                Ok(file) => return Ok(TempFile { path, file: Some(file), renamed: false }),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(e),
            }
        }
        Err(std::io::Error::new(std::io::ErrorKind::AlreadyExists, format!("no free temporary file name in {} after {ATTEMPTS} tries", dir.display())))
    }

    #[cfg(test)]
    fn path(&self) -> &Path {
        &self.path
    }

    fn file(&self) -> &std::fs::File {
        self.file.as_ref().expect("a temporary file is open until it is persisted")
    }

    /// Renames the temporary onto `dest` (atomically replacing it). On
    /// failure the temporary is removed.
    fn persist(mut self, dest: &Path) -> std::io::Result<()> {
        // Closed before the rename: some platforms cannot rename open files.
        drop(self.file.take());
        std::fs::rename(&self.path, dest)?;
        self.renamed = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        drop(self.file.take());
        if !self.renamed {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// Outputs are ordinary readable files (`rw-r--r--`), whatever the umask.
#[cfg(unix)]
const OUTPUT_MODE: u32 = 0o644;

/// Whether the process's umask clears none of [`OUTPUT_MODE`]'s bits, so
/// that files created with that mode have it and need no `fchmod` (one
/// system call per output). Read once from `/proc/self/status` (setting
/// the umask to read it would race other threads' file creation); where
/// it cannot be read, every file is given its mode explicitly.
#[cfg(unix)]
fn umask_keeps_output_mode() -> bool {
    static KEEPS: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *KEEPS.get_or_init(|| {
        let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
        let umask = status.lines().find_map(|l| l.strip_prefix("Umask:")).and_then(|u| u32::from_str_radix(u.trim(), 8).ok());
        umask.is_some_and(|m| m & OUTPUT_MODE == 0)
    })
}

fn write_temp(dir: &Path, contents: &[u8]) -> std::io::Result<TempFile> {
    let temp = TempFile::new_in(dir)?;
    let mut file = temp.file();
    file.write_all(contents)?;
    give_output_mode(file)?;
    Ok(temp)
}

/// Names come from entry point names; anything that is not a plain file
/// name is refused, so nothing is ever written outside its directory.
fn check_file_name(n: &str) -> Result<(), &'static str> {
    if n.is_empty() || n == "." || n == ".." || n.contains(['/', '\\', '\0']) {
        return Err("not a plain file name");
    }
    Ok(())
}

/// Creates a new file for writing, with [`OUTPUT_MODE`] as far as the
/// umask allows. `create_new` fails rather than open an existing file (or
/// follow a symlink planted under the name).
fn create_output_file(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    std::os::unix::fs::OpenOptionsExt::mode(&mut options, OUTPUT_MODE);
    options.open(path)
}

/// Gives a file made by [`create_output_file`] the whole [`OUTPUT_MODE`]
/// where the umask took some of it.
fn give_output_mode(file: &std::fs::File) -> std::io::Result<()> {
    #[cfg(unix)]
    if !umask_keeps_output_mode() {
        use std::os::unix::fs::PermissionsExt;
        file.set_permissions(std::fs::Permissions::from_mode(OUTPUT_MODE))?;
    }
    let _ = file;
    Ok(())
}

/// Whether a file name looks like one of umbrac's outputs (so that stale
/// files are recognised and unrelated files in the directory are left alone).
pub fn is_output_name(name: &str) -> bool {
    [".330.vert", ".330.frag", ".300es.vert", ".300es.frag", ".wgsl", ".spv", ".reflect.json"].iter().any(|s| name.ends_with(s))
}

/// The files in `dir` named like outputs (see [`is_output_name`]) that none
/// of `artifacts` produces, sorted; empty if `dir` cannot be read.
pub fn stale_outputs(dir: &Path, artifacts: &[Artifact]) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Vec::new() };
    let mut stale: Vec<PathBuf> = entries
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| is_output_name(n) && !artifacts.iter().any(|a| a.file_name == *n))
        .map(|n| dir.join(n))
        .collect();
    stale.sort();
    stale
}

/// Removes temporaries left in `dir` by umbrac processes that no longer
/// run (killed mid-write). Best effort: errors are ignored.
fn remove_stale_temps(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(name) = name.to_str() else { continue };
        let Some(rest) = name.strip_prefix(TEMP_PREFIX).and_then(|r| r.strip_suffix(TEMP_SUFFIX)) else { continue };
        let Some(pid) = rest.split('-').next().and_then(|p| p.parse::<u32>().ok()) else { continue };
        if pid != std::process::id() && !process_alive(pid, &e) {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Whether the process that made a temporary may still be writing it.
fn process_alive(pid: u32, temp: &std::fs::DirEntry) -> bool {
    let proc_root = Path::new("/proc/self");
    if proc_root.exists() {
        return Path::new("/proc").join(pid.to_string()).exists();
    }
    // No /proc: only temporaries older than an hour count as abandoned.
    let age = temp.metadata().ok().and_then(|m| m.modified().ok()).and_then(|t| t.elapsed().ok());
    age.is_none_or(|a| a < std::time::Duration::from_secs(3600))
}

/// Puts back what the destinations in `done` held before.
fn rollback(dir: &Path, artifacts: &[Artifact], previous: &[Previous], done: &[usize]) {
    for &i in done {
        let dest = dir.join(&artifacts[i].file_name);
        let old = match &previous[i] {
            Previous::Held(old) => old,
            // It held the artifact's own bytes.
            Previous::Same => &artifacts[i].contents,
            Previous::Absent => {
                let _ = std::fs::remove_file(&dest);
                continue;
            }
        };
        if let Ok(t) = write_temp(dir, old) {
            let _ = t.persist(&dest);
        }
    }
}

/// Test-only fault injection: make the rename of the N-th artifact fail, to
/// exercise the rollback that a real failure (a full disk, a destination
/// made read-only under our feet) would take.
#[cfg(test)]
mod fault {
    use std::cell::Cell;

    thread_local! {
        pub static FAIL_RENAME: Cell<Option<usize>> = const { Cell::new(None) };
    }

    pub fn rename_fails(i: usize) -> Option<std::io::Error> {
        (FAIL_RENAME.with(Cell::get) == Some(i)).then(|| std::io::Error::other("injected rename failure"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn art(name: &str, text: &str) -> Artifact {
        Artifact { file_name: name.into(), target: None, entry: None, contents: text.as_bytes().to_vec() }
    }

    fn listing(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn writes_and_replaces() {
        let d = tempfile::tempdir().unwrap();
        write_artifacts(d.path(), &[art("a.wgsl", "one"), art("b.json", "two")]).unwrap();
        write_artifacts(d.path(), &[art("a.wgsl", "three")]).unwrap();
        assert_eq!(std::fs::read_to_string(d.path().join("a.wgsl")).unwrap(), "three");
        assert_eq!(listing(d.path()), ["a.wgsl", "b.json"]);
    }

    #[test]
    fn unchanged_files_are_touched_or_left_as_asked() {
        let d = tempfile::tempdir().unwrap();
        let old = std::time::SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1_000_000);
        let mtime = |n: &str| std::fs::metadata(d.path().join(n)).unwrap().modified().unwrap();
        let age = |n: &str| std::fs::File::options().write(true).open(d.path().join(n)).unwrap().set_modified(old).unwrap();
        write_artifacts(d.path(), &[art("a.wgsl", "same"), art("b.wgsl", "old")]).unwrap();
        age("a.wgsl");
        age("b.wgsl");
        write_outputs(d.path(), &[art("a.wgsl", "same"), art("b.wgsl", "new")], Unchanged::Leave).unwrap();
        assert_eq!(mtime("a.wgsl"), old, "left alone");
        assert_eq!(std::fs::read_to_string(d.path().join("b.wgsl")).unwrap(), "new");
        write_outputs(d.path(), &[art("a.wgsl", "same")], Unchanged::Touch).unwrap();
        assert!(mtime("a.wgsl") > old, "touched");
        assert_eq!(std::fs::read_to_string(d.path().join("a.wgsl")).unwrap(), "same");
        assert_eq!(listing(d.path()), ["a.wgsl", "b.wgsl"]);
    }

    #[test]
    fn a_directory_in_the_way_changes_nothing() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(d.path().join("a.wgsl"), "old").unwrap();
        std::fs::create_dir(d.path().join("b.spv")).unwrap();
        let e = write_artifacts(d.path(), &[art("a.wgsl", "new"), art("b.spv", "x"), art("c.json", "y")]).unwrap_err();
        assert!(e.to_string().contains("b.spv"), "{e}");
        assert_eq!(std::fs::read_to_string(d.path().join("a.wgsl")).unwrap(), "old");
        assert_eq!(listing(d.path()), ["a.wgsl", "b.spv"]);
    }

    #[test]
    fn refuses_paths() {
        let d = tempfile::tempdir().unwrap();
        assert!(write_artifacts(d.path(), &[art("../x", "")]).is_err());
        assert!(write_artifacts(d.path(), &[art("a", ""), art("a", "")]).is_err());
        assert!(listing(d.path()).is_empty());
    }

    #[test]
    fn creates_missing_directories_but_not_over_files() {
        let d = tempfile::tempdir().unwrap();
        write_artifacts(&d.path().join("x/y"), &[art("a", "1")]).unwrap();
        assert_eq!(std::fs::read_to_string(d.path().join("x/y/a")).unwrap(), "1");
        std::fs::write(d.path().join("f"), "").unwrap();
        let e = write_artifacts(&d.path().join("f"), &[art("a", "1")]).unwrap_err();
        assert!(e.message.contains("not a directory"), "{e}");
    }

    #[test]
    fn a_rename_failing_mid_write_restores_every_output() {
        let d = tempfile::tempdir().unwrap();
        let old = [art("a.vert", "old a"), art("b.frag", "old b"), art("c.wgsl", "old c")];
        write_artifacts(d.path(), &old).unwrap();
        let new = [art("a.vert", "new a"), art("b.frag", "new b"), art("c.wgsl", "new c"), art("d.json", "new d")];
        for fail_at in 0..new.len() {
            fault::FAIL_RENAME.with(|f| f.set(Some(fail_at)));
            let e = write_artifacts(d.path(), &new).unwrap_err();
            fault::FAIL_RENAME.with(|f| f.set(None));
            assert!(e.to_string().contains(&new[fail_at].file_name) && e.message.contains("injected"), "{e}");
            // Byte-identical old outputs, no new ones, no temporaries.
            assert_eq!(listing(d.path()), ["a.vert", "b.frag", "c.wgsl"], "failing rename #{fail_at}");
            for a in &old {
                assert_eq!(std::fs::read(d.path().join(&a.file_name)).unwrap(), a.contents, "failing rename #{fail_at}");
            }
        }
        write_artifacts(d.path(), &new).unwrap();
        assert_eq!(std::fs::read_to_string(d.path().join("b.frag")).unwrap(), "new b");
    }

    #[test]
    fn temporaries_are_hidden_and_stale_ones_are_removed() {
        let d = tempfile::tempdir().unwrap();
        // A process id that cannot be running (above Linux's pid_max).
        let stale = d.path().join(".umbrac-4294967294-abcdef.tmp");
        std::fs::write(&stale, "half").unwrap();
        // One of ours that is in use, and a user's file that looks similar.
        let live = d.path().join(format!(".umbrac-{}-zzzzzz.tmp", std::process::id()));
        std::fs::write(&live, "busy").unwrap();
        std::fs::write(d.path().join("umbrac-1-x.tmp"), "user").unwrap();
        write_artifacts(d.path(), &[art("a.wgsl", "1")]).unwrap();
        let l = listing(d.path());
        if Path::new("/proc/self").exists() {
            assert!(!l.contains(&".umbrac-4294967294-abcdef.tmp".to_string()), "{l:?}");
        }
        assert!(l.contains(&live.file_name().unwrap().to_string_lossy().into_owned()), "{l:?}");
        assert!(l.contains(&"umbrac-1-x.tmp".to_string()) && l.contains(&"a.wgsl".to_string()), "{l:?}");
        let t = write_temp(d.path(), b"x").unwrap();
        let name = t.path().file_name().unwrap().to_string_lossy().into_owned();
        assert!(name.starts_with(&format!(".umbrac-{}-", std::process::id())) && name.ends_with(".tmp"), "{name}");
    }

    #[test]
    fn a_temporary_is_removed_unless_persisted() {
        let d = tempfile::tempdir().unwrap();
        let t = write_temp(d.path(), b"half").unwrap();
        assert_eq!(std::fs::read(t.path()).unwrap(), b"half");
        drop(t);
        assert!(listing(d.path()).is_empty());
        let t = write_temp(d.path(), b"whole").unwrap();
        t.persist(&d.path().join("out.wgsl")).unwrap();
        assert_eq!(listing(d.path()), ["out.wgsl"]);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(d.path().join("out.wgsl")).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o644);
        }
        // A failed rename (onto a directory) removes the temporary too.
        std::fs::create_dir(d.path().join("sub")).unwrap();
        std::fs::write(d.path().join("sub/x"), "").unwrap();
        let t = write_temp(d.path(), b"x").unwrap();
        assert!(t.persist(&d.path().join("sub")).is_err());
        assert_eq!(listing(d.path()), ["out.wgsl", "sub"]);
    }

    #[test]
    fn taken_temporary_names_are_skipped_not_opened() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(d.path().join(".umbrac-1-000000.tmp"), "someone else's").unwrap();
        let mut names = [".umbrac-1-000000.tmp", ".umbrac-1-000001.tmp"].into_iter().map(String::from);
        let t = TempFile::create_first_free(d.path(), || names.next().unwrap()).unwrap();
        assert_eq!(t.path().file_name().unwrap(), ".umbrac-1-000001.tmp");
        assert_eq!(std::fs::read_to_string(d.path().join(".umbrac-1-000000.tmp")).unwrap(), "someone else's");
        drop(t);
        assert_eq!(listing(d.path()), [".umbrac-1-000000.tmp"]);
    }

    #[test]
    fn threads_writing_into_one_directory_never_share_a_temporary() {
        let d = tempfile::tempdir().unwrap();
        std::thread::scope(|s| {
            for t in 0..8 {
                let dir = d.path();
                s.spawn(move || {
                    for i in 0..20 {
                        let name = format!("t{t}-{i}.wgsl");
                        write_artifacts(dir, &[art(&name, &name)]).unwrap();
                    }
                });
            }
        });
        let l = listing(d.path());
        assert_eq!(l.len(), 160, "{l:?}");
        for n in &l {
            assert_eq!(&std::fs::read_to_string(d.path().join(n)).unwrap(), n);
        }
    }
}
