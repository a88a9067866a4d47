//! Many files at once: which files under a directory are programs, and
//! compiling many of them on a bounded pool of compiler threads. The CLI,
//! [`crate::build`] and the golden tests all go through here, so they agree
//! on both.

use std::collections::HashSet;
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use crate::cache::{Cache, Key};
use crate::{Artifact, Compilation, Diagnostic, Options, Preprocessed, SourceMap};

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
                Ok(m) if m.is_dir() && name != "include" => pending.push(path),
                Ok(m) if m.is_dir() => {}
                Ok(m) if m.is_file() && is_das => found.push(path),
                Ok(m) if m.is_file() => {}
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

/// Runs `f(0)` ... `f(count - 1)` on at most `workers` compiler threads
/// ([`crate::spawn_compiler_thread`]) and returns the results in order. A
/// panic in one call becomes `on_panic(i, message)` for it and does not
/// stop the others; if no thread can be started, the calls left run on
/// the calling thread.
pub fn parallel_map<T: Send>(count: usize, workers: usize, f: impl Fn(usize) -> T + Sync, on_panic: impl Fn(usize, String) -> T + Sync) -> Vec<T> {
    let call = |i: usize| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| f(i))).unwrap_or_else(|payload| on_panic(i, crate::diag::panic_message(&*payload)))
    };
    let results: Vec<Mutex<Option<T>>> = (0..count).map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let run_next = || loop {
        let i = next.fetch_add(1, Ordering::Relaxed);
        if i >= count {
            break;
        }
        let r = call(i);
        if let Ok(mut slot) = results[i].lock() {
            *slot = Some(r);
        }
    };
    let workers = workers.clamp(1, count.max(1));
    std::thread::scope(|s| {
        for _ in 0..workers {
            if crate::spawn_compiler_thread(s, run_next).is_err() {
                break;
            }
        }
    });
    results.into_iter().enumerate().map(|(i, slot)| slot.into_inner().ok().flatten().unwrap_or_else(|| call(i))).collect()
}

// ---- Batches with a cache -------------------------------------------------

/// One compilation of a cached batch ([`compile_cached`]).
#[derive(Clone, Debug)]
pub struct Unit<'a> {
    pub path: &'a Path,
    pub opts: Options,
    /// What else the outputs depend on, for the cache key: a caller that
    /// adds outputs of its own through `derive` names their options here.
    pub extra: String,
}

/// Where a unit's outputs came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    /// Compiled in this batch (or failed).
    Compiled,
    /// Read from the cache: nothing was parsed.
    Cached,
    /// Preprocessed to the same key as the earlier unit with this index,
    /// whose outputs (or failure) it shares.
    SameAs(usize),
}

/// What one unit produced.
#[derive(Debug)]
pub struct Outcome {
    /// The outputs (with the `derive`d ones), if it compiled without errors.
    pub artifacts: Option<Vec<Artifact>>,
    /// The hash of each artifact's contents, in order (empty without
    /// artifacts, and when nothing needs them: see [`compile_cached`]):
    /// from the cache entry on a hit, made beside the compile otherwise.
    pub hashes: Vec<Key>,
    /// The compilation of a unit compiled here that failed or said
    /// something (warnings), or the failed preprocessing (or panic) of any
    /// unit: its diagnostics and sources. `None` for a unit compiled
    /// without any diagnostic (its outputs are in `artifacts`), a cache
    /// hit and a unit that shares another's outputs.
    pub compilation: Option<Compilation>,
    /// Every file read, includes too (for depfiles and `rerun-if-changed`).
    pub files_read: Vec<PathBuf>,
    /// Where `#include`s and `require`s found no file
    /// ([`crate::syntax::Unit::probed`]).
    pub probed: Vec<PathBuf>,
    pub origin: Origin,
    pub key: Option<Key>,
}

impl Outcome {
    /// Whether the unit failed; a [`Origin::SameAs`] unit fails when its
    /// original does (look that one's diagnostics up).
    pub fn failed(&self) -> bool {
        self.artifacts.is_none()
    }
}

/// Counts of a cached batch.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub compiled: usize,
    pub cached: usize,
    pub shared: usize,
    /// Entries written to the cache.
    pub stored: usize,
    /// The first error writing the cache (the batch goes on without it).
    pub store_error: Option<String>,
    /// Every file the batch read, with the hash of the bytes it read, where
    /// the cache's manifest ([`crate::cache::direct`]) has them (else
    /// empty): a run record need not read and hash them again.
    pub read_hashes: Vec<(PathBuf, Key)>,
}

/// Outputs a caller adds to a unit's compiled outputs, cached with them
/// (`umbrac::build`'s bindings module): `derive(unit index, compiled)`.
pub type Derive<'a> = dyn Fn(usize, &crate::Compiled) -> Result<Vec<Artifact>, String> + Sync + 'a;

/// Called as soon as a unit's outputs are ready (it compiled without a
/// diagnostic, or was a cache hit), with the unit's index: the CLI writes
/// them to a stage while other units compile (`output::staged`). A hit is
/// reported by the worker that looked it up; a compiled unit by its worker
/// with one worker, and by [`compile_cached`]'s file thread with more. A
/// unit that shares another's compile (same key) is not reported, unless
/// it was a hit. A panic in it fails that unit.
pub type Ready<'a> = dyn Fn(usize, &[Artifact]) + Sync + 'a;

/// What a caller adds to [`compile_cached`]'s work.
#[derive(Clone, Copy, Default)]
pub struct Hooks<'a> {
    pub derive: Option<&'a Derive<'a>>,
    pub ready: Option<&'a Ready<'a>>,
    /// Hash every output ([`Outcome::hashes`]) even without a cache
    /// (`variants.json` records them). With a cache they are always made:
    /// its entries hold them.
    pub output_hashes: bool,
    /// The process ends right after the batch (the CLI but `--watch`): a
    /// batch of one unit leaves its compile tree to the exit instead of
    /// freeing it piece by piece (110 k instructions of a first compile).
    /// With more units each tree is freed, so the next reuses its memory:
    /// leaking 256 made the cold run's CPU time 1.1x (page faults).
    pub process_ends: bool,
}

/// Compiles every unit on at most `workers` threads, with a cache: each
/// unit is preprocessed (in parallel) and keyed ([`Key::of`]); units with
/// the same key are compiled once; a key found in `cache` is not compiled
/// at all; what was compiled without any diagnostic is stored. Results come
/// back in the units' order. A panic anywhere is an internal-error
/// diagnostic of that unit only. Nothing is hashed that nothing uses: a
/// single unit without a cache has no key, and outputs are hashed only
/// for a cache or [`Hooks::output_hashes`].
pub fn compile_cached(units: &[Unit<'_>], workers: usize, cache: Option<&Cache>, hooks: Hooks<'_>) -> (Vec<Outcome>, Stats) {
    let Hooks { derive, ready, output_hashes, process_ends } = hooks;
    // A key finds the cache entry, and units that share one compile.
    let keyed = cache.is_some() || units.len() > 1;
    let hash_outputs = cache.is_some() || output_hashes;
    // With a cache, what the last batch of these units read and keyed
    // them to ([`crate::cache::direct`]): if it still holds, their entries
    // are found without preprocessing; if not, it is recorded afresh.
    let direct = cache.map(|c| {
        let batch_key = crate::cache::direct::batch_key(units.iter().map(|u| (u.path, format!("{:?}", u.opts), u.extra.as_str())));
        let held = crate::cache::direct::Manifest::load(c, &batch_key, units.len());
        let recorder = held.is_none().then(crate::cache::direct::Recorder::default);
        (c, batch_key, held, recorder)
    });
    enum Pre {
        Failed(Box<Compilation>),
        Hit(crate::cache::Entry),
        Miss(Box<Preprocessed>),
    }
    let first = parallel_map(
        units.len(),
        workers,
        |i| {
            let u = &units[i];
            if let Some((c, _, Some(held), _)) = &direct {
                let unit = &held.units[i];
                if let Some(entry) = c.get_entry(&unit.key) {
                    if let Some(r) = ready {
                        r(i, &entry.artifacts);
                    }
                    return (Pre::Hit(entry), (unit.files_read.clone(), unit.probed.clone()), Some(unit.key));
                }
            }
            let pre = crate::preprocess_file(u.path, &u.opts);
            let read = (pre.files_read(), pre.probed().to_vec());
            let recorder = direct.as_ref().and_then(|d| d.3.as_ref());
            if pre.has_errors() {
                if let Some(r) = recorder {
                    r.spoil();
                }
                return (Pre::Failed(Box::new(pre.compile(&u.opts))), read, None);
            }
            let key = keyed.then(|| Key::of(&pre, &u.opts, &u.extra));
            if let (Some(r), Some(key)) = (recorder, key) {
                r.unit(i, key, &pre);
            }
            match cache.zip(key.as_ref()).and_then(|(c, key)| c.get_entry(key)) {
                Some(entry) => {
                    if let Some(r) = ready {
                        r(i, &entry.artifacts);
                    }
                    (Pre::Hit(entry), read, key)
                }
                None => (Pre::Miss(Box::new(pre)), read, key),
            }
        },
        |i, msg| (Pre::Failed(Box::new(panicked_in(units[i].path, &msg))), Default::default(), None),
    );
    // The files read, hashed once: for the caller's run record too.
    let mut read_hashes = Vec::new();
    match direct {
        Some((_, _, Some(held), _)) => read_hashes = held.files,
        Some((c, batch_key, None, Some(recorder))) => {
            if let Some(m) = recorder.finish(units.len()) {
                m.save(c, &batch_key);
                read_hashes = m.files().to_vec();
            }
        }
        _ => {}
    }

    // Each key's first unit is compiled (or was a hit); later ones share it.
    let mut first_of: std::collections::HashMap<Key, usize> = Default::default();
    let mut outcomes: Vec<Option<Outcome>> = Vec::with_capacity(units.len());
    let mut to_compile: Vec<(usize, Box<Preprocessed>)> = Vec::new();
    let mut stats = Stats { read_hashes, ..Default::default() };
    for (i, (pre, (files_read, probed), key)) in first.into_iter().enumerate() {
        if let Some(&j) = key.as_ref().and_then(|k| first_of.get(k)) {
            stats.shared += 1;
            outcomes.push(Some(Outcome { artifacts: None, hashes: Vec::new(), compilation: None, files_read, probed, origin: Origin::SameAs(j), key }));
            continue;
        }
        if let Some(k) = key {
            first_of.insert(k, i);
        }
        outcomes.push(Some(match pre {
            Pre::Failed(c) => Outcome { artifacts: None, hashes: Vec::new(), compilation: Some(*c), files_read, probed, origin: Origin::Compiled, key },
            Pre::Hit(entry) => {
                stats.cached += 1;
                Outcome { artifacts: Some(entry.artifacts), hashes: entry.hashes, compilation: None, files_read, probed, origin: Origin::Cached, key }
            }
            Pre::Miss(pre) => {
                to_compile.push((i, pre));
                Outcome { artifacts: None, hashes: Vec::new(), compilation: None, files_read, probed, origin: Origin::Compiled, key }
            }
        }));
    }

    let (indices, pres): (Vec<usize>, Vec<Box<Preprocessed>>) = to_compile.into_iter().unzip();
    let pres: Vec<Mutex<Option<Box<Preprocessed>>>> = pres.into_iter().map(|p| Mutex::new(Some(p))).collect();
    let keys: Vec<Option<Key>> = indices.iter().map(|&i| outcome_key(&outcomes[i])).collect();
    // What the file system does with the outputs of a unit that compiled
    // without a diagnostic: the `ready` hook and its cache entry. A compile
    // that said something is not stored (a hit must not hide a diagnostic).
    let file_work = |n: usize, arts: &[Artifact], hashes: &[Key]| -> Option<Result<(), String>> {
        if let Some(r) = ready {
            r(indices[n], arts);
        }
        match (cache, &keys[n]) {
            (Some(cache), Some(key)) => Some(cache.put_entry(key, arts, hashes).map_err(|e| format!("cannot write to the cache in `{}`: {e}", cache.dir().display()))),
            _ => None,
        }
    };
    let wants_files = ready.is_some() || cache.is_some();
    // With more than one worker that work is done on one thread of its
    // own while the workers go on compiling: file creation does not scale
    // across threads (it takes locks the kernel shares), and from two
    // threads at once it took longer in all than from one
    // (docs/performance.md, "Compiling at scale").
    let handed: Vec<Mutex<Option<Handed>>> = (0..indices.len()).map(|_| Mutex::new(None)).collect();
    let compiled = std::thread::scope(|s| {
        let (tx, rx) = std::sync::mpsc::channel::<(usize, Vec<Artifact>, Vec<Key>)>();
        let file_thread = (workers > 1 && wants_files)
            .then(|| {
                std::thread::Builder::new()
                    .name("umbrac-files".into())
                    .spawn_scoped(s, || {
                        for (n, arts, hashes) in rx {
                            let done = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| file_work(n, &arts, &hashes)));
                            let result = match done {
                                Ok(stored) => Handed::Done(arts, hashes, stored),
                                Err(payload) => Handed::Panicked(crate::diag::panic_message(&*payload)),
                            };
                            if let Ok(mut slot) = handed[n].lock() {
                                *slot = Some(result);
                            }
                        }
                    })
                    .ok()
            })
            .flatten();
        let tx = file_thread.is_some().then_some(tx);
        let compiled = parallel_map(
            indices.len(),
            workers,
            |n| {
                let i = indices[n];
                let u = &units[i];
                let pre = pres[n].lock().ok().and_then(|mut p| p.take()).expect("each unit is compiled once");
                let mut c = pre.compile(&u.opts);
                let mut artifacts = None;
                if !c.has_errors() {
                    if let Some(result) = c.result.as_mut() {
                        // The derived outputs see the compiled outputs, then
                        // they move out (no copy).
                        let derived = derive.map(|d| d(i, result));
                        let mut arts = std::mem::take(&mut result.artifacts);
                        match derived {
                            None => artifacts = Some(arts),
                            Some(Ok(more)) => {
                                arts.extend(more);
                                artifacts = Some(arts);
                            }
                            Some(Err(msg)) => c.diagnostics.push(Diagnostic::error_nowhere(format!("{}: {msg}", u.path.display()))),
                        }
                    }
                }
                let hashes = artifacts.as_deref().filter(|_| hash_outputs).map(crate::cache::hashes_of).unwrap_or_default();
                // A compile that said nothing has nothing more to report: its
                // tree (the lowered modules) is freed here, on this worker,
                // not all at once at the end of the batch.
                let clean = artifacts.is_some() && c.diagnostics.is_empty();
                let c = match clean {
                    true if process_ends && units.len() == 1 => {
                        std::mem::forget(c);
                        None
                    }
                    true => None,
                    false => Some(c),
                };
                let Some(arts) = artifacts else { return (c, None, hashes, None) };
                if !clean || !wants_files {
                    return (c, Some(arts), hashes, None);
                }
                let arts = match &tx {
                    Some(tx) => match tx.send((n, arts, hashes.clone())) {
                        Ok(()) => return (c, None, hashes, None),
                        // The file thread is gone (short of a bug it cannot
                        // be): the work is done here.
                        Err(std::sync::mpsc::SendError((_, arts, _))) => arts,
                    },
                    None => arts,
                };
                let stored = file_work(n, &arts, &hashes);
                (c, Some(arts), hashes, stored)
            },
            |n, msg| (Some(panicked_in(units[indices[n]].path, &msg)), None, Vec::new(), None),
        );
        drop(tx);
        compiled
    });
    for (n, (i, (mut c, mut artifacts, mut hashes, mut stored))) in indices.into_iter().zip(compiled).enumerate() {
        match handed[n].lock().ok().and_then(|mut h| h.take()) {
            Some(Handed::Done(arts, h, s)) => {
                artifacts = Some(arts);
                hashes = h;
                stored = s;
            }
            Some(Handed::Panicked(msg)) => {
                c = Some(panicked_in(units[i].path, &msg));
                artifacts = None;
                hashes = Vec::new();
            }
            None => {}
        }
        stats.compiled += 1;
        match stored {
            Some(Ok(())) => stats.stored += 1,
            Some(Err(e)) => {
                stats.store_error.get_or_insert(e);
            }
            None => {}
        }
        if let Some(o) = outcomes[i].as_mut() {
            o.artifacts = artifacts;
            o.hashes = hashes;
            o.compilation = c;
        }
    }
    let mut outcomes: Vec<Outcome> = outcomes.into_iter().map(|o| o.expect("every unit has an outcome")).collect();
    for i in 0..outcomes.len() {
        if let Origin::SameAs(j) = outcomes[i].origin {
            outcomes[i].artifacts = outcomes[j].artifacts.clone();
            outcomes[i].hashes = outcomes[j].hashes.clone();
        }
    }
    (outcomes, stats)
}

/// What the file thread of [`compile_cached`] did with a unit's outputs.
enum Handed {
    /// The outputs and their hashes, back, and the cache entry's fate.
    Done(Vec<Artifact>, Vec<Key>, Option<Result<(), String>>),
    Panicked(String),
}

fn outcome_key(o: &Option<Outcome>) -> Option<Key> {
    o.as_ref().and_then(|o| o.key)
}

fn panicked_in(path: &Path, msg: &str) -> Compilation {
    let msg = format!("the compiler panicked while compiling `{}`: {msg}", path.display());
    Compilation { sources: SourceMap::new(), diagnostics: vec![Diagnostic::bug(msg, None)], suppressed_errors: 0, result: None }
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

    /// A fragment program writing `float4(V)`, in `dir`.
    fn program_of_v(dir: &Path) -> PathBuf {
        let prog = dir.join("p.das");
        std::fs::write(&prog, "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(V)\n}\n").unwrap();
        prog
    }

    /// One WGSL unit of `prog` per value of `V`.
    fn units_with_v<'a>(prog: &'a Path, values: &[&str]) -> Vec<Unit<'a>> {
        let with = |v: &str| Options { defines: vec![("V".into(), Some(v.into()))], targets: vec![crate::Target::Wgsl], ..Options::default() };
        values.iter().map(|v| Unit { path: prog, opts: with(v), extra: String::new() }).collect()
    }

    #[test]
    fn a_cached_batch_compiles_each_key_once_and_a_panic_fails_only_its_unit() {
        let t = tempfile::tempdir().unwrap();
        let prog = program_of_v(t.path());
        let units = units_with_v(&prog, &["1.0", "2.0", "1.0", "3.0"]);
        let cache = Cache::new(t.path().join("cache"), crate::cache::DEFAULT_MAX_BYTES);
        // The unit compiled for "3.0" panics in the caller's hook.
        let derive = |i: usize, _: &crate::Compiled| -> Result<Vec<Artifact>, String> {
            if i == 3 {
                panic!("hook blew up");
            }
            Ok(vec![])
        };
        for workers in [1, 3] {
            let (out, stats) = compile_cached(&units, workers, Some(&cache), Hooks { derive: Some(&derive), ready: None, output_hashes: false, process_ends: false });
            assert_eq!(out[2].origin, Origin::SameAs(0));
            assert!(!out[0].failed() && !out[1].failed() && !out[2].failed());
            assert!(out[3].failed());
            let c = out[3].compilation.as_ref().unwrap();
            assert_eq!(c.diagnostics[0].severity, crate::Severity::Bug);
            assert!(c.diagnostics[0].message.contains("panicked") && c.diagnostics[0].message.contains("hook blew up"), "{:?}", c.diagnostics);
            if workers == 1 {
                assert_eq!((stats.compiled, stats.cached, stats.shared, stats.stored), (3, 0, 1, 2));
            } else {
                assert_eq!((stats.compiled, stats.cached, stats.shared), (1, 2, 1), "a hit for 1.0 and 2.0, 3.0 compiled again");
            }
        }
    }

    #[test]
    fn outputs_are_reported_ready_once_each_on_any_number_of_workers_and_a_panic_there_fails_only_its_unit() {
        let t = tempfile::tempdir().unwrap();
        let prog = program_of_v(t.path());
        let values = ["1.0", "2.0", "1.0", "3.0", "4.0", "5.0"];
        let units = units_with_v(&prog, &values);
        let run = |workers: usize, cache: &Cache, panics: bool| {
            let seen = Mutex::new(Vec::new());
            let ready = |i: usize, arts: &[Artifact]| {
                seen.lock().unwrap().push((i, arts.len()));
                if panics && values[i] == "4.0" {
                    panic!("ready blew up");
                }
            };
            let (out, stats) = compile_cached(&units, workers, Some(cache), Hooks { derive: None, ready: Some(&ready), output_hashes: false, process_ends: false });
            let mut seen: Vec<usize> = seen.into_inner().unwrap().into_iter().map(|(i, n)| {
                assert_eq!(n, 2, "the WGSL and the manifest");
                i
            }).collect();
            seen.sort();
            (out, stats, seen)
        };
        // 1 worker: on the worker; more: on the file thread.
        for workers in [1, 2, 4] {
            let cache = Cache::new(t.path().join(format!("cache{workers}")), crate::cache::DEFAULT_MAX_BYTES);
            let (out, stats, seen) = run(workers, &cache, true);
            // Unit 2 shares unit 0's compile: not reported.
            assert_eq!(seen, [0, 1, 3, 4, 5], "workers {workers}");
            assert!(out[4].failed(), "workers {workers}");
            assert!(out[4].compilation.as_ref().unwrap().diagnostics[0].message.contains("ready blew up"));
            for i in [0, 1, 2, 3, 5] {
                assert!(!out[i].failed(), "unit {i}, workers {workers}");
                assert_eq!(out[i].artifacts.as_ref().unwrap().len(), out[i].hashes.len());
            }
            assert_eq!(stats.stored, 4, "every clean unit but the one whose hook panicked");
        }
        // Again with the 2-worker cache: the hits are reported as they are
        // looked up (unit 2 too), and 4.0, never stored, is compiled.
        let cache = Cache::new(t.path().join("cache2"), crate::cache::DEFAULT_MAX_BYTES);
        let (out, stats, seen) = run(2, &cache, false);
        assert_eq!(seen, [0, 1, 2, 3, 4, 5]);
        assert_eq!((stats.cached, stats.compiled, stats.stored), (4, 1, 1));
        assert!(out.iter().all(|o| !o.failed()));
    }

    #[test]
    fn an_unreadable_unit_is_a_located_error_not_a_panic() {
        let missing = Path::new("/nonexistent/missing.das");
        let (out, _) = compile_cached(&[Unit { path: missing, opts: Options::default(), extra: String::new() }], 2, None, Hooks::default());
        let c = out[0].compilation.as_ref().unwrap();
        assert_eq!(c.diagnostics.len(), 1);
        assert_eq!(c.diagnostics[0].severity, crate::Severity::Error, "{:?}", c.diagnostics);
        assert!(c.diagnostics[0].message.contains("cannot read `/nonexistent/missing.das`"), "{:?}", c.diagnostics);
    }
}
