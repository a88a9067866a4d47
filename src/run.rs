//! One `umbrac compile` run over files and variants: what the CLI, its
//! `--watch` and any other front end drive. It reads inputs, compiles them
//! through the cache (`jobs`), reports through a [`Report`] and writes the
//! outputs, the depfile and the rerun record all or nothing; the front end
//! only parses arguments and prints (`main.rs`).

use std::path::{Path, PathBuf};

use crate::{Diagnostic, Options, Severity, SourceMap, Target};

/// Exit statuses: success is 0.
pub const EXIT_ERROR: u8 = 1;
pub const EXIT_USAGE: u8 = 2;
pub const EXIT_BUG: u8 = 3;
/// Output directories written at once (they wait on the disk, not a core).
const WRITERS: usize = 8;

/// What a step read: files, and directories whose `.das` files (at any
/// depth) count too (a new program in a directory argument).
#[derive(Clone, Debug, Default)]
pub struct Watched {
    pub files: Vec<PathBuf>,
    pub dirs: Vec<PathBuf>,
}

/// Where a run's messages go.
pub trait Report {
    /// A diagnostic, with the sources it points into.
    fn diagnostic(&mut self, d: &Diagnostic, map: &SourceMap);
    /// Bad usage (the run's status is [`EXIT_USAGE`]).
    fn usage(&mut self, msg: &str);
    /// The single output of `-o -`; an error when it is lost.
    fn stdout(&mut self, bytes: &[u8]) -> Result<(), Diagnostic>;
    /// A line of `-v`.
    fn verbose(&mut self, line: &str);

    /// A diagnostic that belongs to no source file (I/O errors, usage).
    fn plain(&mut self, d: &Diagnostic) {
        self.diagnostic(d, &SourceMap::new());
    }

    /// Every diagnostic of a compilation, and why it failed if it says nothing.
    fn compilation(&mut self, c: &crate::Compilation) {
        for d in &c.diagnostics {
            self.diagnostic(d, &c.sources);
        }
        if c.suppressed_errors > 0 {
            self.diagnostic(&Diagnostic::suppressed(c.suppressed_errors), &c.sources);
        }
        // A failed compilation always says why.
        if c.result.is_none() && !c.diagnostics.iter().any(|d| d.is_error()) {
            self.plain(&Diagnostic::bug("compilation failed without a diagnostic", None));
        }
    }
}

/// A variant spec's variants, or the error that points into it.
pub type LoadVariants<'a> = &'a dyn Fn(&Path) -> Result<Vec<crate::variants::Variant>, Box<(SourceMap, Diagnostic)>>;

/// One compile run, as `umbrac compile` takes it.
pub struct Request<'a> {
    /// Input files and directories.
    pub files: &'a [PathBuf],
    pub options: Options,
    /// Output directory (default `.`), or `-` for standard output.
    pub out: Option<PathBuf>,
    /// A variant spec, and how to read it.
    pub variants: Option<PathBuf>,
    pub load_variants: LoadVariants<'a>,
    pub depfile: Option<PathBuf>,
    /// Whether the run repeats (`--watch`): its memory is then freed.
    pub watch: bool,
    /// `umbrac outputs`: print the files the run would write (one per
    /// line, normalised, sorted) instead of writing them.
    pub list_outputs: bool,
    /// Compilations at once; `None`: the cores available.
    pub jobs: Option<usize>,
    pub cache: Option<crate::cache::Cache>,
    /// `-v`.
    pub verbose: bool,
}

/// The exit status a compilation's diagnostics call for.
pub fn exit_code(c: &crate::Compilation) -> u8 {
    if c.diagnostics.iter().any(|d| d.severity == Severity::Bug) || (c.result.is_none() && !c.diagnostics.iter().any(|d| d.is_error())) {
        EXIT_BUG
    } else if c.has_errors() {
        EXIT_ERROR
    } else {
        0
    }
}

fn usage(report: &mut dyn Report, msg: &str) -> u8 {
    report.usage(msg);
    EXIT_USAGE
}

/// One `compile`: the exit code, and what `--watch` waits on.
pub fn compile_once(req: Request, report: &mut dyn Report) -> (u8, Watched) {
    let Request { files, options: opts, out, variants: variants_spec, load_variants, depfile, watch, list_outputs, jobs, cache, verbose } = req;
    let workers = || jobs.unwrap_or_else(crate::batch::default_workers);
    let to_stdout = out.as_deref() == Some(Path::new("-"));
    let mut watched = Watched { files: variants_spec.iter().cloned().collect(), dirs: files.iter().filter(|f| f.is_dir()).cloned().collect() };
    watched.files.extend(files.iter().filter(|f| !f.is_dir()).cloned());
    let inputs = match crate::jobs::inputs_of(files) {
        Ok(i) => i,
        Err(e) => return (usage(report, &e), watched),
    };
    if to_stdout {
        if inputs.len() != 1 {
            return (usage(report, "`-o -` prints one output to stdout; give exactly one FILE"), watched);
        }
        if opts.targets.is_empty() || opts.targets.contains(&Target::Spirv) {
            return (usage(report, "`-o -` prints one text output; SPIR-V is binary (choose one --target of glsl330, gles300, glsl430, gles310, wgsl)"), watched);
        }
    }
    let dir = out.clone().unwrap_or_else(|| PathBuf::from("."));
    // A rerun that would change nothing ends here (src/rerun.rs), before
    // the variant spec is even expanded: its bytes are among the files
    // the record holds the hash of.
    // Without a cache there is no record to read or write: nothing hashed.
    let run_key = (!to_stdout && !list_outputs && cache.is_some()).then(|| run_key(&variants_spec, &depfile, &inputs, &opts, &dir));
    if let (Some(c), Some(key)) = (&cache, &run_key) {
        if let Some(rec) = crate::rerun::Record::load(c, key) {
            let stamps = crate::output::stamps::Stamps::load(c.dir(), &dir);
            let holds = rec.still_holds(&stamps, workers());
            // The outputs it had to read are stamped: the next rerun
            // reads none (and a full run below, none of those).
            stamps.save();
            if holds {
                watched.files.extend(rec.files.iter().map(|(p, _)| p.clone()));
                if verbose {
                    let [jobs, compiled, cached, shared] = rec.counts;
                    report.verbose(&format!(
                        "umbrac: {jobs} jobs: nothing to do, every file read and every output is as the last run left them (that run: {compiled} compiled, {cached} from the cache, {shared} same as another; cache {})",
                        c.dir().display()
                    ));
                }
                if let Some((path, text)) = &rec.depfile {
                    if let Err(e) = write_file(path, text.clone()) {
                        report.plain(&Diagnostic::error_nowhere(e));
                        return (EXIT_ERROR, watched);
                    }
                }
                // The process ends next (see the end of a full run).
                if !watch {
                    std::mem::forget(rec);
                }
                return (0, watched);
            }
        }
    }
    let variants = match &variants_spec {
        None => Vec::new(),
        Some(spec) => match load_variants(spec) {
            Ok(v) => v,
            Err(e) => {
                let (map, d) = *e;
                report.diagnostic(&d, &map);
                return (EXIT_ERROR, watched);
            }
        },
    };
    // One job needs no count of the machine's cores (cgroup files read).
    let workers = if inputs.len() == 1 && variants.is_empty() { 1 } else { workers() };
    let settings = crate::jobs::Settings { options: &opts, workers, cache: cache.as_ref(), process_ends: !watch };
    // Variants whose directories do not exist yet: each job's outputs go
    // to a stage as soon as it compiles, and a rename per directory
    // publishes them (src/output/staged.rs).
    let mut stage = (!to_stdout && !list_outputs && !variants.is_empty()).then(|| crate::output::staged::Staged::begin(&dir)).flatten();
    let to_stage = |_job: usize, rel: &Path, artifacts: &[crate::Artifact]| {
        if let Some(s) = stage.as_ref().filter(|s| s.takes(rel)) {
            // A failed write spoils the stage; everything is then written
            // the usual way, which reports why.
            let _ = s.write(rel, artifacts);
        }
    };
    let ready: Option<&crate::jobs::Ready> = if stage.is_some() { Some(&to_stage) } else { None };
    let batch = crate::jobs::Batch::compile(inputs, variants, &settings, ready);
    let files_read = batch.files_read();
    watched.files.extend(files_read.iter().cloned());
    let _trimming = report_stats(verbose, &batch, cache.as_ref(), report);

    let mut code = 0;
    for f in batch.failures() {
        for d in batch.diagnostics_of(&f) {
            report.diagnostic(&d, &f.compilation.sources);
        }
        if f.compilation.suppressed_errors > 0 {
            report.plain(&Diagnostic::suppressed(f.compilation.suppressed_errors));
        }
        code = code.max(exit_code(f.compilation));
    }
    // Warnings of compilations that succeeded (a cache hit had none).
    for o in batch.outcomes.iter().filter(|o| !o.failed()) {
        if let Some(c) = o.compilation.as_ref().filter(|c| !c.diagnostics.is_empty()) {
            report.compilation(c);
        }
    }
    // A run is all or nothing, like one compile: with one input failing,
    // the others' outputs are not written either (README).
    if code != 0 {
        return (code, watched);
    }

    // Which job writes where; an output two jobs would write is an error.
    // Jobs in directories of their own cannot clash (one job's outputs
    // have distinct names): then no output is looked up.
    let mut dirs = std::collections::HashSet::new();
    let may_clash = !batch.outcomes.iter().enumerate().filter(|(_, o)| o.artifacts.is_some()).all(|(j, _)| dirs.insert(batch.out_dir(j, &dir)));
    drop(dirs);
    let mut owner: std::collections::HashMap<PathBuf, &Path> = Default::default();
    let mut to_write: Vec<(usize, PathBuf)> = Vec::new();
    for (j, o) in batch.outcomes.iter().enumerate() {
        let path = &batch.inputs[batch.jobs[j].input].path;
        let Some(artifacts) = &o.artifacts else { continue };
        if to_stdout {
            let outputs: Vec<_> = artifacts.iter().filter(|a| a.target.is_some()).collect();
            if outputs.len() != 1 {
                let names: Vec<_> = outputs.iter().map(|a| a.file_name.as_str()).collect();
                return (
                    usage(report, &format!(
                        "`-o -` needs exactly one output, but this compile has {} ({}); narrow it with --target and --entry",
                        outputs.len(),
                        names.join(", ")
                    )),
                    watched,
                );
            }
            if let Err(e) = report.stdout(&outputs[0].contents) {
                report.plain(&e);
                code = code.max(EXIT_ERROR);
            }
            continue;
        }
        let out_dir = batch.out_dir(j, &dir);
        if !may_clash {
            to_write.push((j, out_dir));
            continue;
        }
        if let Some((a, other)) = artifacts.iter().find_map(|a| owner.get(&out_dir.join(&a.file_name)).map(|o| (a, *o))) {
            let (map, d) = crate::jobs::output_clash(&a.file_name, a.entry.as_deref(), other, path);
            report.diagnostic(&d, &map);
            code = code.max(EXIT_ERROR);
            continue;
        }
        owner.extend(artifacts.iter().map(|a| (out_dir.join(&a.file_name), path.as_path())));
        to_write.push((j, out_dir));
    }
    if code != 0 {
        return (code, watched);
    }
    // An output never replaces a file the compile read (`x.wgsl` as the
    // input of `-o` its own directory): the whole run is refused, nothing
    // written.
    if !to_stdout {
        let writes = to_write.iter().filter_map(|(j, d)| batch.outcomes[*j].artifacts.as_deref().map(|a| (d.as_path(), a)));
        if let Some((output, input)) = crate::jobs::output_replacing_input(writes, &files_read) {
            report.plain(&Diagnostic::error_nowhere(format!(
                "the output `{}` would replace `{}`, which this compile reads; nothing was written (choose another output directory)",
                output.display(),
                input.display()
            )));
            return (code.max(EXIT_ERROR), watched);
        }
    }
    let mut inputs_read = files_read;
    inputs_read.extend(variants_spec.iter().cloned());
    let manifest = (!batch.variants.is_empty()).then(|| crate::jobs::variants_artifact(&batch));
    // Like `gcc -MD`: a depfile only for a build that succeeded. It is
    // written before the outputs and renamed into place after them, so a
    // depfile that cannot be written changes nothing.
    // Every file the run writes: the depfile's targets, and what
    // `umbrac outputs` prints.
    let written = || {
        let mut targets: Vec<PathBuf> = to_write.iter().flat_map(|(j, d)| batch.outcomes[*j].artifacts.iter().flatten().map(move |a| d.join(&a.file_name))).collect();
        targets.extend(manifest.iter().map(|m| dir.join(&m.file_name)));
        targets
    };
    if list_outputs {
        let mut names: Vec<String> = written().iter().map(|p| crate::syntax::normalize(p).display().to_string()).collect();
        names.sort();
        names.push(String::new());
        if let Err(e) = report.stdout(names.join("\n").as_bytes()) {
            report.plain(&e);
            return (EXIT_ERROR, watched);
        }
        return (0, watched);
    }
    let mut pending_depfile = None;
    if let Some(depfile) = &depfile {
        let targets = written();
        if let Some(p) = crate::depfile::unwritable(&targets).or_else(|| crate::depfile::unwritable(&inputs_read)) {
            report.plain(&Diagnostic::error_nowhere(format!("`{}` has a line break in its name, which a depfile cannot hold; nothing was written", p.display())));
            return (EXIT_ERROR, watched);
        }
        let text = crate::depfile::render(&targets, &inputs_read, relative_base(files).as_deref()).into_bytes();
        match crate::depfile::Pending::write(depfile, &text) {
            Ok(p) => pending_depfile = Some((p, depfile.clone(), text)),
            Err(e) => {
                report.plain(&Diagnostic::error_nowhere(e));
                return (EXIT_ERROR, watched);
            }
        }
    }
    // The staged directories are published; which of `to_write` they hold.
    let published: Vec<bool> = match stage.take() {
        Some(s) if code == 0 => publish_stage(s, &batch, &to_write, &dir),
        _ => Vec::new(),
    };
    let is_published = |k: usize| published.get(k).copied().unwrap_or(false);
    let in_place = (0..to_write.len()).filter(|&k| !is_published(k)).count();
    // An unchanged output newer than every file read is left alone; the
    // cache's stamps say which outputs need not be read back to see that.
    let newest_input = crate::jobs::newest_mtime(&inputs_read);
    let stamps = match &cache {
        Some(c) if in_place > 0 || manifest.is_some() => crate::output::stamps::Stamps::load(c.dir(), &dir),
        _ => Default::default(),
    };
    // Each directory atomically, several at once (file system calls block
    // now and then).
    let results: Vec<Result<(), String>> = if in_place == 0 {
        vec![Ok(()); to_write.len()]
    } else {
        crate::batch::parallel_map(
            to_write.len(),
            WRITERS,
            |k| {
                if is_published(k) {
                    return Ok(());
                }
                let (j, out_dir) = &to_write[k];
                let o = &batch.outcomes[*j];
                let artifacts = o.artifacts.as_deref().unwrap_or_default();
                let known = (o.hashes.len() == artifacts.len()).then_some(crate::output::Known { hashes: &o.hashes, stamps: &stamps });
                crate::jobs::write_outputs(out_dir, artifacts, newest_input, known.as_ref()).map_err(|e| e.to_string())
            },
            |_, msg| Err(format!("writing panicked: {msg}")),
        )
    };
    let mut written_hashes: Vec<(PathBuf, crate::cache::Key)> = Vec::new();
    for ((j, out_dir), result) in to_write.iter().zip(results) {
        let path = &batch.inputs[batch.jobs[*j].input].path;
        match result {
            Ok(()) => {
                let o = &batch.outcomes[*j];
                written_hashes.extend(o.artifacts.iter().flatten().zip(&o.hashes).map(|(a, h)| (out_dir.join(&a.file_name), *h)));
            }
            Err(e) => {
                report.plain(&Diagnostic::error_nowhere(format!("{e}; no output of `{}` was changed", path.display())));
                code = code.max(EXIT_ERROR);
            }
        }
    }
    if to_stdout {
        return (code, watched);
    }
    if let (Some(manifest), 0) = (&manifest, code) {
        // Its hash is for the stamps and the run record: only with a cache.
        let hash: Vec<crate::cache::Key> = cache.iter().map(|_| crate::cache::Key::of_bytes(&manifest.contents)).collect();
        let known = cache.as_ref().map(|_| crate::output::Known { hashes: &hash, stamps: &stamps });
        match crate::jobs::write_outputs(&dir, std::slice::from_ref(manifest), newest_input, known.as_ref()) {
            Ok(()) => {
                written_hashes.extend(hash.first().map(|h| (dir.join(&manifest.file_name), *h)));
            }
            Err(e) => {
                report.plain(&Diagnostic::error_nowhere(e.to_string()));
                code = code.max(EXIT_ERROR);
            }
        }
    }
    stamps.save();
    // The depfile goes into place once every output is written (dropped
    // otherwise: its temporary is removed and the old one stays).
    let mut depfile_text = None;
    if let (Some((pending, depfile, text)), 0) = (pending_depfile, code) {
        match pending.commit() {
            Ok(()) => depfile_text = Some((depfile, text)),
            Err(e) => {
                report.plain(&Diagnostic::error_nowhere(e));
                code = code.max(EXIT_ERROR);
            }
        }
    }
    // What the next run needs to see that it would change nothing. A run
    // in which a unit said something (a warning) records nothing: a rerun
    // that did nothing would not say it again (the cache stores only
    // compilations without a diagnostic, for the same reason).
    let said_something = batch.outcomes.iter().any(|o| o.compilation.as_ref().is_some_and(|c| !c.diagnostics.is_empty()));
    if let (0, false, Some(c), Some(key)) = (code, said_something, &cache, &run_key) {
        // Each file's hash as the batch made it from the bytes it read
        // (each byte hashed once); the rest (the variant spec) read now.
        let known = batch.read_hashes();
        let mut files = Vec::new();
        for f in inputs_read.iter() {
            match known.get(f).copied().map(Ok).unwrap_or_else(|| std::fs::read(f).map(|b| crate::cache::Key::of_bytes(&b))) {
                Ok(hash) => files.push((f.clone(), hash)),
                Err(_) => return (code, watched),
            }
        }
        let mut probed: Vec<PathBuf> = batch.outcomes.iter().flat_map(|o| o.probed.iter().cloned()).collect();
        probed.sort();
        probed.dedup();
        let s = &batch.stats;
        let counts = [batch.jobs.len() as u64, s.compiled as u64, s.cached as u64, s.shared as u64];
        crate::rerun::Record { files, probed, outputs: written_hashes, depfile: depfile_text, counts }.save(c, key);
    }
    drop(_trimming);
    // The process ends next and its memory goes back to the system at
    // once: freeing thousands of outputs one by one first took another
    // millisecond of a cold run. `--watch` runs again, and frees.
    if !watch {
        std::mem::forget(batch);
    }
    (code, watched)
}

/// Completes a stage with what it takes and does not hold yet (jobs that
/// share another's outputs) and publishes it: for each of `to_write`,
/// whether it was published. Empty where that could not be done: the
/// caller then writes everything the usual way, and the stage is gone.
fn publish_stage(stage: crate::output::staged::Staged, batch: &crate::jobs::Batch, to_write: &[(usize, PathBuf)], dir: &Path) -> Vec<bool> {
    let mut taken = Vec::with_capacity(to_write.len());
    for (j, out_dir) in to_write {
        let Ok(rel) = out_dir.strip_prefix(dir) else { return Vec::new() };
        let takes = stage.takes(rel);
        taken.push(takes);
        if !takes || stage.holds(rel) {
            continue;
        }
        let Some(artifacts) = &batch.outcomes[*j].artifacts else { return Vec::new() };
        if stage.write(rel, artifacts).is_err() {
            return Vec::new();
        }
    }
    match stage.publish() {
        Ok(()) => taken,
        Err(_) => Vec::new(),
    }
}

/// Says what `-v` asks (what was compiled, shared and read from the
/// cache) and any cache store error. A run that stored entries trims the
/// cache, on another thread, until the result is dropped.
pub fn report_stats(verbose: bool, batch: &crate::jobs::Batch, cache: Option<&crate::cache::Cache>, report: &mut dyn Report) -> Option<crate::cache::Trimming> {
    let s = &batch.stats;
    if let Some(e) = &s.store_error {
        let mut d = Diagnostic::error_nowhere(e.clone());
        d.severity = Severity::Warning;
        report.plain(&d);
    }
    if verbose {
        let where_ = cache.map_or("no cache".to_string(), |c| format!("cache {}", c.dir().display()));
        report.verbose(&format!("umbrac: {} jobs: {} compiled, {} from the cache, {} same as another ({where_}, {} stored)", batch.jobs.len(), s.compiled, s.cached, s.shared, s.stored));
    }
    cache.filter(|_| s.stored > 0).map(crate::cache::Cache::trim_in_background)
}

/// The key of a compile command's whole configuration (src/rerun.rs):
/// where it runs, what it reads, how and where it writes.
/// The spec's variants are not in it: the record holds the hash of the
/// spec's bytes, which are all they depend on.
fn run_key(variants: &Option<PathBuf>, depfile: &Option<PathBuf>, inputs: &[crate::jobs::Input], opts: &crate::Options, dir: &Path) -> crate::cache::Key {
    let cwd = std::env::current_dir().unwrap_or_default();
    let parts = [
        format!("{cwd:?}"),
        format!("{inputs:?}"),
        format!("{variants:?}"),
        format!("{opts:?}"),
        format!("{dir:?}"),
        format!("{depfile:?}"),
    ];
    let bytes: Vec<&[u8]> = parts.iter().map(|p| p.as_bytes()).collect();
    crate::rerun::key(&bytes)
}

/// Writes one file atomically.
fn write_file(path: &Path, contents: Vec<u8>) -> Result<(), String> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).ok_or_else(|| format!("`{}` is not a file name", path.display()))?;
    let a = crate::Artifact { file_name: name, target: None, entry: None, contents };
    crate::output::write_artifacts(dir, &[a]).map_err(|e| e.to_string())
}

/// The working directory, when every input was named relative to it: the
/// depfile's paths are then relative too (docs/build.md, "Depfiles").
fn relative_base(files: &[PathBuf]) -> Option<PathBuf> {
    files.iter().all(|f| f.is_relative()).then(std::env::current_dir).and_then(Result::ok)
}
