//! The small binary files umbrac keeps in its cache directory: what the
//! cache entries (`cache`), the output stamps (`output::stamps`) and the
//! run records (`rerun`) share.
//!
//! - [`seal`] / [`unseal`]: an 8-byte magic (the format and its version),
//!   a CRC-32 of the rest, the rest. A file that fails is damage or another
//!   version, and reads as nothing.
//! - [`put_field`] and [`Reader`]: length-prefixed fields (`u64` lengths,
//!   little-endian), hashes and paths.
//! - [`write_atomically`]: a temporary beside the destination, renamed
//!   onto it, so a reader sees a whole file or the previous one.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::SystemTime;


/// How a temporary's name starts (cache entries are named by hex digits,
/// stamps and records too).
pub(crate) const TEMP_PREFIX: &str = ".tmp-";

/// `magic`, a CRC-32 of `body`, `body`.
pub(crate) fn seal(magic: &[u8; 8], body: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(12 + body.len());
    out.extend_from_slice(magic);
    out.extend_from_slice(&crc32fast::hash(body).to_le_bytes());
    out.extend_from_slice(body);
    out
}

/// The body of a file [`seal`] made with `magic`, if it is whole.
pub(crate) fn unseal<'a>(magic: &[u8; 8], bytes: &'a [u8]) -> Option<&'a [u8]> {
    let body = bytes.get(12..)?;
    (bytes[..8] == magic[..] && crc32fast::hash(body) == u32::from_le_bytes(bytes[8..12].try_into().ok()?)).then_some(body)
}

/// Appends `bytes` with its length.
pub(crate) fn put_field(out: &mut Vec<u8>, bytes: &[u8]) {
    out.extend_from_slice(&(bytes.len() as u64).to_le_bytes());
    out.extend_from_slice(bytes);
}

/// Appends a path as its bytes, with their length.
pub(crate) fn put_path(out: &mut Vec<u8>, path: &Path) {
    put_field(out, path.as_os_str().as_encoded_bytes());
}

/// Reads what [`put_field`] and its neighbours wrote; every method is
/// `None` past the end.
pub(crate) struct Reader<'a>(pub &'a [u8]);

impl<'a> Reader<'a> {
    pub fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        if self.0.len() < n {
            return None;
        }
        let (a, rest) = self.0.split_at(n);
        self.0 = rest;
        Some(a)
    }

    pub fn u64(&mut self) -> Option<u64> {
        Some(u64::from_le_bytes(self.take(8)?.try_into().ok()?))
    }

    pub fn i128(&mut self) -> Option<i128> {
        Some(i128::from_le_bytes(self.take(16)?.try_into().ok()?))
    }

    /// A length-prefixed field.
    pub fn field(&mut self) -> Option<&'a [u8]> {
        let n = usize::try_from(self.u64()?).ok()?;
        self.take(n)
    }

    pub fn path(&mut self) -> Option<PathBuf> {
        path_of_bytes(self.field()?)
    }

    pub fn hash(&mut self) -> Option<[u8; 32]> {
        self.take(32)?.try_into().ok()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

#[cfg(unix)]
fn path_of_bytes(b: &[u8]) -> Option<PathBuf> {
    use std::os::unix::ffi::OsStrExt;
    Some(PathBuf::from(std::ffi::OsStr::from_bytes(b)))
}

/// Where paths are not bytes, no stamp or record holding one is read back
/// (there are no stamps there: `output::stamps::FileState::of`).
#[cfg(not(unix))]
fn path_of_bytes(_: &[u8]) -> Option<PathBuf> {
    None
}

/// A temporary name in `dir` no other thread or process uses: the process
/// id, a per-process counter and the clock.
pub(crate) fn unique_temp(dir: &Path) -> PathBuf {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let nanos = SystemTime::now().duration_since(SystemTime::UNIX_EPOCH).map(|d| d.subsec_nanos()).unwrap_or(0);
    // One `getpid` per process, not per file.
    static PID: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
    dir.join(format!("{TEMP_PREFIX}{}-{n}-{nanos:08x}", PID.get_or_init(std::process::id)))
}

/// Writes `bytes` to `path` (its directory created if missing) through a
/// temporary beside it, removed if anything fails. No fsync: what these
/// files hold is checked when read, and redone when damaged.
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    write_atomically_in(dir, path, bytes)
}

/// [`write_atomically`] into `dir`, `path`'s directory, which exists.
pub(crate) fn write_atomically_in(dir: &Path, path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = unique_temp(dir);
    let written = std::fs::File::options().write(true).create_new(true).open(&tmp).and_then(|mut f| f.write_all(bytes));
    match written.and_then(|_| std::fs::rename(&tmp, path)) {
        Ok(()) => Ok(()),
        Err(e) => {
            let _ = std::fs::remove_file(&tmp);
            Err(e)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sealed_bytes_read_back_and_any_damage_reads_as_nothing() {
        let mut body = Vec::new();
        put_field(&mut body, b"abc");
        put_path(&mut body, Path::new("d/e.das"));
        let sealed = seal(b"UMBTEST1", &body);
        let got = unseal(b"UMBTEST1", &sealed).unwrap();
        let mut r = Reader(got);
        assert_eq!(r.field(), Some(&b"abc"[..]));
        assert_eq!(r.path(), Some(PathBuf::from("d/e.das")));
        assert!(r.is_empty() && r.u64().is_none());
        assert!(unseal(b"UMBTEST2", &sealed).is_none(), "another format or version");
        for i in 0..sealed.len() {
            let mut bad = sealed.clone();
            bad[i] ^= 0x10;
            assert!(unseal(b"UMBTEST1", &bad).is_none(), "byte {i} flipped");
        }
        assert!(unseal(b"UMBTEST1", &sealed[..sealed.len() - 1]).is_none());
    }
}
