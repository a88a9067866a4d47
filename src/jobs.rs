//! One run of the compiler over many inputs and variants: what `umbrac
//! compile` and [`crate::build`] do between reading their arguments and
//! writing. Every input is compiled once per variant through
//! [`crate::batch::compile_cached`] (in parallel, deduplicated by
//! preprocessed text, through the cache); [`Batch`] then says where each
//! job's outputs go and writes `variants.json`.
//!
//! Determinism: what an output records of its input ([`Input::source_name`])
//! is the file's name for a file given by itself, and its path relative to
//! the directory for a file found under a directory argument, with `/`
//! separators: never the working directory or an absolute path. Nothing
//! else in any output depends on the order jobs finish in, the number of
//! workers, the machine or the time.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::batch::{self, Outcome, Stats, Unit};
use crate::cache::Cache;
use crate::variants::{describe, Variant};
use crate::{Artifact, Compilation, Diagnostic, Options};

/// An input file of a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// The path as given (or as found under a directory given): what
    /// diagnostics show.
    pub path: PathBuf,
    /// Where its outputs go, relative to the output directory (a file found
    /// under a directory argument keeps its subdirectory).
    pub subdir: PathBuf,
    /// What its outputs record (the manifest's `source`): see the module docs.
    pub source_name: String,
}

/// The inputs named by command-line arguments: each FILE, and the programs
/// under each DIR ([`batch::programs_under`]).
pub fn inputs_of(args: &[PathBuf]) -> Result<Vec<Input>, String> {
    let mut out = Vec::new();
    for arg in args {
        if !arg.is_dir() {
            let name = arg.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| arg.display().to_string());
            out.push(Input { path: arg.clone(), subdir: PathBuf::new(), source_name: name });
            continue;
        }
        let found = batch::programs_under(arg).map_err(|e| e.to_string())?;
        if found.is_empty() {
            return Err(format!("no `.das` files under `{}`", arg.display()));
        }
        for f in found {
            let file = f.path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            let mut parts: Vec<String> = f.subdir.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
            parts.push(file);
            out.push(Input { path: f.path, subdir: f.subdir, source_name: parts.join("/") });
        }
    }
    Ok(out)
}

/// One compilation of a run: an input with a variant's defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Job {
    pub input: usize,
    /// Index into [`Batch::variants`]; `None` in a run without variants.
    pub variant: Option<usize>,
}

/// A compiled run.
#[derive(Debug)]
pub struct Batch {
    pub inputs: Vec<Input>,
    /// The variants (empty: a run without `--variants`).
    pub variants: Vec<Variant>,
    pub jobs: Vec<Job>,
    /// Indexed like `jobs`.
    pub outcomes: Vec<Outcome>,
    pub stats: Stats,
}

/// How to run: the options every job shares, and the pool and cache.
#[derive(Clone, Debug)]
pub struct Settings<'a> {
    pub options: &'a Options,
    pub workers: usize,
    pub cache: Option<&'a Cache>,
    /// See [`batch::Hooks::process_ends`].
    pub process_ends: bool,
}

impl Batch {
    /// Compiles every input with every variant (or once each, with none).
    /// `ready(job, dir, outputs)` is called as soon as a job's outputs are
    /// ready, `dir` being where they go relative to the output directory
    /// ([`Batch::out_dir`]); which jobs are reported, and on which thread,
    /// is [`batch::Ready`]'s rule.
    pub fn compile(inputs: Vec<Input>, variants: Vec<Variant>, settings: &Settings<'_>, ready: Option<&Ready<'_>>) -> Batch {
        let mut jobs = Vec::new();
        for input in 0..inputs.len() {
            if variants.is_empty() {
                jobs.push(Job { input, variant: None });
            } else {
                jobs.extend((0..variants.len()).map(|v| Job { input, variant: Some(v) }));
            }
        }
        let units: Vec<Unit> = jobs
            .iter()
            .map(|j| {
                let input = &inputs[j.input];
                let mut opts = settings.options.clone();
                if let Some(v) = j.variant {
                    opts.defines.extend(variants[v].defines.iter().cloned());
                }
                opts.source_name = Some(input.source_name.clone());
                Unit { path: &input.path, opts, extra: String::new() }
            })
            .collect();
        let rel_dirs: Vec<PathBuf> = match ready {
            Some(_) => jobs.iter().map(|j| rel_dir(j, &inputs, &variants)).collect(),
            None => Vec::new(),
        };
        let report = |j: usize, arts: &[Artifact]| {
            if let Some(r) = ready {
                r(j, &rel_dirs[j], arts);
            }
        };
        let hooks = batch::Hooks { derive: None, ready: ready.is_some().then_some(&report as &batch::Ready), output_hashes: !variants.is_empty(), process_ends: settings.process_ends };
        let (outcomes, stats) = batch::compile_cached(&units, settings.workers, settings.cache, hooks);
        drop(units);
        Batch { inputs, variants, jobs, outcomes, stats }
    }

    /// Whether every job compiled.
    pub fn succeeded(&self) -> bool {
        self.outcomes.iter().all(|o| !o.failed())
    }

    /// The directory of job `j`'s outputs under `root`:
    /// `root/VARIANT/SUBDIR`.
    pub fn out_dir(&self, j: usize, root: &Path) -> PathBuf {
        let rel = rel_dir(&self.jobs[j], &self.inputs, &self.variants);
        if rel.as_os_str().is_empty() {
            root.to_path_buf()
        } else {
            root.join(rel)
        }
    }

    /// A failed job's diagnostics, once per distinct failure: jobs that
    /// failed with the same rendered text (variants whose preprocessed
    /// source is identical, or that hit the same error) are one group. In
    /// a run with variants each diagnostic gets a note naming them.
    pub fn failures(&self) -> Vec<Failure<'_>> {
        let mut groups: Vec<Failure> = Vec::new();
        let mut by_text: BTreeMap<String, usize> = BTreeMap::new();
        for (j, o) in self.outcomes.iter().enumerate() {
            if !o.failed() {
                continue;
            }
            let original = match o.origin {
                batch::Origin::SameAs(k) => k,
                _ => j,
            };
            let Some(c) = self.outcomes[original].compilation.as_ref() else { continue };
            let text = c.render_diagnostics();
            let at = *by_text.entry(text).or_insert_with(|| {
                groups.push(Failure { compilation: c, jobs: Vec::new() });
                groups.len() - 1
            });
            groups[at].jobs.push(j);
        }
        groups
    }

    /// The diagnostics of a failure, with a note naming the variants it
    /// belongs to (in a run with variants).
    pub fn diagnostics_of(&self, f: &Failure<'_>) -> Vec<Diagnostic> {
        let mut ds = f.compilation.diagnostics.clone();
        if ds.is_empty() {
            ds.push(Diagnostic::bug("compilation failed without a diagnostic", None));
        }
        if self.variants.is_empty() {
            return ds;
        }
        let names: Vec<String> = f.jobs.iter().filter_map(|&j| self.jobs[j].variant).map(|v| {
            let v = &self.variants[v];
            format!("`{}` ({})", v.name, describe(&v.defines))
        }).collect();
        const SHOWN: usize = 4;
        let note = if names.len() == 1 {
            format!("in variant {}", names[0])
        } else if names.len() <= SHOWN {
            format!("in variants {}", names.join(", "))
        } else {
            format!("in {} variants: {} and {} more", names.len(), names[..SHOWN].join(", "), names.len() - SHOWN)
        };
        for d in &mut ds {
            d.notes.push(note.clone());
        }
        ds
    }

    /// `variants.json`: each variant's defines, directory and the BLAKE3
    /// hash of every output, paths relative to the output directory. Sorted
    /// (variants in spec order), so it is byte-identical across runs.
    pub fn variants_json(&self) -> String {
        // Written directly in serde_json's pretty layout (two-space
        // indents, keys sorted): building a `serde_json::Value` of 256
        // variants and printing it took milliseconds of a warm run.
        let mut by_variant: Vec<Vec<usize>> = vec![Vec::new(); self.variants.len()];
        for (j, job) in self.jobs.iter().enumerate() {
            if let Some(v) = job.variant {
                by_variant[v].push(j);
            }
        }
        let mut out: Vec<u8> = Vec::with_capacity(1024 + 800 * self.jobs.len());
        // Format 2: BLAKE3 hashes (`blake3:`); 1 had SHA-256 ones.
        out.extend_from_slice(b"{\n  \"format\": 2,\n  \"variants\": [");
        for (vi, v) in self.variants.iter().enumerate() {
            let mut outputs: BTreeMap<String, &crate::cache::Key> = BTreeMap::new();
            let mut same_as = None;
            for &j in &by_variant[vi] {
                let job = &self.jobs[j];
                let o = &self.outcomes[j];
                if let batch::Origin::SameAs(k) = o.origin {
                    if let Some(kv) = self.jobs[k].variant.filter(|&kv| kv != vi) {
                        same_as.get_or_insert(self.variants[kv].name.as_str());
                    }
                }
                let sub = &self.inputs[job.input].subdir;
                debug_assert_eq!(o.artifacts.as_ref().map_or(0, Vec::len), o.hashes.len());
                for (a, hash) in o.artifacts.iter().flatten().zip(&o.hashes) {
                    let mut rel: Vec<String> = sub.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
                    rel.push(a.file_name.clone());
                    outputs.insert(rel.join("/"), hash);
                }
            }
            out.extend_from_slice(if vi == 0 { b"\n    {\n      \"defines\": " } else { b",\n    {\n      \"defines\": " });
            let defines: BTreeMap<&str, Option<&str>> = v.defines.iter().map(|(n, val)| (n.as_str(), val.as_deref())).collect();
            inner_object(&mut out, defines, |out, val| match val {
                Some(val) => json_string(out, val),
                None => out.extend_from_slice(b"null"),
            });
            out.extend_from_slice(b",\n      \"dir\": ");
            json_string(&mut out, &v.name);
            out.extend_from_slice(b",\n      \"name\": ");
            json_string(&mut out, &v.name);
            out.extend_from_slice(b",\n      \"outputs\": ");
            inner_object(&mut out, outputs, |out, hash| {
                out.extend_from_slice(b"\"blake3:");
                out.extend_from_slice(hash.hex().as_bytes());
                out.push(b'"');
            });
            out.extend_from_slice(b",\n      \"same_source_as\": ");
            match same_as {
                Some(name) => json_string(&mut out, name),
                None => out.extend_from_slice(b"null"),
            }
            out.extend_from_slice(b"\n    }");
        }
        out.extend_from_slice(if self.variants.is_empty() { b"]\n}\n" } else { b"\n  ]\n}\n" });
        String::from_utf8(out).expect("JSON text is UTF-8")
    }

    /// Every file any job read, sorted, without repeats, without `./`
    /// steps (an include next to a root given as a bare name is `./x`).
    pub fn files_read(&self) -> Vec<PathBuf> {
        // Variants read the same files: each distinct path is tidied once.
        let mut seen: std::collections::HashSet<&Path> = self.outcomes.iter().flat_map(|o| o.files_read.iter().map(PathBuf::as_path)).collect();
        seen.extend(self.inputs.iter().map(|i| i.path.as_path()));
        let mut all: Vec<PathBuf> = seen.into_iter().map(tidy).collect();
        all.sort();
        all.dedup();
        all
    }
}

/// A path without `./` steps, as [`Batch::files_read`] names files.
fn tidy(p: &Path) -> PathBuf {
    p.components().filter(|c| !matches!(c, std::path::Component::CurDir)).collect()
}

impl Batch {
    /// The hash of each file read that the batch hashed already
    /// ([`Stats::read_hashes`]), by the name [`Batch::files_read`] gives it.
    pub fn read_hashes(&self) -> std::collections::HashMap<PathBuf, crate::cache::Key> {
        self.stats.read_hashes.iter().map(|(p, h)| (tidy(p), *h)).collect()
    }
}

/// Where [`Batch::compile`] reports a job's outputs as they are ready.
pub type Ready<'a> = dyn Fn(usize, &Path, &[Artifact]) + Sync + 'a;

/// A job's output directory relative to the run's: `VARIANT/SUBDIR`.
fn rel_dir(job: &Job, inputs: &[Input], variants: &[Variant]) -> PathBuf {
    let mut d = PathBuf::new();
    if let Some(v) = job.variant {
        d.push(&variants[v].name);
    }
    let sub = &inputs[job.input].subdir;
    if !sub.as_os_str().is_empty() {
        d.push(sub);
    }
    d
}

/// A JSON string, escaped as JSON requires.
fn json_string(out: &mut Vec<u8>, s: &str) {
    // Writing to a Vec cannot fail.
    let _ = serde_json::to_writer(&mut *out, s);
}

/// An object nested two levels down in `variants.json` (a variant's
/// `defines` or `outputs`), in serde_json's pretty layout: `{}` when
/// empty, else one `"key": value` per line.
fn inner_object<K: AsRef<str>, V>(out: &mut Vec<u8>, entries: BTreeMap<K, V>, value: impl Fn(&mut Vec<u8>, V)) {
    if entries.is_empty() {
        out.extend_from_slice(b"{}");
        return;
    }
    for (i, (key, v)) in entries.into_iter().enumerate() {
        out.extend_from_slice(if i == 0 { b"{\n        " } else { b",\n        " });
        json_string(out, key.as_ref());
        out.extend_from_slice(b": ");
        value(out, v);
    }
    out.extend_from_slice(b"\n      }");
}

/// Jobs that failed alike ([`Batch::failures`]).
#[derive(Debug)]
pub struct Failure<'a> {
    pub compilation: &'a Compilation,
    pub jobs: Vec<usize>,
}

/// `variants.json`'s artifact, written last into the output directory.
pub fn variants_artifact(batch: &Batch) -> Artifact {
    Artifact { file_name: "variants.json".into(), target: None, entry: None, contents: batch.variants_json().into_bytes() }
}

/// Writes a job's outputs into `dir`: the files whose bytes changed
/// atomically, and for the others, where they are not newer than
/// `newest_input` (or always without it), only a new modification time, as
/// if rewritten (make and ninja compare times). A warm run so rewrites
/// nothing, and with `known` reads back only files no stamp vouches for
/// ([`crate::output::write_outputs_known`]).
pub fn write_outputs(dir: &Path, artifacts: &[Artifact], newest_input: Option<std::time::SystemTime>, known: Option<&crate::output::Known<'_>>) -> Result<(), crate::output::OutputError> {
    let unchanged = match newest_input {
        Some(t) => crate::output::Unchanged::TouchUnlessNewerThan(t),
        None => crate::output::Unchanged::Touch,
    };
    crate::output::write_outputs_known(dir, artifacts, unchanged, known)
}

/// The newest modification time of `files` (`None` if one cannot be read:
/// then every unchanged output is touched).
pub fn newest_mtime(files: &[PathBuf]) -> Option<std::time::SystemTime> {
    files.iter().try_fold(std::time::UNIX_EPOCH, |newest, f| std::fs::metadata(f).and_then(|m| m.modified()).ok().map(|t| t.max(newest)))
}

/// The first output that would replace a file the compile read (an input
/// or an include named like one of the outputs, in the output directory),
/// with that file. The check compares canonical paths, so `-o .` and
/// `-o ./self` meet `self/x.wgsl` however they are spelled; a directory
/// that does not exist yet holds no input.
pub fn output_replacing_input<'a>(writes: impl IntoIterator<Item = (&'a Path, &'a [Artifact])>, files_read: &[PathBuf]) -> Option<(PathBuf, PathBuf)> {
    let read: std::collections::HashMap<PathBuf, &PathBuf> = files_read.iter().filter_map(|f| std::fs::canonicalize(f).ok().map(|c| (c, f))).collect();
    if read.is_empty() {
        return None;
    }
    let mut canonical_dirs: std::collections::HashMap<&Path, Option<PathBuf>> = Default::default();
    for (dir, artifacts) in writes {
        let Some(canonical) = canonical_dirs.entry(dir).or_insert_with(|| std::fs::canonicalize(dir).ok()) else { continue };
        for a in artifacts {
            if let Some(input) = read.get(&canonical.join(&a.file_name)) {
                return Some((dir.join(&a.file_name), (*input).clone()));
            }
        }
    }
    None
}

/// The error of an output that two inputs would write (`a/x.das` and
/// `b/x.das` into one `-o`), located in both: at the entry point that
/// names it where it is a per-entry-point file (`def vs` makes
/// `vs.330.vert`), else at the start of each input, whose name names it.
/// The sources are read again for this (an input that cannot be is shown
/// by name only).
pub fn output_clash(file_name: &str, entry: Option<&str>, first: &Path, second: &Path) -> (crate::SourceMap, Diagnostic) {
    let mut map = crate::SourceMap::new();
    let mut place = |path: &Path| {
        let text = std::fs::read_to_string(path).ok()?;
        let at = entry.and_then(|e| entry_definition(&text, e)).unwrap_or(0..0);
        let id = map.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
        let base = map.file(id).base;
        Some(crate::source::Span::new(base + at.start as u32, base + at.end as u32))
    };
    let (at_first, at_second) = (place(first), place(second));
    let message = format!(
        "`{file_name}` is an output of both `{}` and `{}`; nothing was written (compile them into different directories)",
        first.display(),
        second.display()
    );
    let mut d = match at_second {
        Some(span) => Diagnostic::error(message, span).with_label(format!("writes `{file_name}`")),
        None => Diagnostic::error_nowhere(message),
    };
    if let Some(span) = at_first {
        d = d.with_secondary(span, format!("also writes `{file_name}`"));
    }
    (map, d)
}

/// The byte range of `name` in the first `def name` of `text`.
fn entry_definition(text: &str, name: &str) -> Option<std::ops::Range<usize>> {
    let mut from = 0;
    while let Some(i) = text[from..].find("def ") {
        let start = from + i + 4;
        let rest = &text[start..];
        let skipped = rest.len() - rest.trim_start_matches([' ', '\t']).len();
        let at = start + skipped;
        let end = at + name.len();
        if text[at..].starts_with(name) && !text[end..].starts_with(|c: char| c.is_alphanumeric() || c == '_') {
            return Some(at..end);
        }
        from = start;
    }
    None
}
