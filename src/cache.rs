//! A content-addressed cache of compiled outputs.
//!
//! The [`Key`] of a compilation is a BLAKE3 hash of everything its outputs
//! depend on: the preprocessed token stream of the whole translation unit
//! (every file read, after `#include`, `#ifdef` and `#define`, so the `-D`
//! definitions and the include directories are in it through what they
//! changed), the name and stem the outputs record, the targets, the entry
//! points, the conventions, and umbrac's version and build id (a hash of
//! the compiler's sources and its naga release, made by `build.rs`).
//! Comments and whitespace are not tokens, so editing only them is a hit;
//! two define sets that preprocess to the same text share one entry.
//!
//! An entry is one file, `DIR/v4/AB/ABCDEF...`: a header (magic, the key,
//! the body's length, a CRC-32 of the body) and the artifacts, each with
//! the BLAKE3 hash of its contents, which is what `variants.json` records
//! of each output: a hit hashes no output. The CRC-32 (crc32fast, SIMD) is
//! there to catch damage, not forgery: it detects every truncation (with
//! the length), every burst of up to 32 flipped bits and all but 2^-32 of
//! other corruption, at a small part of the cost of hashing each output
//! again on every hit.
//!
//! BLAKE3, not SHA-256 (which layouts up to `v3` used): a content-addressed
//! cache wants a cryptographic hash, and BLAKE3 is one at several times
//! fewer instructions a byte (its SIMD code is chosen at run time). SHA-256
//! in portable code was a third of a whole compile (docs/performance.md,
//! "Whole process"). Nothing is hashed that no cache, run record or
//! `variants.json` will use: `--no-cache` on one file hashes nothing. An entry is written to a temporary
//! beside it (`.tmp-*` in its own `AB/` directory, so that stores on
//! several threads do not all create files in one directory) and renamed
//! into place, so a reader sees a whole entry or none; two processes that
//! store the same key write the same bytes, and the last rename wins.
//! Reading checks the magic, the key, the length and the CRC: an entry that
//! fails (truncated, corrupted, from an incompatible version) is removed
//! and reported as a miss, never served. A hit refreshes the entry's
//! modification time when it is over a minute old (so a warm run right
//! after another writes nothing to the cache); [`Cache::trim`] keeps the
//! total size under the bound by removing the entries used longest ago
//! (not needed, and skipped, in a cache that did not exist before this
//! run and holds less than the bound: [`Cache::may_need_trim`]).
//!
//! Only successful compilations with no diagnostic at all are stored, so a
//! hit never hides a warning. Failing to read or write the cache never
//! fails a compilation: it is then compiled, and not stored.

use std::fmt;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use crate::sealed::{Reader, TEMP_PREFIX};

pub mod direct;
use crate::syntax::token::{Kw, TokKind, Token, P};
use crate::{Artifact, Options, Preprocessed, Target};

/// The default bound on a cache's size: 256 MiB (the 256 variants of
/// `shaders/variants.das` for every target take about 3 MiB).
pub const DEFAULT_MAX_BYTES: u64 = 256 << 20;

/// Entry layout version; a change makes every old entry a miss (and
/// removes it on the first read).
const MAGIC: &[u8; 8] = b"UMBRAC\x04\x00";
const LAYOUT_DIR: &str = "v4";
const HEADER_LEN: usize = 8 + 32 + 8 + 4;


/// A hit refreshes an entry's modification time (its place in the
/// eviction order) only when it is older than this.
const REFRESH_AFTER: Duration = Duration::from_secs(60);

/// umbrac's own identity in every key: a new release or a rebuilt compiler
/// never serves another's outputs.
const COMPILER_ID: &str = concat!(env!("CARGO_PKG_VERSION"), "+", env!("UMBRAC_BUILD_ID"));

/// umbrac's version and build id, as every key includes them.
pub fn compiler_id() -> &'static str {
    COMPILER_ID
}

/// A BLAKE3 content hash (256 bits).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Key(pub [u8; 32]);

impl Key {
    /// The key of compiling `pre` with `opts`. `extra` separates entries
    /// that hold more than the compiler's outputs (`umbrac::build` adds its
    /// bindings module and names the generator's options in it).
    pub fn of(pre: &Preprocessed, opts: &Options, extra: &str) -> Key {
        let mut h = blake3::Hasher::new();
        let field = |h: &mut blake3::Hasher, bytes: &[u8]| {
            h.update(&(bytes.len() as u64).to_le_bytes());
            h.update(bytes);
        };
        field(&mut h, b"umbrac compile key 2");
        field(&mut h, COMPILER_ID.as_bytes());
        let root_name = pre.root_name();
        field(&mut h, opts.source_name.as_deref().unwrap_or(root_name).as_bytes());
        field(&mut h, crate::stem_of(root_name).as_bytes());
        for t in opts.targets() {
            field(&mut h, t.name().as_bytes());
        }
        field(&mut h, b"entries");
        for e in &opts.entries {
            field(&mut h, e.as_bytes());
        }
        field(&mut h, format!("{:?}", opts.conventions).as_bytes());
        field(&mut h, opts.gl_uniforms.as_str().as_bytes());
        field(&mut h, format!("{:?} strict {}", opts.limits, opts.strict_limits).as_bytes());
        field(&mut h, extra.as_bytes());
        // Where `require` looks decides which files the tokens come from.
        field(&mut h, b"modules");
        for d in opts.daslib.iter().chain(&opts.daslang_root) {
            field(&mut h, d.as_os_str().as_encoded_bytes());
        }
        for (prefix, dir) in &opts.modules {
            field(&mut h, prefix.as_bytes());
            field(&mut h, dir.as_os_str().as_encoded_bytes());
        }
        field(&mut h, b"tokens");
        hash_tokens(&mut h, pre.tokens(), pre.sources());
        Key(*h.finalize().as_bytes())
    }

    /// The hash of some bytes (output hashes in `variants.json`).
    pub fn of_bytes(bytes: &[u8]) -> Key {
        Key(*blake3::hash(bytes).as_bytes())
    }

    pub fn hex(&self) -> String {
        const DIGITS: &[u8; 16] = b"0123456789abcdef";
        let mut s = String::with_capacity(64);
        for b in self.0 {
            s.push(DIGITS[(b >> 4) as usize] as char);
            s.push(DIGITS[(b & 15) as usize] as char);
        }
        s
    }
}

/// The hash of each artifact's contents, in order.
pub fn hashes_of(artifacts: &[Artifact]) -> Vec<Key> {
    artifacts.iter().map(|a| Key::of_bytes(&a.contents)).collect()
}

/// What an entry holds: artifacts and the hash of each one's contents.
#[derive(Clone, Debug)]
pub struct Entry {
    pub artifacts: Vec<Artifact>,
    pub hashes: Vec<Key>,
}

impl fmt::Debug for Key {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Key({})", self.hex())
    }
}

/// Feeds each token's kind, and the text of those whose kind does not
/// fix it. The kind is given as a number so that a text that lexes
/// differently in another context (a macro's value) still hashes as what
/// it is. A keyword or a punctuation token has one spelling (the lexer
/// makes each from exactly its text), so its kind is all of it: a byte.
/// Other tokens add their length (LEB128) and text. This stream is about
/// half the bytes of one with a fixed-size length for every token, and
/// so half the hashing (docs/performance.md, "Whole process").
fn hash_tokens(h: &mut blake3::Hasher, toks: &[Token], map: &crate::SourceMap) {
    // Each token's text straight from its file's bytes: the tokens of a
    // run mostly come from one file, which is found again only when a
    // token lies outside it (`SourceMap::slice` located every token, a
    // third of the key's instructions).
    let files: Vec<(u32, &[u8])> = map.files().map(|(_, f)| (f.base, f.text.as_bytes())).collect();
    let mut cur: (u32, &[u8]) = files.first().copied().unwrap_or((0, &[]));
    let mut buf = Vec::with_capacity(64 * 1024);
    // Line breaks before the first token (a comment at the top of the file)
    // end no statement. Runs of them are one token already.
    let first = toks.iter().position(|t| t.kind != TokKind::Newline).unwrap_or(toks.len());
    for t in &toks[first..] {
        let code = kind_code(t.kind);
        buf.push(code);
        if code >= FIXED_TEXT {
            continue;
        }
        let (start, end) = (t.span.start, t.span.end.max(t.span.start));
        if start < cur.0 || start - cur.0 > cur.1.len() as u32 {
            let at = files.partition_point(|f| f.0 <= start);
            cur = at.checked_sub(1).map_or((0, &[]), |i| files[i]);
        }
        // As `SourceMap::slice`: clipped to the file, empty outside any.
        let bytes = cur.1;
        let from = ((start - cur.0) as usize).min(bytes.len());
        let text = &bytes[from..((end - cur.0) as usize).clamp(from, bytes.len())];
        let mut len = text.len();
        while len >= 0x80 {
            buf.push(0x80 | (len & 0x7f) as u8);
            len >>= 7;
        }
        buf.push(len as u8);
        buf.extend_from_slice(text);
        if buf.len() >= 60 * 1024 {
            h.update(&buf);
            buf.clear();
        }
    }
    h.update(&buf);
}

/// Kind codes from here up are keywords and punctuation, whose text the
/// kind fixes.
const FIXED_TEXT: u8 = 0x40;

fn kind_code(k: TokKind) -> u8 {
    // Checked at compile time: the keywords' codes stay below the
    // punctuation's, and the last punctuation's fits a byte.
    const _: () = assert!(FIXED_TEXT as usize + (Kw::False as usize) < 0x60 && 0x60 + P::Tilde as usize <= 0xff);
    match k {
        TokKind::Ident => 1,
        TokKind::Int => 2,
        TokKind::Float => 3,
        TokKind::Str => 4,
        TokKind::Char => 5,
        TokKind::Newline => 6,
        TokKind::Eof => 7,
        TokKind::Error(e) => 0x10 + e as u8,
        TokKind::Kw(kw) => FIXED_TEXT + kw as u8,
        TokKind::P(p) => 0x60 + p as u8,
    }
}

/// A cache directory; see the module docs.
#[derive(Clone, Debug)]
pub struct Cache {
    dir: PathBuf,
    max_bytes: u64,
    /// Directories this process already made or found (the tag, each
    /// `v4/AB/`): a batch storing 256 entries makes each once instead of
    /// trying it 256 times.
    made: std::sync::Arc<Made>,
}

#[derive(Debug, Default)]
struct Made {
    /// The cache directory did not exist when this `Cache` was made: all
    /// it holds was stored through it (or by processes that trim for
    /// themselves), so it needs no walk to be trimmed until `stored`
    /// passes the bound.
    fresh: bool,
    /// Bytes of entries stored through this `Cache`.
    stored: std::sync::atomic::AtomicU64,
    tagged: std::sync::atomic::AtomicBool,
    /// One bit per first key byte: `v4/AB/` exists.
    fanout: [std::sync::atomic::AtomicU64; 4],
}

impl Made {
    fn has(&self, byte: u8) -> bool {
        self.fanout[usize::from(byte / 64)].load(std::sync::atomic::Ordering::Relaxed) & (1 << (byte % 64)) != 0
    }
    fn set(&self, byte: u8) {
        self.fanout[usize::from(byte / 64)].fetch_or(1 << (byte % 64), std::sync::atomic::Ordering::Relaxed);
    }
}

/// What [`Cache::trim`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trimmed {
    pub entries: usize,
    pub bytes: u64,
    pub removed: usize,
}

impl Cache {
    /// A cache in `dir` (created on the first store) holding at most
    /// `max_bytes` after each [`Cache::trim`].
    pub fn new(dir: impl Into<PathBuf>, max_bytes: u64) -> Cache {
        let dir = dir.into();
        let fresh = std::fs::symlink_metadata(&dir).is_err_and(|e| e.kind() == std::io::ErrorKind::NotFound);
        Cache { dir, max_bytes, made: std::sync::Arc::new(Made { fresh, ..Default::default() }) }
    }

    /// The CLI's default directory: `$UMBRAC_CACHE_DIR`, else
    /// `$XDG_CACHE_HOME/umbrac`, else `$HOME/.cache/umbrac`; `None` if
    /// none of them is set.
    pub fn default_dir() -> Option<PathBuf> {
        let var = |n: &str| std::env::var_os(n).filter(|v| !v.is_empty()).map(PathBuf::from);
        var("UMBRAC_CACHE_DIR")
            .or_else(|| var("XDG_CACHE_HOME").map(|d| d.join("umbrac")))
            .or_else(|| var("HOME").map(|d| d.join(".cache").join("umbrac")))
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    fn path_of(&self, key: &Key) -> PathBuf {
        let hex = key.hex();
        self.dir.join(LAYOUT_DIR).join(&hex[..2]).join(&hex[2..])
    }

    /// The artifacts stored under `key`, if there is a whole, intact entry.
    /// A damaged one is removed.
    pub fn get(&self, key: &Key) -> Option<Vec<Artifact>> {
        self.get_entry(key).map(|e| e.artifacts)
    }

    /// [`Cache::get`], with the hash of each artifact's contents.
    pub fn get_entry(&self, key: &Key) -> Option<Entry> {
        use std::io::Read as _;
        let path = self.path_of(key);
        let mut file = std::fs::File::open(&path).ok()?;
        let meta = file.metadata().ok()?;
        let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
        file.read_to_end(&mut bytes).ok()?;
        drop(file);
        match decode(key, &bytes) {
            Some(entry) => {
                // Used now: the last to be evicted. Best effort, and only
                // when the order could change by more than a minute.
                let now = SystemTime::now();
                if meta.modified().map_or(true, |m| now.duration_since(m).is_ok_and(|age| age > REFRESH_AFTER)) {
                    if let Ok(f) = std::fs::File::options().write(true).open(&path) {
                        let _ = f.set_modified(now);
                    }
                }
                Some(entry)
            }
            None => {
                let _ = std::fs::remove_file(&path);
                None
            }
        }
    }

    /// Stores `artifacts` under `key`, atomically.
    pub fn put(&self, key: &Key, artifacts: &[Artifact]) -> std::io::Result<()> {
        self.put_entry(key, artifacts, &hashes_of(artifacts))
    }

    /// [`Cache::put`] with the hashes of the artifacts' contents already
    /// made ([`hashes_of`]).
    pub fn put_entry(&self, key: &Key, artifacts: &[Artifact], hashes: &[Key]) -> std::io::Result<()> {
        assert_eq!(artifacts.len(), hashes.len(), "one hash per artifact");
        let path = self.path_of(key);
        let parent = path.parent().expect("an entry path has a parent");
        let first = key.0[0];
        if !self.made.has(first) {
            std::fs::create_dir_all(parent)?;
            self.made.set(first);
        }
        self.tag_dir();
        // No fsync: an entry torn by a crash fails its CRC and is recompiled.
        let bytes = encode(key, artifacts, hashes);
        match crate::sealed::write_atomically_in(parent, &path, &bytes) {
            // The directory went away under this process (the cache was
            // deleted): made again, once.
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                std::fs::create_dir_all(parent)?;
                crate::sealed::write_atomically_in(parent, &path, &bytes)
            }
            r => r,
        }?;
        self.made.stored.fetch_add(bytes.len() as u64, std::sync::atomic::Ordering::Relaxed);
        Ok(())
    }

    /// Whether [`Cache::trim`] could remove anything: not while the cache
    /// was new to this `Cache` and holds less than its bound of what was
    /// stored through it (a first compile then walks no directory).
    pub fn may_need_trim(&self) -> bool {
        !self.made.fresh || self.made.stored.load(std::sync::atomic::Ordering::Relaxed) > self.max_bytes
    }

    /// Marks the directory as a cache for backup tools (`CACHEDIR.TAG`),
    /// once per process.
    fn tag_dir(&self) {
        if self.made.tagged.swap(true, std::sync::atomic::Ordering::Relaxed) {
            return;
        }
        let tag = self.dir.join("CACHEDIR.TAG");
        if !tag.exists() {
            let _ = std::fs::write(tag, "Signature: 8a477f597d28d172789f06886806bc55\n# umbrac's compile cache; see docs/build.md.\n");
        }
    }

    /// Removes the entries used longest ago until the cache holds at most
    /// its bound (down to 90 % of it, so the next stores do not trim again
    /// at once), and temporaries older than an hour (left by killed
    /// processes). Safe while other processes use the cache: an entry
    /// removed under a reader is a miss for it.
    pub fn trim(&self) -> Trimmed {
        let mut entries: Vec<(SystemTime, u64, PathBuf)> = Vec::new();
        let hour_ago = SystemTime::now() - Duration::from_secs(3600);
        let layout = self.dir.join(LAYOUT_DIR);
        for sub in read_dir_paths(&layout) {
            for path in read_dir_paths(&sub) {
                let Ok(m) = std::fs::metadata(&path) else { continue };
                if !m.is_file() {
                    continue;
                }
                let modified = m.modified().unwrap_or(SystemTime::UNIX_EPOCH);
                if path.file_name().is_some_and(|n| n.to_string_lossy().starts_with(TEMP_PREFIX)) {
                    if modified < hour_ago {
                        let _ = std::fs::remove_file(&path);
                    }
                    continue;
                }
                entries.push((modified, m.len(), path));
            }
        }
        // Stamps, run records and manifests (`output::stamps`, `rerun`,
        // `direct`) unused for a month: the output directories and
        // commands they describe are likely gone.
        let month_ago = SystemTime::now() - Duration::from_secs(30 * 24 * 3600);
        for sub in ["stamps", "runs", "direct"] {
            for path in read_dir_paths(&self.dir.join(sub)) {
                if std::fs::metadata(&path).and_then(|m| m.modified()).is_ok_and(|t| t < month_ago) {
                    let _ = std::fs::remove_file(&path);
                }
            }
        }
        // What earlier layouts left (`v3/`, `v2/`, its `tmp/`): never read again.
        for old in read_dir_paths(&self.dir) {
            let name = old.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            let earlier_layout = name == "tmp" || (name.len() > 1 && name.starts_with('v') && name[1..].bytes().all(|b| b.is_ascii_digit()) && name != LAYOUT_DIR);
            if earlier_layout && old.is_dir() {
                let _ = std::fs::remove_dir_all(&old);
            }
        }
        let mut total: u64 = entries.iter().map(|e| e.1).sum();
        let mut removed = 0;
        if total > self.max_bytes {
            let target = self.max_bytes / 10 * 9;
            entries.sort();
            for (_, len, path) in &entries {
                if total <= target {
                    break;
                }
                if std::fs::remove_file(path).is_ok() {
                    removed += 1;
                }
                total = total.saturating_sub(*len);
            }
        }
        Trimmed { entries: entries.len() - removed, bytes: total, removed }
    }
}

/// A [`Cache::trim`] running on a thread of its own
/// ([`Cache::trim_in_background`]); dropping it waits for it to end.
#[derive(Debug)]
pub struct Trimming(Option<std::thread::JoinHandle<Trimmed>>);

impl Cache {
    /// Trims on another thread while the caller goes on (writing outputs,
    /// its records): the walk over every entry is then off the run's
    /// critical path. If no thread can be started, trims here.
    pub fn trim_in_background(&self) -> Trimming {
        if !self.may_need_trim() {
            return Trimming(None);
        }
        let c = self.clone();
        match std::thread::Builder::new().name("umbrac-trim".into()).spawn(move || c.trim()) {
            Ok(h) => Trimming(Some(h)),
            Err(_) => {
                self.trim();
                Trimming(None)
            }
        }
    }
}

impl Drop for Trimming {
    fn drop(&mut self) {
        if let Some(h) = self.0.take() {
            let _ = h.join();
        }
    }
}

fn read_dir_paths(dir: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(dir).map(|rd| rd.flatten().map(|e| e.path()).collect()).unwrap_or_default()
}

fn target_tag(t: Option<Target>) -> u8 {
    match t {
        None => 0,
        Some(Target::Glsl330) => 1,
        Some(Target::Gles300) => 2,
        Some(Target::Wgsl) => 3,
        Some(Target::Spirv) => 4,
        Some(Target::Glsl430) => 5,
        Some(Target::Gles310) => 6,
    }
}

fn tag_target(tag: u8) -> Option<Option<Target>> {
    Some(match tag {
        0 => None,
        1 => Some(Target::Glsl330),
        2 => Some(Target::Gles300),
        3 => Some(Target::Wgsl),
        4 => Some(Target::Spirv),
        5 => Some(Target::Glsl430),
        6 => Some(Target::Gles310),
        _ => return None,
    })
}

fn encode(key: &Key, artifacts: &[Artifact], hashes: &[Key]) -> Vec<u8> {
    let size: usize = artifacts.iter().map(|a| 64 + a.file_name.len() + a.entry.as_ref().map_or(0, String::len) + a.contents.len()).sum();
    let mut out = Vec::with_capacity(HEADER_LEN + 4 + size);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&key.0);
    out.extend_from_slice(&[0; 12]); // the body's length and CRC, below
    out.extend_from_slice(&(artifacts.len() as u32).to_le_bytes());
    for (a, hash) in artifacts.iter().zip(hashes) {
        out.push(target_tag(a.target));
        out.extend_from_slice(&(a.file_name.len() as u64).to_le_bytes());
        out.extend_from_slice(a.file_name.as_bytes());
        match &a.entry {
            Some(e) => {
                out.push(1);
                out.extend_from_slice(&(e.len() as u64).to_le_bytes());
                out.extend_from_slice(e.as_bytes());
            }
            None => out.push(0),
        }
        out.extend_from_slice(&hash.0);
        out.extend_from_slice(&(a.contents.len() as u64).to_le_bytes());
        out.extend_from_slice(&a.contents);
    }
    let body_len = (out.len() - HEADER_LEN) as u64;
    let crc = crc32fast::hash(&out[HEADER_LEN..]);
    out[40..48].copy_from_slice(&body_len.to_le_bytes());
    out[48..52].copy_from_slice(&crc.to_le_bytes());
    out
}

/// The entry, or `None` unless every check passes.
fn decode(key: &Key, bytes: &[u8]) -> Option<Entry> {
    let header = bytes.get(..HEADER_LEN)?;
    let body = &bytes[HEADER_LEN..];
    if &header[..8] != MAGIC || header[8..40] != key.0 {
        return None;
    }
    let len = u64::from_le_bytes(header[40..48].try_into().ok()?);
    let crc = u32::from_le_bytes(header[48..52].try_into().ok()?);
    if len != body.len() as u64 || crc32fast::hash(body) != crc {
        return None;
    }
    let mut r = Reader(body);
    let count = u32::from_le_bytes(r.take(4)?.try_into().ok()?);
    let mut artifacts = Vec::with_capacity(count.min(1024) as usize);
    let mut hashes = Vec::with_capacity(count.min(1024) as usize);
    for _ in 0..count {
        let target = tag_target(r.take(1)?[0])?;
        let file_name = String::from_utf8(r.field()?.to_vec()).ok()?;
        let entry = match r.take(1)?[0] {
            0 => None,
            1 => Some(String::from_utf8(r.field()?.to_vec()).ok()?),
            _ => return None,
        };
        let hash = Key(r.take(32)?.try_into().ok()?);
        let contents = r.field()?;
        artifacts.push(Artifact { file_name, target, entry, contents: contents.to_vec() });
        hashes.push(hash);
    }
    r.is_empty().then_some(Entry { artifacts, hashes })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn art(name: &str, text: &str) -> Artifact {
        Artifact { file_name: name.into(), target: Some(Target::Wgsl), entry: Some("main_fs".into()), contents: text.as_bytes().to_vec() }
    }

    fn key(n: u8) -> Key {
        Key([n; 32])
    }

    #[test]
    fn hashes_are_blake3() {
        // `variants.json` names the algorithm (`blake3:`): its values must
        // be BLAKE3's, on every machine (the reference's test vectors).
        assert_eq!(Key::of_bytes(b"").hex(), "af1349b9f5f9a1a6a0404dea36dcc9499bcb25c9adc112b7cc9a93cae41f3262");
        assert_eq!(Key::of_bytes(b"abc").hex(), "6437b3ac38465133ffb63b75273a8db548c558465d79db03fd359c6cd5bd9d85");
    }

    #[test]
    fn keys_follow_every_files_tokens_and_not_their_comments() {
        // Tokens from two files (an include and the file around it): the
        // key sees each one's text wherever it lies.
        let d = tempfile::tempdir().unwrap();
        let key_with = |inc: &str, main: &str| {
            std::fs::write(d.path().join("inc.das"), inc).unwrap();
            std::fs::write(d.path().join("main.das"), main).unwrap();
            let opts = Options::default();
            let pre = crate::preprocess_file(&d.path().join("main.das"), &opts);
            assert!(!pre.has_errors());
            Key::of(&pre, &opts, "")
        };
        let main = "var a = 1\n#include \"inc.das\"\nvar c = 3\n";
        let k = key_with("var b = 2\n", main);
        assert_eq!(k, key_with("// a comment\nvar  b = 2 // another\n", main), "comments and spaces are no tokens");
        assert_ne!(k, key_with("var b = 5\n", main), "a token of the include changed");
        assert_ne!(k, key_with("var b = 2\n", &main.replace('3', "4")), "a token after the include changed");
        assert_ne!(k, key_with("var b = 2\n", &main.replace("var a", "var x")), "the file's first token changed");
    }

    #[test]
    fn stores_and_reads_back() {
        let d = tempfile::tempdir().unwrap();
        let c = Cache::new(d.path(), DEFAULT_MAX_BYTES);
        assert!(c.get(&key(1)).is_none());
        let arts = [art("a.wgsl", "fn main() {}"), Artifact { file_name: "a.reflect.json".into(), target: None, entry: None, contents: b"{}".to_vec() }];
        c.put(&key(1), &arts).unwrap();
        let back = c.get(&key(1)).unwrap();
        assert_eq!(back.len(), 2);
        assert_eq!((back[0].file_name.as_str(), back[0].target, back[0].entry.as_deref()), ("a.wgsl", Some(Target::Wgsl), Some("main_fs")));
        assert_eq!(back[1].contents, b"{}");
        assert!(d.path().join("CACHEDIR.TAG").is_file());
        assert!(c.get(&key(2)).is_none());
    }

    #[test]
    fn a_cache_deleted_while_in_use_is_made_again() {
        // Each `v4/AB/` is made once per process; the cache's directory
        // going away must not make later stores fail.
        let d = tempfile::tempdir().unwrap();
        let dir = d.path().join("cache");
        let c = Cache::new(&dir, DEFAULT_MAX_BYTES);
        c.put(&key(1), &[art("a.wgsl", "1")]).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        c.put(&key(1), &[art("a.wgsl", "2")]).unwrap();
        let mut other = [7u8; 32];
        other[0] = 1;
        c.put(&Key(other), &[art("b.wgsl", "3")]).unwrap();
        assert_eq!(c.get(&Key(other)).unwrap()[0].contents, b"3");
        assert_eq!(c.get(&key(1)).unwrap()[0].contents, b"2");
    }

    #[test]
    fn every_truncation_and_every_flipped_byte_is_a_miss_and_removed() {
        let d = tempfile::tempdir().unwrap();
        let c = Cache::new(d.path(), DEFAULT_MAX_BYTES);
        c.put(&key(7), &[art("x.wgsl", "some shader text")]).unwrap();
        let path = c.path_of(&key(7));
        let good = std::fs::read(&path).unwrap();
        for cut in 0..good.len() {
            std::fs::write(&path, &good[..cut]).unwrap();
            assert!(c.get(&key(7)).is_none(), "truncated to {cut} bytes");
            assert!(!path.exists(), "a damaged entry is removed");
        }
        for i in 0..good.len() {
            let mut bad = good.clone();
            bad[i] ^= 0x20;
            std::fs::write(&path, &bad).unwrap();
            assert!(c.get(&key(7)).is_none(), "byte {i} flipped");
        }
        // An entry copied under another key's name is not served either.
        std::fs::create_dir_all(c.path_of(&key(8)).parent().unwrap()).unwrap();
        std::fs::write(c.path_of(&key(8)), &good).unwrap();
        assert!(c.get(&key(8)).is_none());
        std::fs::write(&path, &good).unwrap();
        assert_eq!(c.get(&key(7)).unwrap()[0].text(), "some shader text");
    }

    #[test]
    fn trim_removes_the_least_recently_used_first() {
        let d = tempfile::tempdir().unwrap();
        let big = "x".repeat(10_000);
        let c = Cache::new(d.path(), 35_000);
        for n in 0..5u8 {
            c.put(&key(n), &[art("a", &big)]).unwrap();
            let t = SystemTime::now() - Duration::from_secs(100 - n as u64 * 10);
            std::fs::File::options().write(true).open(c.path_of(&key(n))).unwrap().set_modified(t).unwrap();
        }
        // Reading entry 0 makes it the most recently used.
        assert!(c.get(&key(0)).is_some());
        let t = c.trim();
        // Five entries of ~10 kB over a 35 kB bound: down to 90 % of it.
        assert_eq!((t.removed, t.entries), (2, 3), "{t:?}");
        assert!(t.bytes <= 31_500);
        let left: Vec<u8> = (0..5).filter(|&n| c.path_of(&key(n)).exists()).collect();
        assert_eq!(left, [0, 3, 4], "the oldest, 1 and 2, go first");
    }

    #[test]
    fn a_new_cache_needs_no_trim_until_its_stores_pass_the_bound() {
        let d = tempfile::tempdir().unwrap();
        let c = Cache::new(d.path().join("new"), 25_000);
        c.put(&key(1), &[art("a", &"x".repeat(10_000))]).unwrap();
        assert!(!c.may_need_trim(), "all it holds was stored through it, under the bound");
        c.put(&key(2), &[art("a", &"y".repeat(10_000))]).unwrap();
        c.put(&key(3), &[art("a", &"z".repeat(10_000))]).unwrap();
        assert!(c.may_need_trim(), "stored past the bound");
        // One that existed may hold anything: always walked.
        assert!(Cache::new(d.path().join("new"), 25_000).may_need_trim());
    }

    #[test]
    fn threads_storing_and_reading_one_key_never_see_a_partial_entry() {
        let d = tempfile::tempdir().unwrap();
        let c = Cache::new(d.path(), DEFAULT_MAX_BYTES);
        let text = "y".repeat(200_000);
        std::thread::scope(|s| {
            for _ in 0..4 {
                s.spawn(|| {
                    for _ in 0..20 {
                        c.put(&key(3), &[art("b", &text)]).unwrap();
                        if let Some(a) = c.get(&key(3)) {
                            assert_eq!(a[0].contents.len(), text.len());
                        }
                    }
                });
            }
        });
        assert!(read_dir_paths(c.path_of(&key(3)).parent().unwrap()).iter().all(|p| !p.file_name().unwrap().to_string_lossy().starts_with(".tmp-")), "no temporaries left");
    }
}
