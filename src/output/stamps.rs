//! What the outputs already on disk hold, without reading them again.
//!
//! A warm run's outputs are almost always the files the previous run left,
//! and reading every one back to see that (2,049 files for 256 variants)
//! was most of such a run. A [`Stamps`] file remembers, for each output it
//! has seen, the hash of its contents together with what the file
//! system says of the file: size, inode, modification and status-change
//! times. Any write, rename or `touch` changes the status-change time
//! (ctime), which no program can set back, so a file whose size, inode and
//! both times are still the remembered ones still holds the remembered
//! bytes.
//!
//! One case is not covered by that: a change made in the same tick of the
//! file system's clock as the state that was remembered leaves ctime
//! as it was. So a stamp is only trusted when it was taken at least
//! [`MARGIN`] after the file's ctime (`COARSE_MARGIN` where timestamps
//! have whole seconds only); a file read sooner after it changed is read
//! again next time (git's index has the same rule for the same reason).
//! Stamps are recorded only for files read and found equal to the output
//! they should hold, never for files just written (those are that new).
//!
//! Stamps are an optimisation: a missing, damaged or stale stamp file only
//! means the outputs are read. They live in the cache directory
//! (`stamps/`, one file per output directory of a command), never among
//! the outputs, and are written atomically.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, SystemTime};

use rustc_hash::FxHashMap;

use crate::cache::Key;
use crate::sealed::{self, Reader};

/// How long after a file's last change a stamp of it must have been taken
/// to be trusted: over one tick of the coarsest clock Linux file systems
/// keep times with (10 ms at `HZ=100`).
pub const MARGIN: Duration = Duration::from_millis(20);
/// The same where times have no fraction of a second (FAT, some network
/// file systems): their clocks tick by one or two seconds.
const COARSE_MARGIN: Duration = Duration::from_secs(3);

/// `3`: BLAKE3 hashes (`2` held SHA-256 ones).
const MAGIC: &[u8; 8] = b"UMBSTMP3";

/// What the file system says of a file, as far as a stamp compares it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileState {
    len: u64,
    ino: u64,
    dev: u64,
    mtime_ns: i128,
    ctime_ns: i128,
}

impl FileState {
    /// The state of a regular file's metadata; `None` where the platform
    /// has no inode numbers and status-change times (not Unix).
    pub fn of(m: &std::fs::Metadata) -> Option<FileState> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let ns = |s: i64, n: i64| s as i128 * 1_000_000_000 + n as i128;
            Some(FileState { len: m.len(), ino: m.ino(), dev: m.dev(), mtime_ns: ns(m.mtime(), m.mtime_nsec()), ctime_ns: ns(m.ctime(), m.ctime_nsec()) })
        }
        #[cfg(not(unix))]
        {
            let _ = m;
            None
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Stamp {
    state: FileState,
    hash: Key,
    /// When the state was read (before the file was), in nanoseconds
    /// since the epoch.
    taken_ns: i128,
}

impl Stamp {
    fn trusted(&self) -> bool {
        let margin = if self.state.ctime_ns % 1_000_000_000 == 0 { COARSE_MARGIN } else { MARGIN };
        self.taken_ns >= self.state.ctime_ns + margin.as_nanos() as i128
    }
}

/// The stamps of one output directory tree (see the module docs), shared
/// by the threads writing into it.
#[derive(Debug, Default)]
pub struct Stamps {
    /// The cache directory and the output directory, where loaded from.
    dirs: Option<(PathBuf, PathBuf)>,
    /// By path, as its bytes: a warm run of 256 variants looks up 1,793
    /// outputs, and `Path`'s own hash (component by component, SipHash)
    /// was most of its time.
    old: FxHashMap<OsString, Stamp>,
    new: Mutex<FxHashMap<OsString, Option<Stamp>>>,
}

/// Where the stamps of `out_dir` are kept: named by its canonical path,
/// so that every way of naming it finds them (`None` while it does not
/// exist).
fn stamps_path(cache_dir: &Path, out_dir: &Path) -> Option<PathBuf> {
    let canonical = std::fs::canonicalize(out_dir).ok()?;
    Some(cache_dir.join("stamps").join(Key::of_bytes(canonical.as_os_str().as_encoded_bytes()).hex()))
}

/// Now, in nanoseconds since the epoch.
pub fn now_ns() -> i128 {
    SystemTime::now().duration_since(SystemTime::UNIX_EPOCH).map_or(0, |d| d.as_nanos() as i128)
}

impl Stamps {
    /// The stamps kept in `cache_dir` for the outputs under `out_dir`
    /// (empty if there are none or they cannot be read).
    pub fn load(cache_dir: &Path, out_dir: &Path) -> Stamps {
        let old = stamps_path(cache_dir, out_dir).and_then(|p| std::fs::read(p).ok()).and_then(|b| decode(sealed::unseal(MAGIC, &b)?)).unwrap_or_default();
        Stamps { dirs: Some((cache_dir.to_path_buf(), out_dir.to_path_buf())), old, new: Mutex::new(FxHashMap::default()) }
    }

    /// The contents' hash of the file at `path`, if a trusted stamp of
    /// it matches its present state `state`.
    pub fn hash_of(&self, path: &Path, state: &FileState) -> Option<Key> {
        self.old.get(path.as_os_str()).filter(|s| s.state == *state && s.trusted()).map(|s| s.hash)
    }

    /// Remembers that the file at `path`, in state `state` read at
    /// `taken_ns` ([`now_ns`], before the file's contents were), holds
    /// contents with hash `hash`.
    pub fn record(&self, path: &Path, state: FileState, hash: Key, taken_ns: i128) {
        if let Ok(mut new) = self.new.lock() {
            new.insert(path.as_os_str().to_owned(), Some(Stamp { state, hash, taken_ns }));
        }
    }

    /// Forgets the file at `path` (it was just replaced). A path with no
    /// stamp has nothing to forget: a run into a new directory records
    /// nothing here.
    pub fn forget(&self, path: &Path) {
        let key = path.as_os_str();
        if let Ok(mut new) = self.new.lock() {
            if self.old.contains_key(key) || new.contains_key(key) {
                new.insert(key.to_owned(), None);
            }
        }
    }

    /// Writes the stamps back, if anything changed (best effort: stamps
    /// only save reading).
    pub fn save(self) {
        let new = self.new.into_inner().unwrap_or_default();
        if new.is_empty() || (self.old.is_empty() && new.values().all(Option::is_none)) {
            return;
        }
        let Some(path) = self.dirs.and_then(|(cache, out)| stamps_path(&cache, &out)) else { return };
        let mut all = self.old;
        for (p, s) in new {
            match s {
                Some(s) => all.insert(p, s),
                None => all.remove(&p),
            };
        }
        let _ = sealed::write_atomically(&path, &encode(&all));
    }
}

fn encode(all: &FxHashMap<OsString, Stamp>) -> Vec<u8> {
    let mut entries: Vec<_> = all.iter().collect();
    entries.sort_by(|a, b| a.0.cmp(b.0));
    let mut out = Vec::with_capacity(entries.len() * 160);
    for (p, s) in entries {
        sealed::put_path(&mut out, Path::new(p));
        out.extend_from_slice(&s.hash.0);
        for v in [s.state.len, s.state.ino, s.state.dev] {
            out.extend_from_slice(&v.to_le_bytes());
        }
        for v in [s.state.mtime_ns, s.state.ctime_ns, s.taken_ns] {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    sealed::seal(MAGIC, &out)
}

/// The stamps in the body of a stamps file (see [`sealed::unseal`]).
fn decode(body: &[u8]) -> Option<FxHashMap<OsString, Stamp>> {
    let mut r = Reader(body);
    // About 150 bytes a stamp: one allocation, no rehashing as it grows.
    let mut all = FxHashMap::with_capacity_and_hasher(body.len() / 140, Default::default());
    while !r.is_empty() {
        let path = r.path()?;
        let hash = Key(r.hash()?);
        let (len, ino, dev) = (r.u64()?, r.u64()?, r.u64()?);
        let (mtime_ns, ctime_ns, taken_ns) = (r.i128()?, r.i128()?, r.i128()?);
        all.insert(path.into_os_string(), Stamp { state: FileState { len, ino, dev, mtime_ns, ctime_ns }, hash, taken_ns });
    }
    Some(all)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stamp_is_trusted_only_for_the_state_it_saw_and_after_the_margin() {
        let d = tempfile::tempdir().unwrap();
        let (cache, out) = (d.path().join("cache"), d.path().join("out"));
        std::fs::create_dir_all(&out).unwrap();
        let f = out.join("a.wgsl");
        std::fs::write(&f, "one").unwrap();
        let state = FileState::of(&std::fs::metadata(&f).unwrap()).unwrap();
        let h = Key::of_bytes(b"one");

        // Taken within a margin of the file's change: racy, so not trusted.
        // (The times are given, not read from the clock: a slow machine
        // must not turn one case into the other.)
        let margin = MARGIN.as_nanos() as i128;
        let s = Stamps::load(&cache, &out);
        s.record(&f, state, h, state.ctime_ns + margin / 2);
        s.save();
        assert_eq!(Stamps::load(&cache, &out).hash_of(&f, &state), None);

        // Taken a margin later: trusted, for that state only.
        let s = Stamps::load(&cache, &out);
        s.record(&f, state, h, state.ctime_ns + margin);
        s.save();
        let s = Stamps::load(&cache, &out);
        assert_eq!(s.hash_of(&f, &state), Some(h));
        std::fs::write(&f, "two").unwrap();
        let changed = FileState::of(&std::fs::metadata(&f).unwrap()).unwrap();
        assert_ne!(changed, state, "a write changes the state");
        assert_eq!(s.hash_of(&f, &changed), None);

        // Forgotten when replaced; a damaged file is no stamps at all.
        s.forget(&f);
        s.save();
        assert_eq!(Stamps::load(&cache, &out).hash_of(&f, &state), None);
        let file = std::fs::read_dir(cache.join("stamps")).unwrap().next().unwrap().unwrap().path();
        let mut bytes = std::fs::read(&file).unwrap();
        let s = Stamps::load(&cache, &out);
        s.record(&f, state, h, now_ns() + 10_i128.pow(10));
        s.save();
        bytes = std::fs::read(&file).map(|b| if b.len() > 20 { b } else { bytes.clone() }).unwrap();
        let last = bytes.len() - 1;
        bytes[last] ^= 1;
        std::fs::write(&file, &bytes).unwrap();
        assert_eq!(Stamps::load(&cache, &out).hash_of(&f, &state), None);
    }
}
