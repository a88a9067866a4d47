//! A rerun that would change nothing, told without compiling.
//!
//! A build system reruns a command when any of its inputs is newer than
//! its outputs, and a user reruns it by hand; most of those reruns find
//! every output as it was. After a command succeeds, a [`Record`] keeps
//! what it depended on and what it left:
//!
//! - the hash of every file it read (sources, includes, modules, the
//!   variant spec);
//! - every path an `#include` or `require` looked at and found no file at
//!   ([`crate::syntax::Unit::probed`]): a file appearing there would change
//!   what is read;
//! - the hash of every output, and the depfile's text.
//!
//! It is stored in the cache directory (`runs/`), under a key made of the
//! command's whole configuration (umbrac's build, the inputs, the variants,
//! every option, the output directory and depfile). The next run with the
//! same key checks the record: every file read must hash as before,
//! nothing may have appeared where nothing was, and every output must
//! still hold its recorded bytes, and be newer than every file read (or
//! make would rerun the command). An output a trusted stamp
//! ([`crate::output::stamps`]) vouches for is not read; one it does not
//! (the first rerun after the outputs were written) is read, hashed and
//! stamped, so the first rerun already has nothing else to do, and the
//! next ones read no output at all. If all of that holds the command has nothing to do but
//! rewrite the depfile (ninja deletes it once read): nothing is
//! preprocessed or read from the cache. If anything differs, the command
//! runs as usual, so a record can only ever save work, never change a
//! result.

use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::cache::{Cache, Key};
use crate::output::stamps::{now_ns, FileState, Stamps};
use crate::sealed::{self, Reader};

/// `02`: BLAKE3 hashes (`01` held SHA-256 ones).
const MAGIC: &[u8; 8] = b"UMBRUN02";

/// What one successful command depended on and left (see the module docs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Record {
    /// Every file read, with the hash of its contents.
    pub files: Vec<(PathBuf, Key)>,
    /// Where nothing was found.
    pub probed: Vec<PathBuf>,
    /// Every output, with the hash of its contents.
    pub outputs: Vec<(PathBuf, Key)>,
    /// The depfile and its text, if one was asked for.
    pub depfile: Option<(PathBuf, Vec<u8>)>,
    /// `-v`'s counts of the run: jobs, compiled, from the cache, shared.
    pub counts: [u64; 4],
}

/// The key of a command's configuration: its parts, each length-prefixed,
/// after umbrac's own build id.
pub fn key(parts: &[&[u8]]) -> Key {
    let mut all = Vec::new();
    for p in std::iter::once(crate::cache::compiler_id().as_bytes()).chain(parts.iter().copied()) {
        all.extend_from_slice(&(p.len() as u64).to_le_bytes());
        all.extend_from_slice(p);
    }
    Key::of_bytes(&all)
}

impl Record {
    fn path(cache: &Cache, key: &Key) -> PathBuf {
        cache.dir().join("runs").join(key.hex())
    }

    /// The record stored under `key`, if there is an intact one.
    pub fn load(cache: &Cache, key: &Key) -> Option<Record> {
        decode(sealed::unseal(MAGIC, &std::fs::read(Self::path(cache, key)).ok()?)?)
    }

    /// Stores the record under `key`, atomically (best effort: a record
    /// only saves work).
    pub fn save(&self, cache: &Cache, key: &Key) {
        let _ = sealed::write_atomically(&Self::path(cache, key), &encode(self));
    }

    /// Whether a rerun would change nothing (see the module docs), the
    /// outputs checked on up to `workers` threads. Outputs read to see that
    /// are stamped in `stamps` (the caller saves them).
    pub fn still_holds(&self, stamps: &Stamps, workers: usize) -> bool {
        // When the outputs' states are read: before any of them is (an
        // earlier time only makes a stamp less trusted), and once, not
        // once per output (2,000 clock reads for 256 variants).
        let taken = now_ns();
        let mut newest = SystemTime::UNIX_EPOCH;
        for (path, hash) in &self.files {
            // Not a regular file any more (a FIFO would block the read):
            // the command runs, and says what it is.
            if !std::fs::metadata(path).is_ok_and(|m| m.is_file()) {
                return false;
            }
            let Ok(bytes) = std::fs::read(path) else { return false };
            if Key::of_bytes(&bytes) != *hash {
                return false;
            }
            match std::fs::metadata(path).and_then(|m| m.modified()) {
                Ok(t) => newest = newest.max(t),
                Err(_) => return false,
            }
        }
        if self.probed.iter().any(|p| std::fs::metadata(p).is_ok()) {
            return false;
        }
        let chunk = self.outputs.len().div_ceil(workers.max(1)).max(64);
        let chunks: Vec<&[(PathBuf, Key)]> = self.outputs.chunks(chunk).collect();
        let held = crate::batch::parallel_map(chunks.len(), workers, |c| chunks[c].iter().all(|(p, h)| output_holds(p, h, stamps, newest, taken)), |_, _| false);
        held.into_iter().all(|h| h)
    }
}

/// Whether the output at `path` is newer than `newest` and holds bytes
/// with hash `hash`: by a trusted stamp, or else read (and then stamped as
/// of `taken`, a time before its state is read: as in
/// `output::write_outputs_known`, the clock, then the state, then the
/// bytes, so a change after the state was read shows in it).
fn output_holds(path: &Path, hash: &Key, stamps: &Stamps, newest: SystemTime, taken: i128) -> bool {
    let Ok(m) = std::fs::symlink_metadata(path) else { return false };
    if !m.is_file() || !m.modified().is_ok_and(|t| t > newest) {
        return false;
    }
    let state = FileState::of(&m);
    if state.is_some_and(|s| stamps.hash_of(path, &s) == Some(*hash)) {
        return true;
    }
    let Ok(bytes) = std::fs::read(path) else { return false };
    if Key::of_bytes(&bytes) != *hash {
        return false;
    }
    if let Some(s) = state {
        stamps.record(path, s, *hash, taken);
    }
    true
}

fn encode(r: &Record) -> Vec<u8> {
    let mut out = Vec::with_capacity(64 + 128 * (r.files.len() + r.probed.len() + r.outputs.len()));
    for c in r.counts {
        out.extend_from_slice(&c.to_le_bytes());
    }
    for list in [&r.files, &r.outputs] {
        out.extend_from_slice(&(list.len() as u64).to_le_bytes());
        for (p, h) in list.iter() {
            sealed::put_path(&mut out, p);
            out.extend_from_slice(&h.0);
        }
    }
    out.extend_from_slice(&(r.probed.len() as u64).to_le_bytes());
    for p in &r.probed {
        sealed::put_path(&mut out, p);
    }
    match &r.depfile {
        Some((p, text)) => {
            out.push(1);
            sealed::put_path(&mut out, p);
            sealed::put_field(&mut out, text);
        }
        None => out.push(0),
    }
    sealed::seal(MAGIC, &out)
}

/// A record from the body of its file (see [`sealed::unseal`]).
fn decode(body: &[u8]) -> Option<Record> {
    let mut r = Reader(body);
    let mut rec = Record::default();
    for c in rec.counts.iter_mut() {
        *c = r.u64()?;
    }
    for list in [&mut rec.files, &mut rec.outputs] {
        for _ in 0..r.u64()? {
            let p = r.path()?;
            list.push((p, Key(r.hash()?)));
        }
    }
    for _ in 0..r.u64()? {
        rec.probed.push(r.path()?);
    }
    rec.depfile = match r.take(1)?[0] {
        0 => None,
        _ => Some((r.path()?, r.field()?.to_vec())),
    };
    r.is_empty().then_some(rec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_round_trip_and_damage_is_no_record() {
        let d = tempfile::tempdir().unwrap();
        let cache = Cache::new(d.path(), crate::cache::DEFAULT_MAX_BYTES);
        let rec = Record {
            files: vec![(PathBuf::from("a.das"), Key::of_bytes(b"a"))],
            probed: vec![PathBuf::from("inc/x.das")],
            outputs: vec![(PathBuf::from("out/a.wgsl"), Key::of_bytes(b"w")), (PathBuf::from("out/a.spv"), Key::of_bytes(b"s"))],
            depfile: Some((PathBuf::from("a.d"), b"out/a.wgsl: a.das\n".to_vec())),
            counts: [1, 1, 0, 0],
        };
        let k = key(&[b"one"]);
        assert_ne!(k, key(&[b"on", b"e"]), "parts are delimited");
        rec.save(&cache, &k);
        assert_eq!(Record::load(&cache, &k), Some(rec.clone()));
        let path = Record::path(&cache, &k);
        let mut bytes = std::fs::read(&path).unwrap();
        bytes[20] ^= 4;
        std::fs::write(&path, &bytes).unwrap();
        assert_eq!(Record::load(&cache, &k), None);
        std::fs::write(&path, &encode(&rec)[..30]).unwrap();
        assert_eq!(Record::load(&cache, &k), None);
    }

    #[test]
    fn a_changed_input_or_an_appeared_file_means_the_command_runs() {
        let d = tempfile::tempdir().unwrap();
        let src = d.path().join("a.das");
        std::fs::write(&src, "x").unwrap();
        let probed = d.path().join("inc.das");
        let rec = Record { files: vec![(src.clone(), Key::of_bytes(b"x"))], probed: vec![probed.clone()], ..Default::default() };
        let stamps = Stamps::default();
        assert!(rec.still_holds(&stamps, 2), "no outputs to check: holds");
        std::fs::write(&src, "y").unwrap();
        assert!(!rec.still_holds(&stamps, 2), "an input changed");
        std::fs::write(&src, "x").unwrap();
        std::fs::write(&probed, "").unwrap();
        assert!(!rec.still_holds(&stamps, 2), "a file appeared where an include looked");
        std::fs::remove_file(&probed).unwrap();
        let out = d.path().join("a.wgsl");
        let with_output = Record { outputs: vec![(out.clone(), Key::of_bytes(b"w"))], ..rec };
        // Times set, not left to the clock: the output must be newer than
        // the input, which a coarse clock could make a tie.
        let input_time = std::fs::metadata(&src).unwrap().modified().unwrap();
        let set_time = |t| std::fs::File::options().write(true).open(&out).unwrap().set_modified(t).unwrap();
        std::fs::write(&out, "x").unwrap();
        set_time(input_time + std::time::Duration::from_secs(1));
        assert!(!with_output.still_holds(&stamps, 2), "an output that holds other bytes");
        std::fs::write(&out, "w").unwrap();
        set_time(input_time);
        assert!(!with_output.still_holds(&stamps, 2), "an output not newer than an input");
        set_time(input_time + std::time::Duration::from_secs(1));
        // No stamp vouches for it: it is read, found to hold its bytes,
        // and stamped (a stamp taken now of a file changed now is not
        // trusted, so only its recording is checked here).
        let stamps = Stamps::load(&d.path().join("cache"), d.path());
        assert!(with_output.still_holds(&stamps, 2), "an output read and found to hold its bytes");
        stamps.save();
        assert!(d.path().join("cache/stamps").read_dir().unwrap().next().is_some(), "the output read was stamped");
    }
}
