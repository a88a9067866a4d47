//! Cache hits without preprocessing (what ccache calls its direct mode).
//!
//! A unit's [`Key`] is a hash of its preprocessed tokens, so finding its
//! entry meant reading, lexing and expanding its sources first: on a hit
//! that was over a third of a whole process's instructions
//! (docs/performance.md, "Whole process"). After a batch has preprocessed
//! its units, a [`Manifest`] keeps, under a key of the batch's whole
//! configuration ([`batch_key`]: umbrac's build, the working directory,
//! each unit's path, options and extra), every file read with the hash of
//! its bytes, every path an `#include` or `require` found no file at, and
//! each unit's key, files read and paths probed. Preprocessing is a
//! function of exactly those, so the next batch with that configuration
//! checks the manifest ([`Manifest::load`]): if every file still hashes as
//! it did and nothing has appeared where nothing was, each unit's key is
//! the recorded one and its entry is read without preprocessing. Anything
//! else and the batch preprocesses as before, and records again: a
//! manifest can only save work. A damaged one reads as none.
//!
//! Manifests live in the cache directory (`direct/`), are written
//! atomically, and those unused for a month are removed by
//! [`super::Cache::trim`].

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use rustc_hash::FxHashMap;

use super::{Cache, Key};
use crate::sealed::{self, Reader};

const MAGIC: &[u8; 8] = b"UMBDIR01";

/// What one unit read, and the key it preprocessed to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnitRead {
    pub key: Key,
    pub files_read: Vec<PathBuf>,
    pub probed: Vec<PathBuf>,
}

/// A manifest that still holds ([`Manifest::load`]).
#[derive(Clone, Debug)]
pub struct Held {
    /// Per unit, in the batch's order.
    pub units: Vec<UnitRead>,
    /// Every distinct file read, with the hash of its bytes as it is now.
    pub files: Vec<(PathBuf, Key)>,
}

/// What a batch read (see the module docs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Manifest {
    /// Every distinct file read, with the hash of its bytes.
    files: Vec<(PathBuf, Key)>,
    /// Per unit, in the batch's order.
    units: Vec<Recorded>,
}

/// A unit in a manifest: its key, the indices of the files it read in
/// [`Manifest`]'s files, the paths it probed.
type Recorded = (Key, Vec<u32>, Vec<PathBuf>);

/// The key of a batch's configuration: every unit's path, options and
/// extra, after umbrac's build and the working directory (relative paths,
/// includes and `-I` directories are resolved from it).
pub fn batch_key<'a>(units: impl ExactSizeIterator<Item = (&'a Path, String, &'a str)>) -> Key {
    let mut h = blake3::Hasher::new();
    let mut field = |bytes: &[u8]| {
        h.update(&(bytes.len() as u64).to_le_bytes());
        h.update(bytes);
    };
    field(b"umbrac direct manifest 1");
    field(super::compiler_id().as_bytes());
    field(format!("{:?}", std::env::current_dir().ok()).as_bytes());
    field(&(units.len() as u64).to_le_bytes());
    for (path, opts, extra) in units {
        field(path.as_os_str().as_encoded_bytes());
        field(opts.as_bytes());
        field(extra.as_bytes());
    }
    Key(*h.finalize().as_bytes())
}

impl Manifest {
    fn path(cache: &Cache, key: &Key) -> PathBuf {
        cache.dir().join("direct").join(key.hex())
    }

    /// What each of `units` units read and preprocessed to, if a manifest
    /// for `key` exists, is intact, is for that many units, and still
    /// holds: every file hashes as recorded, and no path probed holds a
    /// file now.
    pub fn load(cache: &Cache, key: &Key, units: usize) -> Option<Held> {
        let bytes = std::fs::read(Self::path(cache, key)).ok()?;
        let m = decode(sealed::unseal(MAGIC, &bytes)?)?;
        if m.units.len() != units {
            return None;
        }
        for (path, hash) in &m.files {
            // A path that is no longer a regular file (a FIFO would block
            // the read) is preprocessed, which says what it is.
            if !std::fs::metadata(path).ok()?.is_file() || Key::of_bytes(&std::fs::read(path).ok()?) != *hash {
                return None;
            }
        }
        let mut checked: rustc_hash::FxHashSet<&Path> = Default::default();
        for p in m.units.iter().flat_map(|u| &u.2) {
            if checked.insert(p) && std::fs::metadata(p).is_ok() {
                return None;
            }
        }
        let files = &m.files;
        let units = m.units.iter().map(|(key, read, probed)| UnitRead { key: *key, files_read: read.iter().map(|&i| files[i as usize].0.clone()).collect(), probed: probed.clone() }).collect();
        Some(Held { units, files: m.files })
    }

    /// Every distinct file read, with the hash of its bytes.
    pub fn files(&self) -> &[(PathBuf, Key)] {
        &self.files
    }

    /// Stores the manifest under `key`, atomically (best effort: a
    /// manifest only saves work).
    pub fn save(&self, cache: &Cache, key: &Key) {
        let _ = sealed::write_atomically(&Self::path(cache, key), &encode(self));
    }
}

/// Builds a [`Manifest`] while a batch's units are preprocessed, on any
/// number of threads: each distinct file's text is hashed once, and a
/// file two units saw with different bytes (changed during the batch)
/// leaves no manifest.
#[derive(Debug, Default)]
pub struct Recorder {
    /// Per path: its index in the manifest's files, its text and hash.
    seen: Mutex<FxHashMap<PathBuf, (u32, String, Key)>>,
    units: Mutex<FxHashMap<usize, Recorded>>,
    spoiled: AtomicBool,
}

impl Recorder {
    /// Records unit `i`, preprocessed to `key` from `pre`'s files.
    pub fn unit(&self, i: usize, key: Key, pre: &crate::Preprocessed) {
        let mut read = Vec::new();
        for (_, f) in pre.sources().files() {
            let Some(path) = &f.path else { continue };
            let Ok(mut seen) = self.seen.lock() else { return self.spoil() };
            let next = seen.len() as u32;
            match seen.get(path) {
                Some((at, text, _)) if *text == f.text => read.push(*at),
                Some(_) => return self.spoil(),
                None => {
                    seen.insert(path.clone(), (next, f.text.clone(), Key::of_bytes(f.text.as_bytes())));
                    read.push(next);
                }
            }
        }
        match self.units.lock() {
            Ok(mut units) => {
                units.insert(i, (key, read, pre.probed().to_vec()));
            }
            Err(_) => self.spoil(),
        }
    }

    /// A unit that cannot be recorded (it failed to preprocess): the batch
    /// gets no manifest.
    pub fn spoil(&self) {
        self.spoiled.store(true, Ordering::Relaxed);
    }

    /// The manifest of a batch of `units` units, if every one was recorded.
    pub fn finish(self, units: usize) -> Option<Manifest> {
        if self.spoiled.into_inner() {
            return None;
        }
        let mut recorded = self.units.into_inner().ok()?;
        let mut files: Vec<(u32, PathBuf, Key)> = self.seen.into_inner().ok()?.into_iter().map(|(p, (i, _, h))| (i, p, h)).collect();
        files.sort_by_key(|f| f.0);
        let units = (0..units).map(|i| recorded.remove(&i)).collect::<Option<Vec<_>>>()?;
        Some(Manifest { files: files.into_iter().map(|(_, p, h)| (p, h)).collect(), units })
    }
}

fn encode(m: &Manifest) -> Vec<u8> {
    let mut out = Vec::with_capacity(64 + 128 * m.files.len() + 64 * m.units.len());
    out.extend_from_slice(&(m.files.len() as u64).to_le_bytes());
    for (p, h) in &m.files {
        sealed::put_path(&mut out, p);
        out.extend_from_slice(&h.0);
    }
    out.extend_from_slice(&(m.units.len() as u64).to_le_bytes());
    for (key, read, probed) in &m.units {
        out.extend_from_slice(&key.0);
        out.extend_from_slice(&(read.len() as u64).to_le_bytes());
        for &i in read {
            out.extend_from_slice(&u64::from(i).to_le_bytes());
        }
        out.extend_from_slice(&(probed.len() as u64).to_le_bytes());
        for p in probed {
            sealed::put_path(&mut out, p);
        }
    }
    sealed::seal(MAGIC, &out)
}

/// A manifest from the body of its file; `None` unless it is well formed.
fn decode(body: &[u8]) -> Option<Manifest> {
    let mut r = Reader(body);
    let mut m = Manifest::default();
    for _ in 0..r.u64()? {
        let p = r.path()?;
        m.files.push((p, Key(r.hash()?)));
    }
    for _ in 0..r.u64()? {
        let key = Key(r.hash()?);
        let mut read = Vec::new();
        for _ in 0..r.u64()? {
            let i = u32::try_from(r.u64()?).ok().filter(|&i| (i as usize) < m.files.len())?;
            read.push(i);
        }
        let mut probed = Vec::new();
        for _ in 0..r.u64()? {
            probed.push(r.path()?);
        }
        m.units.push((key, read, probed));
    }
    r.is_empty().then_some(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_manifest_holds_until_a_file_changes_or_appears_and_damage_is_none() {
        let d = tempfile::tempdir().unwrap();
        let cache = Cache::new(d.path().join("cache"), super::super::DEFAULT_MAX_BYTES);
        // `inc.das` is looked for beside `main.das` first (not there: a
        // path probed), then found in the `-I` directory.
        let (main, inc, probe) = (d.path().join("main.das"), d.path().join("lib/inc.das"), d.path().join("inc.das"));
        std::fs::create_dir_all(d.path().join("lib")).unwrap();
        std::fs::write(&inc, "var b = 2\n").unwrap();
        std::fs::write(&main, "#include \"inc.das\"\nvar a = 1\n").unwrap();
        let opts = crate::Options { include_dirs: vec![d.path().join("lib")], ..Default::default() };
        // Two units reading the same files: each file once in the manifest.
        let rec = Recorder::default();
        let pre = crate::preprocess_file(&main, &opts);
        assert!(!pre.has_errors());
        assert_eq!(pre.probed(), std::slice::from_ref(&probe));
        rec.unit(1, Key([1; 32]), &pre);
        rec.unit(0, Key([0; 32]), &pre);
        let m = Recorder::finish(rec, 2).unwrap();
        assert_eq!(m.files.len(), 2, "{m:?}");
        let key = batch_key([(main.as_path(), format!("{opts:?}"), "")].into_iter());
        m.save(&cache, &key);
        let units = Manifest::load(&cache, &key, 2).unwrap().units;
        assert_eq!(units[0].key, Key([0; 32]));
        assert_eq!(units[1].files_read, units[0].files_read);
        assert!(Manifest::load(&cache, &key, 3).is_none(), "another number of units");

        // A file changed: no manifest; back as it was: it holds again.
        std::fs::write(&inc, "var b = 3\n").unwrap();
        assert!(Manifest::load(&cache, &key, 2).is_none());
        std::fs::write(&inc, "var b = 2\n").unwrap();
        assert!(Manifest::load(&cache, &key, 2).is_some());

        // A file where an include looked and found none: no manifest.
        std::fs::write(&probe, "var b = 2\n").unwrap();
        assert!(Manifest::load(&cache, &key, 2).is_none());
        std::fs::remove_file(&probe).unwrap();
        assert!(Manifest::load(&cache, &key, 2).is_some());

        // A FIFO where a file was: no manifest, and no read that waits
        // for a writer.
        #[cfg(target_os = "linux")]
        {
            std::fs::remove_file(&inc).unwrap();
            let c = std::ffi::CString::new(inc.to_str().unwrap()).unwrap();
            // SAFETY: a valid NUL-terminated path; mkfifo only creates a file.
            assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
            assert!(Manifest::load(&cache, &key, 2).is_none());
            std::fs::remove_file(&inc).unwrap();
            std::fs::write(&inc, "var b = 2\n").unwrap();
            assert!(Manifest::load(&cache, &key, 2).is_some());
        }

        // Damage is no manifest.
        let path = Manifest::path(&cache, &key);
        let mut bytes = std::fs::read(&path).unwrap();
        let last = bytes.len() - 1;
        bytes[last] ^= 1;
        std::fs::write(&path, &bytes).unwrap();
        assert!(Manifest::load(&cache, &key, 2).is_none());
    }

    #[test]
    fn a_unit_that_saw_other_bytes_or_was_not_recorded_leaves_no_manifest() {
        let d = tempfile::tempdir().unwrap();
        let main = d.path().join("main.das");
        let opts = crate::Options::default();
        std::fs::write(&main, "var a = 1\n").unwrap();
        let one = crate::preprocess_file(&main, &opts);
        std::fs::write(&main, "var a = 2\n").unwrap();
        let two = crate::preprocess_file(&main, &opts);
        let rec = Recorder::default();
        rec.unit(0, Key([0; 32]), &one);
        rec.unit(1, Key([1; 32]), &two);
        assert!(rec.finish(2).is_none(), "the file changed between the two");
        let rec = Recorder::default();
        rec.unit(0, Key([0; 32]), &one);
        assert!(rec.finish(2).is_none(), "unit 1 was not recorded");
    }
}
