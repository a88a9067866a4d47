//! The `umbrac` command line.
//!
//! ```text
//! umbrac compile FILE|DIR... [--target glsl330|gles300|wgsl|spirv|all]... [-o DIR]
//!                [-D NAME[=VALUE]]... [-I DIR]... [--entry NAME]...
//!                [--conventions portable|native] [--allow-outside-includes]
//!                [--message-format human|json]
//! umbrac compile --check FILE|DIR... [-o DIR]   (compare with DIR, write nothing)
//! umbrac check FILE|DIR...  (compile for every target, write nothing)
//! umbrac reflect FILE       (print the reflection manifest)
//! umbrac bindgen FILE [-o bindings.rs] [--module NAME] [--no-bytemuck]
//! umbrac render ...         (feature `render`)
//! ```
//!
//! Exit status: 0 success, 1 compile error (or outputs that cannot be
//! written), 2 bad usage, 3 internal compiler error.
//!
//! A DIR stands for every `.das` file under it (recursively, skipping
//! `include` directories and hidden entries; `umbrac::batch`), its outputs in the same relative
//! subdirectory of `-o DIR`. Several FILEs compile in parallel; each file's outputs are written
//! atomically and only if that file compiled without errors. `-o -` prints
//! the single text output of a single FILE to stdout (the manifest is not
//! printed; use `umbrac reflect` for it). Diagnostics go to stderr as
//! codespan-reporting text, or with `--message-format json` to stdout, one
//! JSON object per line.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream};
use umbrac::{Compilation, Conventions, Diagnostic, Options, Severity, SourceMap, Target};

/// Subcommands' argument types that live in their own files.
mod cli;

const EXIT_ERROR: u8 = 1;
const EXIT_USAGE: u8 = 2;
const EXIT_BUG: u8 = 3;
/// Output directories written at once (they wait on the disk, not a core).
const WRITERS: usize = 8;

#[derive(Parser, Debug)]
#[command(name = "umbrac", version, about = "Compiles daslang shaders to GLSL 330, GLSL ES 3.00, WGSL and SPIR-V")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Compile shader files and write the outputs.
    Compile(CompileArgs),
    /// Compile for every target and report diagnostics; write nothing.
    Check(CheckArgs),
    /// Print the reflection manifest of a shader file.
    Reflect(ReflectArgs),
    /// Write the Rust bindings module of a shader file (what umbrac::build generates).
    Bindgen(BindgenArgs),
    /// Render the shadow scene from compiled shaders.
    #[cfg(feature = "render")]
    Render(cli::render::RenderArgs),
}

#[derive(Args, Debug)]
struct CompileArgs {
    /// Input files, or directories: every `.das` file under a directory
    /// (recursively, skipping directories named `include` and hidden ones),
    /// with outputs in the same relative subdirectory of the output directory.
    #[arg(required = true, value_name = "FILE|DIR")]
    files: Vec<PathBuf>,
    /// Targets to emit (repeatable); default: all.
    #[arg(long = "target", value_enum, value_name = "TARGET")]
    targets: Vec<TargetArg>,
    /// Output directory (created if missing), or `-` for stdout; default: the current directory.
    #[arg(short = 'o', value_name = "DIR")]
    out: Option<PathBuf>,
    /// Compare with the files already in the output directory instead of
    /// writing: print a unified diff per difference, exit 1 if any.
    #[arg(long)]
    check: bool,
    /// Compile every variant of a TOML spec into DIR/VARIANT/ and write
    /// DIR/variants.json (docs/build.md, "Variants").
    #[arg(long, value_name = "SPEC.toml")]
    variants: Option<PathBuf>,
    /// Write a Make-syntax depfile naming every output and every file read.
    #[arg(long, value_name = "FILE")]
    depfile: Option<PathBuf>,
    /// Compile, then again whenever a file read changes, until interrupted;
    /// a failed compile leaves the last good outputs.
    #[arg(long)]
    watch: bool,
    #[command(flatten)]
    batch: BatchArgs,
    #[command(flatten)]
    common: CommonArgs,
}

#[derive(Args, Debug)]
struct BatchArgs {
    /// Compilations run at once; default: the cores available.
    #[arg(short = 'j', long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    jobs: Option<u32>,
    /// Cache directory; default: $UMBRAC_CACHE_DIR, else $XDG_CACHE_HOME/umbrac, else ~/.cache/umbrac.
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    cache: Option<PathBuf>,
    /// Do not read or write the cache.
    #[arg(long)]
    no_cache: bool,
    /// Bound on the cache's size (bytes, or with K, M or G); default 256M.
    #[arg(long, value_name = "SIZE", value_parser = parse_size)]
    cache_size: Option<u64>,
    /// Print what was compiled and what came from the cache.
    #[arg(short = 'v', long)]
    verbose: bool,
}

fn parse_size(s: &str) -> Result<u64, String> {
    let (digits, unit) = match s.char_indices().find(|(_, c)| !c.is_ascii_digit()) {
        Some((i, _)) => s.split_at(i),
        None => (s, ""),
    };
    let n: u64 = digits.parse().map_err(|_| format!("`{s}` is not a size (e.g. 512M)"))?;
    let mul: u64 = match unit.to_ascii_uppercase().as_str() {
        "" | "B" => 1,
        "K" | "KB" | "KIB" => 1 << 10,
        "M" | "MB" | "MIB" => 1 << 20,
        "G" | "GB" | "GIB" => 1 << 30,
        _ => return Err(format!("`{s}`: unknown unit `{unit}` (K, M or G)")),
    };
    n.checked_mul(mul).ok_or_else(|| format!("`{s}` is too large"))
}

impl BatchArgs {
    fn workers(&self) -> usize {
        self.jobs.map_or_else(umbrac::batch::default_workers, |n| n as usize)
    }

    fn cache(&self) -> Option<umbrac::cache::Cache> {
        if self.no_cache {
            return None;
        }
        let dir = self.cache.clone().or_else(umbrac::cache::Cache::default_dir)?;
        Some(umbrac::cache::Cache::new(dir, self.cache_size.unwrap_or(umbrac::cache::DEFAULT_MAX_BYTES)))
    }
}

#[derive(Args, Debug)]
struct CheckArgs {
    /// Input files or directories (as for `compile`).
    #[arg(required = true, value_name = "FILE|DIR")]
    files: Vec<PathBuf>,
    #[command(flatten)]
    batch: BatchArgs,
    #[command(flatten)]
    common: CommonArgs,
}

#[derive(Args, Debug)]
struct ReflectArgs {
    #[arg(value_name = "FILE")]
    file: PathBuf,
    #[command(flatten)]
    common: CommonArgs,
}

#[derive(Args, Debug)]
// `--module NAME` names the bindings' module here: the module prefixes
// (`--module PREFIX=DIR` elsewhere) are `--module-prefix`.
#[command(mut_arg("modules", |a| a.long("module-prefix")))]
struct BindgenArgs {
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// Output file; default: stdout.
    #[arg(short = 'o', value_name = "FILE")]
    out: Option<PathBuf>,
    /// The module's name; default: the input's stem.
    #[arg(long, value_name = "NAME")]
    module: Option<String>,
    /// Do not derive bytemuck::Pod/Zeroable.
    #[arg(long)]
    no_bytemuck: bool,
    #[command(flatten)]
    common: CommonArgs,
}

#[derive(Args, Debug)]
struct CommonArgs {
    /// Define a preprocessor name (repeatable).
    #[arg(short = 'D', value_name = "NAME[=VALUE]", value_parser = parse_define)]
    defines: Vec<Define>,
    /// Add an include directory (repeatable).
    #[arg(short = 'I', value_name = "DIR")]
    include_dirs: Vec<PathBuf>,
    /// Compile only this entry point (repeatable); default: all.
    #[arg(long = "entry", value_name = "NAME")]
    entries: Vec<String>,
    /// Clip-space conventions of the WGSL and SPIR-V outputs.
    #[arg(long, value_enum, default_value_t = ConventionsArg::Portable)]
    conventions: ConventionsArg,
    /// How GLSL declares the loose uniforms: plain `uniform T name;` (set by
    /// name with glUniform*, as daslang's generator writes them) or one std140
    /// block per @set group, laid out as the WGSL/SPIR-V uniform buffer.
    #[arg(long, value_enum, default_value_t = GlUniformsArg::Plain)]
    gl_uniforms: GlUniformsArg,
    /// Compile for devices with more of a resource than the targets' minimums
    /// (repeatable), e.g. `--limit uniform-blocks=16`; docs/targets.md lists the
    /// names and minimums.
    #[arg(long = "limit", value_name = "NAME=N", value_parser = parse_limit)]
    limits: Vec<(umbrac::Limit, u64)>,
    /// Refuse a program over any guaranteed minimum; by default, going over a
    /// guarantee that every device in use exceeds is a warning.
    #[arg(long)]
    strict_limits: bool,
    /// Let #include reach files outside the input's directory and the -I directories.
    #[arg(long)]
    allow_outside_includes: bool,
    /// daslang's `daslib` directory, for `require daslib/NAME`.
    #[arg(long, value_name = "DIR")]
    daslib: Option<PathBuf>,
    /// A daslang tree or install, for `require`: its `daslib/`, the prefixes
    /// its `modules/*/.das_module` files register, its prefix-named folders.
    #[arg(long, value_name = "DIR", value_parser = umbrac::syntax::modules::parse_daslang_root)]
    daslang_root: Option<PathBuf>,
    /// Where `require PREFIX/NAME` finds `NAME.das` (repeatable), e.g.
    /// `geometry=modules/dasGlsl/glsl`.
    #[arg(long = "module", value_name = "PREFIX=DIR", value_parser = umbrac::syntax::modules::parse_module_arg)]
    modules: Vec<(String, PathBuf)>,
    /// How diagnostics are printed.
    #[arg(long, value_enum, default_value_t = MessageFormat::Human)]
    message_format: MessageFormat,
}

#[derive(Clone, Debug)]
struct Define(String, Option<String>);

fn parse_define(s: &str) -> Result<Define, String> {
    let (name, value) = match s.split_once('=') {
        Some((n, v)) => (n, Some(v.to_string())),
        None => (s, None),
    };
    let ok = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !ok {
        return Err(format!("`{name}` is not a valid preprocessor name"));
    }
    Ok(Define(name.to_string(), value))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum TargetArg {
    #[value(name = "glsl330")]
    Glsl330,
    #[value(name = "gles300")]
    Gles300,
    #[value(name = "glsl430")]
    Glsl430,
    #[value(name = "gles310")]
    Gles310,
    #[value(name = "wgsl")]
    Wgsl,
    #[value(name = "spirv")]
    Spirv,
    #[value(name = "all")]
    All,
}

fn parse_limit(s: &str) -> Result<(umbrac::Limit, u64), String> {
    let names = || umbrac::Limit::ALL.iter().map(|l| l.name()).collect::<Vec<_>>().join(", ");
    let (name, n) = s.split_once('=').ok_or_else(|| format!("`{s}` is not NAME=N (names: {})", names()))?;
    let limit = umbrac::Limit::from_name(name).ok_or_else(|| format!("no limit is named `{name}` (names: {})", names()))?;
    let n = n.parse::<u64>().map_err(|_| format!("`{n}` is not a count"))?;
    Ok((limit, n))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum GlUniformsArg {
    Plain,
    Blocks,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum ConventionsArg {
    Portable,
    Native,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum MessageFormat {
    Human,
    Json,
}

impl CommonArgs {
    fn options(&self, targets: Vec<Target>) -> Options {
        Options {
            targets,
            defines: self.defines.iter().map(|d| (d.0.clone(), d.1.clone())).collect(),
            include_dirs: self.include_dirs.clone(),
            entries: self.entries.clone(),
            conventions: match self.conventions {
                ConventionsArg::Portable => Conventions::Portable,
                ConventionsArg::Native => Conventions::Native,
            },
            gl_uniforms: match self.gl_uniforms {
                GlUniformsArg::Plain => umbrac::GlUniforms::Plain,
                GlUniformsArg::Blocks => umbrac::GlUniforms::Blocks,
            },
            limits: self.limits.clone(),
            strict_limits: self.strict_limits,
            allow_outside_includes: self.allow_outside_includes,
            daslib: self.daslib.clone(),
            daslang_root: self.daslang_root.clone(),
            modules: self.modules.clone(),
            source_name: None,
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse(); // bad usage: clap prints it and exits with 2
    let code = match cli.command {
        Command::Compile(args) => compile(&args),
        Command::Check(args) => check(&args),
        Command::Reflect(args) => reflect(&args),
        Command::Bindgen(args) => bindgen(&args),
        #[cfg(feature = "render")]
        Command::Render(args) => {
            // A headless run has no login session's runtime directory; the
            // graphics stack then probes Wayland anyway, whose client library
            // prints "error: XDG_RUNTIME_DIR is invalid or not set" on a run
            // that succeeds. Any directory silences it. Set here, while the
            // process has one thread, for this process and its children.
            if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
                std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
            }
            cli::render::run(&args)
        }
    };
    ExitCode::from(code)
}

/// Prints diagnostics in the chosen format.
struct Reporter {
    format: MessageFormat,
    stderr: StandardStream,
}

impl Reporter {
    fn new(format: MessageFormat) -> Self {
        let color = if std::io::stderr().is_terminal() { ColorChoice::Auto } else { ColorChoice::Never };
        Reporter { format, stderr: StandardStream::stderr(color) }
    }

    fn diagnostic(&mut self, d: &Diagnostic, map: &SourceMap) {
        match self.format {
            MessageFormat::Human => d.emit(map, &mut self.stderr),
            MessageFormat::Json => {
                if let Ok(line) = serde_json::to_string(&d.to_json(map)) {
                    let mut out = std::io::stdout().lock();
                    let _ = writeln!(out, "{line}");
                }
            }
        }
    }

    /// A diagnostic that belongs to no source file (I/O errors, usage).
    fn plain(&mut self, d: &Diagnostic) {
        self.diagnostic(d, &SourceMap::new());
    }

    fn compilation(&mut self, c: &Compilation) {
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

fn exit_code(c: &Compilation) -> u8 {
    if c.diagnostics.iter().any(|d| d.severity == Severity::Bug) || (c.result.is_none() && !c.diagnostics.iter().any(|d| d.is_error())) {
        EXIT_BUG
    } else if c.has_errors() {
        EXIT_ERROR
    } else {
        0
    }
}

#[cfg(not(unix))]
fn stdout_was_closed_at_start() -> bool {
    false
}

/// Writes an output to standard output, which may be a full disk, a pipe
/// whose reader is gone or a closed descriptor: then the output is lost,
/// and the run must fail.
fn write_stdout(bytes: &[u8]) -> Result<(), Diagnostic> {
    let lost = |e: std::io::Error| Diagnostic::error_nowhere(format!("cannot write the output to standard output: {e}"));
    let out = std::io::stdout();
    // Rust's stdout quietly drops what is written to a closed descriptor
    // (EBADF); duplicating it asks the OS whether it is open.
    #[cfg(unix)]
    std::os::fd::AsFd::as_fd(&out).try_clone_to_owned().map_err(lost)?;
    if stdout_was_closed_at_start() {
        return Err(lost(std::io::Error::from_raw_os_error(9)));
    }
    let mut out = out.lock();
    out.write_all(bytes).and_then(|_| out.flush()).map_err(lost)
}

/// Whether the process started with descriptor 1 closed (`>&-`). Rust's
/// runtime then opens `/dev/null` read-write in its place before `main`,
/// so writes succeed and vanish; a shell's `> /dev/null` opens it
/// write-only. Read from Linux's `/proc/self/fdinfo`; elsewhere, false.
#[cfg(unix)]
fn stdout_was_closed_at_start() -> bool {
    use std::os::unix::fs::{FileTypeExt, MetadataExt};
    let (Ok(null), Ok(fd1)) = (std::fs::metadata("/dev/null"), std::fs::metadata("/proc/self/fd/1")) else { return false };
    if null.rdev() != fd1.rdev() || !fd1.file_type().is_char_device() {
        return false;
    }
    let Ok(info) = std::fs::read_to_string("/proc/self/fdinfo/1") else { return false };
    // `flags:` is octal; the access mode is its low two bits (2: O_RDWR).
    info.lines().find_map(|l| l.strip_prefix("flags:")).and_then(|f| u32::from_str_radix(f.trim(), 8).ok()).is_some_and(|f| f & 3 == 2)
}

fn usage_error(msg: &str) -> u8 {
    eprintln!("error: {msg}");
    eprintln!("\nFor more information, try '--help'.");
    EXIT_USAGE
}

/// Compiles every file with `opts`, in parallel ([`umbrac::batch::compile_many`]).
fn compile_all(files: &[PathBuf], opts: &Options) -> Vec<Compilation> {
    let jobs: Vec<umbrac::batch::Job> = files.iter().map(|path| umbrac::batch::Job { path, opts }).collect();
    umbrac::batch::compile_many(&jobs, umbrac::batch::default_workers())
}

fn targets_of(args: &[TargetArg]) -> Vec<Target> {
    let mut t: Vec<Target> = Vec::new();
    for a in args {
        match a {
            TargetArg::Glsl330 => t.push(Target::Glsl330),
            TargetArg::Gles300 => t.push(Target::Gles300),
            TargetArg::Glsl430 => t.push(Target::Glsl430),
            TargetArg::Gles310 => t.push(Target::Gles310),
            TargetArg::Wgsl => t.push(Target::Wgsl),
            TargetArg::Spirv => t.push(Target::Spirv),
            // Every target that can run the program: decided once it
            // is checked (`Target::defaults`).
            TargetArg::All => return Vec::new(),
        }
    }
    t.sort();
    t.dedup();
    t
}

fn compile(args: &CompileArgs) -> u8 {
    let to_stdout = args.out.as_deref() == Some(Path::new("-"));
    if args.check && to_stdout {
        return usage_error("`--check` compares with the files in a directory; give `-o DIR`");
    }
    if args.check && (args.variants.is_some() || args.depfile.is_some() || args.watch) {
        return usage_error("`--check` writes nothing: it does not take --variants, --depfile or --watch");
    }
    if to_stdout && (args.variants.is_some() || args.depfile.is_some()) {
        return usage_error("`-o -` prints one output; --variants and --depfile need an output directory");
    }
    if args.watch {
        let mut reporter = Reporter::new(args.common.message_format);
        return match umbrac::watch::watch(|| compile_once(args)) {
            Ok(()) => 0,
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(e));
                EXIT_ERROR
            }
        };
    }
    compile_once(args).0
}

/// One `compile`: the exit code, and what `--watch` waits on.
fn compile_once(args: &CompileArgs) -> (u8, umbrac::watch::Watched) {
    let targets = targets_of(&args.targets);
    let to_stdout = args.out.as_deref() == Some(Path::new("-"));
    let mut watched = umbrac::watch::Watched { files: args.variants.iter().cloned().collect(), dirs: args.files.iter().filter(|f| f.is_dir()).cloned().collect() };
    watched.files.extend(args.files.iter().filter(|f| !f.is_dir()).cloned());
    let inputs = match umbrac::jobs::inputs_of(&args.files) {
        Ok(i) => i,
        Err(e) => return (usage_error(&e), watched),
    };
    if args.check {
        return (compile_check(args, targets, inputs), watched);
    }
    if to_stdout {
        if inputs.len() != 1 {
            return (usage_error("`-o -` prints one output to stdout; give exactly one FILE"), watched);
        }
        if targets.is_empty() || targets.contains(&Target::Spirv) {
            return (usage_error("`-o -` prints one text output; SPIR-V is binary (choose one --target of glsl330, gles300, glsl430, gles310, wgsl)"), watched);
        }
    }
    let mut reporter = Reporter::new(args.common.message_format);
    let opts = args.common.options(targets);
    let cache = args.batch.cache();
    let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    // A rerun that would change nothing ends here (src/rerun.rs), before
    // the variant spec is even expanded: its bytes are among the files
    // the record holds the hash of.
    // Without a cache there is no record to read or write: nothing hashed.
    let run_key = (!to_stdout && cache.is_some()).then(|| run_key(args, &inputs, &opts, &dir));
    if let (Some(c), Some(key)) = (&cache, &run_key) {
        if let Some(rec) = umbrac::rerun::Record::load(c, key) {
            let stamps = umbrac::output::stamps::Stamps::load(c.dir(), &dir);
            let holds = rec.still_holds(&stamps, args.batch.workers());
            // The outputs it had to read are stamped: the next rerun
            // reads none (and a full run below, none of those).
            stamps.save();
            if holds {
                watched.files.extend(rec.files.iter().map(|(p, _)| p.clone()));
                if args.batch.verbose {
                    let [jobs, compiled, cached, shared] = rec.counts;
                    eprintln!(
                        "umbrac: {jobs} jobs: nothing to do, every file read and every output is as the last run left them (that run: {compiled} compiled, {cached} from the cache, {shared} same as another; cache {})",
                        c.dir().display()
                    );
                }
                if let Some((path, text)) = &rec.depfile {
                    if let Err(e) = write_file(path, text.clone()) {
                        reporter.plain(&Diagnostic::error_nowhere(e));
                        return (EXIT_ERROR, watched);
                    }
                }
                // The process ends next (see the end of a full run).
                if !args.watch {
                    std::mem::forget(rec);
                }
                return (0, watched);
            }
        }
    }
    let variants = match &args.variants {
        None => Vec::new(),
        Some(spec) => match load_spec(spec) {
            Ok(v) => v,
            Err(e) => {
                let (map, d) = *e;
                reporter.diagnostic(&d, &map);
                return (EXIT_ERROR, watched);
            }
        },
    };
    let settings = umbrac::jobs::Settings { options: &opts, workers: args.batch.workers(), cache: cache.as_ref() };
    // Variants whose directories do not exist yet: each job's outputs go
    // to a stage as soon as it compiles, and a rename per directory
    // publishes them (src/output/staged.rs).
    let mut stage = (!to_stdout && !variants.is_empty()).then(|| umbrac::output::staged::Staged::begin(&dir)).flatten();
    let to_stage = |_job: usize, rel: &Path, artifacts: &[umbrac::Artifact]| {
        if let Some(s) = stage.as_ref().filter(|s| s.takes(rel)) {
            // A failed write spoils the stage; everything is then written
            // the usual way, which reports why.
            let _ = s.write(rel, artifacts);
        }
    };
    let ready: Option<&umbrac::jobs::Ready> = if stage.is_some() { Some(&to_stage) } else { None };
    let batch = umbrac::jobs::Batch::compile(inputs, variants, &settings, ready);
    let files_read = batch.files_read();
    watched.files.extend(files_read.iter().cloned());
    let _trimming = report_stats(&args.batch, &batch, cache.as_ref(), &mut reporter);

    let mut code = 0;
    for f in batch.failures() {
        for d in batch.diagnostics_of(&f) {
            reporter.diagnostic(&d, &f.compilation.sources);
        }
        if f.compilation.suppressed_errors > 0 {
            reporter.plain(&Diagnostic::suppressed(f.compilation.suppressed_errors));
        }
        code = code.max(exit_code(f.compilation));
    }
    // Warnings of compilations that succeeded (a cache hit had none).
    for o in batch.outcomes.iter().filter(|o| !o.failed()) {
        if let Some(c) = o.compilation.as_ref().filter(|c| !c.diagnostics.is_empty()) {
            reporter.compilation(c);
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
                    usage_error(&format!(
                        "`-o -` needs exactly one output, but this compile has {} ({}); narrow it with --target and --entry",
                        outputs.len(),
                        names.join(", ")
                    )),
                    watched,
                );
            }
            if let Err(e) = write_stdout(&outputs[0].contents) {
                reporter.plain(&e);
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
            let (map, d) = umbrac::jobs::output_clash(&a.file_name, a.entry.as_deref(), other, path);
            reporter.diagnostic(&d, &map);
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
        if let Some((output, input)) = umbrac::jobs::output_replacing_input(writes, &files_read) {
            reporter.plain(&Diagnostic::error_nowhere(format!(
                "the output `{}` would replace `{}`, which this compile reads; nothing was written (choose another output directory)",
                output.display(),
                input.display()
            )));
            return (code.max(EXIT_ERROR), watched);
        }
    }
    let mut inputs_read = files_read;
    inputs_read.extend(args.variants.iter().cloned());
    let manifest = (!batch.variants.is_empty()).then(|| umbrac::jobs::variants_artifact(&batch));
    // Like `gcc -MD`: a depfile only for a build that succeeded. It is
    // written before the outputs and renamed into place after them, so a
    // depfile that cannot be written changes nothing.
    let mut pending_depfile = None;
    if let Some(depfile) = &args.depfile {
        let mut targets: Vec<PathBuf> = to_write.iter().flat_map(|(j, d)| batch.outcomes[*j].artifacts.iter().flatten().map(move |a| d.join(&a.file_name))).collect();
        targets.extend(manifest.iter().map(|m| dir.join(&m.file_name)));
        if let Some(p) = umbrac::depfile::unwritable(&targets).or_else(|| umbrac::depfile::unwritable(&inputs_read)) {
            reporter.plain(&Diagnostic::error_nowhere(format!("`{}` has a line break in its name, which a depfile cannot hold; nothing was written", p.display())));
            return (EXIT_ERROR, watched);
        }
        let text = umbrac::depfile::render(&targets, &inputs_read).into_bytes();
        match umbrac::depfile::Pending::write(depfile, &text) {
            Ok(p) => pending_depfile = Some((p, depfile.clone(), text)),
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(e));
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
    let newest_input = umbrac::jobs::newest_mtime(&inputs_read);
    let stamps = match &cache {
        Some(c) if in_place > 0 || manifest.is_some() => umbrac::output::stamps::Stamps::load(c.dir(), &dir),
        _ => Default::default(),
    };
    // Each directory atomically, several at once (file system calls block
    // now and then).
    let results: Vec<Result<(), String>> = if in_place == 0 {
        vec![Ok(()); to_write.len()]
    } else {
        umbrac::batch::parallel_map(
            to_write.len(),
            WRITERS,
            |k| {
                if is_published(k) {
                    return Ok(());
                }
                let (j, out_dir) = &to_write[k];
                let o = &batch.outcomes[*j];
                let artifacts = o.artifacts.as_deref().unwrap_or_default();
                let known = (o.hashes.len() == artifacts.len()).then_some(umbrac::output::Known { hashes: &o.hashes, stamps: &stamps });
                umbrac::jobs::write_outputs(out_dir, artifacts, newest_input, known.as_ref()).map_err(|e| e.to_string())
            },
            |_, msg| Err(format!("writing panicked: {msg}")),
        )
    };
    let mut written_hashes: Vec<(PathBuf, umbrac::cache::Key)> = Vec::new();
    for ((j, out_dir), result) in to_write.iter().zip(results) {
        let path = &batch.inputs[batch.jobs[*j].input].path;
        match result {
            Ok(()) => {
                let o = &batch.outcomes[*j];
                written_hashes.extend(o.artifacts.iter().flatten().zip(&o.hashes).map(|(a, h)| (out_dir.join(&a.file_name), *h)));
            }
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(format!("{e}; no output of `{}` was changed", path.display())));
                code = code.max(EXIT_ERROR);
            }
        }
    }
    if to_stdout {
        return (code, watched);
    }
    if let (Some(manifest), 0) = (&manifest, code) {
        // Its hash is for the stamps and the run record: only with a cache.
        let hash: Vec<umbrac::cache::Key> = cache.iter().map(|_| umbrac::cache::Key::of_bytes(&manifest.contents)).collect();
        let known = cache.as_ref().map(|_| umbrac::output::Known { hashes: &hash, stamps: &stamps });
        match umbrac::jobs::write_outputs(&dir, std::slice::from_ref(manifest), newest_input, known.as_ref()) {
            Ok(()) => {
                written_hashes.extend(hash.first().map(|h| (dir.join(&manifest.file_name), *h)));
            }
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(e.to_string()));
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
                reporter.plain(&Diagnostic::error_nowhere(e));
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
            match known.get(f).copied().map(Ok).unwrap_or_else(|| std::fs::read(f).map(|b| umbrac::cache::Key::of_bytes(&b))) {
                Ok(hash) => files.push((f.clone(), hash)),
                Err(_) => return (code, watched),
            }
        }
        let mut probed: Vec<PathBuf> = batch.outcomes.iter().flat_map(|o| o.probed.iter().cloned()).collect();
        probed.sort();
        probed.dedup();
        let s = &batch.stats;
        let counts = [batch.jobs.len() as u64, s.compiled as u64, s.cached as u64, s.shared as u64];
        umbrac::rerun::Record { files, probed, outputs: written_hashes, depfile: depfile_text, counts }.save(c, key);
    }
    drop(_trimming);
    // The process ends next and its memory goes back to the system at
    // once: freeing thousands of outputs one by one first took another
    // millisecond of a cold run. `--watch` runs again, and frees.
    if !args.watch {
        std::mem::forget(batch);
    }
    (code, watched)
}

/// Completes a stage with what it takes and does not hold yet (jobs that
/// share another's outputs) and publishes it: for each of `to_write`,
/// whether it was published. Empty where that could not be done: the
/// caller then writes everything the usual way, and the stage is gone.
fn publish_stage(stage: umbrac::output::staged::Staged, batch: &umbrac::jobs::Batch, to_write: &[(usize, PathBuf)], dir: &Path) -> Vec<bool> {
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

/// What a FILE argument's outputs record of it: its file name
/// (docs/scale.md, "Determinism").
fn file_name_of(path: &Path) -> Option<String> {
    path.file_name().map(|n| n.to_string_lossy().into_owned())
}

/// Reads and expands a variant spec; errors point into it.
fn load_spec(path: &Path) -> Result<Vec<umbrac::variants::Variant>, Box<(SourceMap, Diagnostic)>> {
    let mut map = SourceMap::new();
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => return Err(Box::new((map, Diagnostic::error_nowhere(format!("cannot read the variant spec `{}`: {e}", path.display()))))),
    };
    let id = map.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
    let (spec, spans) = match umbrac::variants::Spec::parse_toml_spanned(&map, id) {
        Ok(s) => s,
        Err(d) => return Err(Box::new((map, d))),
    };
    spec.expand().map_err(|e| {
        let label = match e.1 {
            umbrac::variants::Place::Spec => "in this spec",
            umbrac::variants::Place::Axes => "in these axes",
            umbrac::variants::Place::Named(_) => "this variant",
        };
        let d = Diagnostic::error(e.0, spans.of(e.1)).with_label(label);
        Box::new((map, d))
    })
}

/// Says what `-v` asks (what was compiled, shared and read from the
/// cache) and any cache store error. A run that stored entries trims the
/// cache, on another thread, until the result is dropped.
fn report_stats(args: &BatchArgs, batch: &umbrac::jobs::Batch, cache: Option<&umbrac::cache::Cache>, reporter: &mut Reporter) -> Option<umbrac::cache::Trimming> {
    let s = &batch.stats;
    if let Some(e) = &s.store_error {
        let mut d = Diagnostic::error_nowhere(e.clone());
        d.severity = Severity::Warning;
        reporter.plain(&d);
    }
    if args.verbose {
        let where_ = cache.map_or("no cache".to_string(), |c| format!("cache {}", c.dir().display()));
        eprintln!("umbrac: {} jobs: {} compiled, {} from the cache, {} same as another ({where_}, {} stored)", batch.jobs.len(), s.compiled, s.cached, s.shared, s.stored);
    }
    cache.filter(|_| s.stored > 0).map(umbrac::cache::Cache::trim_in_background)
}

/// The key of a compile command's whole configuration (src/rerun.rs):
/// where it runs, what it reads, how and where it writes.
/// The spec's variants are not in it: the record holds the hash of the
/// spec's bytes, which are all they depend on.
fn run_key(args: &CompileArgs, inputs: &[umbrac::jobs::Input], opts: &umbrac::Options, dir: &Path) -> umbrac::cache::Key {
    let cwd = std::env::current_dir().unwrap_or_default();
    let parts = [
        format!("{cwd:?}"),
        format!("{inputs:?}"),
        format!("{:?}", args.variants),
        format!("{opts:?}"),
        format!("{dir:?}"),
        format!("{:?}", args.depfile),
    ];
    let bytes: Vec<&[u8]> = parts.iter().map(|p| p.as_bytes()).collect();
    umbrac::rerun::key(&bytes)
}

/// Writes one file atomically.
fn write_file(path: &Path, contents: Vec<u8>) -> Result<(), String> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).ok_or_else(|| format!("`{}` is not a file name", path.display()))?;
    let a = umbrac::Artifact { file_name: name, target: None, entry: None, contents };
    umbrac::output::write_artifacts(dir, &[a]).map_err(|e| e.to_string())
}

fn check(args: &CheckArgs) -> u8 {
    let opts = args.common.options(Vec::new());
    let inputs = match umbrac::jobs::inputs_of(&args.files) {
        Ok(i) => i,
        Err(e) => return usage_error(&e),
    };
    let cache = args.batch.cache();
    let settings = umbrac::jobs::Settings { options: &opts, workers: args.batch.workers(), cache: cache.as_ref() };
    let batch = umbrac::jobs::Batch::compile(inputs, Vec::new(), &settings, None);
    let mut reporter = Reporter::new(args.common.message_format);
    let _trimming = report_stats(&args.batch, &batch, cache.as_ref(), &mut reporter);
    let mut code = 0;
    for f in batch.failures() {
        reporter.compilation(f.compilation);
        code = code.max(exit_code(f.compilation));
    }
    code
}

fn reflect(args: &ReflectArgs) -> u8 {
    let mut opts = args.common.options(Vec::new());
    opts.source_name = file_name_of(&args.file);
    let comps = compile_all(std::slice::from_ref(&args.file), &opts);
    let c = &comps[0];
    let mut reporter = Reporter::new(args.common.message_format);
    reporter.compilation(c);
    let code = exit_code(c);
    if let Some(result) = c.result.as_ref().filter(|_| code == 0) {
        if let Some(manifest) = result.artifacts.iter().find(|a| a.target.is_none()) {
            if let Err(e) = write_stdout(&manifest.contents) {
                reporter.plain(&e);
                return EXIT_ERROR;
            }
        }
    }
    code
}

/// `compile --check`: every difference between the outputs and the files in
/// the directory, as unified diffs on stdout; nothing is written.
fn compile_check(args: &CompileArgs, targets: Vec<Target>, inputs: Vec<umbrac::jobs::Input>) -> u8 {
    let opts = args.common.options(targets);
    let cache = args.batch.cache();
    let settings = umbrac::jobs::Settings { options: &opts, workers: args.batch.workers(), cache: cache.as_ref() };
    let batch = umbrac::jobs::Batch::compile(inputs, Vec::new(), &settings, None);
    let mut reporter = Reporter::new(args.common.message_format);
    let _trimming = report_stats(&args.batch, &batch, cache.as_ref(), &mut reporter);
    let mut code = 0;
    for f in batch.failures() {
        reporter.compilation(f.compilation);
        code = code.max(exit_code(f.compilation));
    }
    let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    // The outputs expected in each directory (a DIR input mirrors its
    // subdirectories under -o, as `compile` writes them).
    let mut expected: std::collections::BTreeMap<PathBuf, Vec<umbrac::Artifact>> = Default::default();
    for (j, o) in batch.outcomes.iter().enumerate() {
        let slot = expected.entry(batch.out_dir(j, &dir)).or_default();
        slot.extend(o.artifacts.iter().flatten().cloned());
    }
    let mut diffs = Vec::new();
    for (d, artifacts) in &expected {
        match umbrac::golden::compare(artifacts, d) {
            Ok(found) => diffs.extend(found),
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(format!("cannot read `{}`: {e}", d.display())));
                return code.max(EXIT_ERROR);
            }
        }
    }
    // With a failed input its outputs are unknown, so none is called stale.
    let diffs: Vec<_> = diffs.into_iter().filter(|d| code == 0 || !matches!(d, umbrac::golden::Difference::Stale { .. })).collect();
    let text: String = diffs.iter().map(|d| d.to_string()).collect();
    if let Err(e) = write_stdout(text.as_bytes()) {
        reporter.plain(&e);
        code = code.max(EXIT_ERROR);
    }
    if !diffs.is_empty() {
        eprintln!("error: {} file(s) in `{}` differ from the compiler's output", diffs.len(), dir.display());
        code = code.max(EXIT_ERROR);
    }
    code
}

fn bindgen(args: &BindgenArgs) -> u8 {
    let mut opts = args.common.options(Vec::new());
    opts.source_name = file_name_of(&args.file);
    let comps = compile_all(std::slice::from_ref(&args.file), &opts);
    let c = &comps[0];
    let mut reporter = Reporter::new(args.common.message_format);
    reporter.compilation(c);
    let code = exit_code(c);
    let Some(result) = c.result.as_ref().filter(|_| code == 0) else { return code };
    let bopts = umbrac::bindgen::BindgenOptions { module_name: args.module.clone(), bytemuck: !args.no_bytemuck, sources: true };
    let text = match umbrac::bindgen::generate(result, &bopts) {
        Ok(t) => t,
        Err(e) => {
            reporter.plain(&Diagnostic::error_nowhere(e));
            return EXIT_ERROR;
        }
    };
    match args.out.as_deref().filter(|p| *p != Path::new("-")) {
        None => match write_stdout(text.as_bytes()) {
            Ok(()) => 0,
            Err(e) => {
                reporter.plain(&e);
                EXIT_ERROR
            }
        },
        Some(path) => {
            let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
            let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            let a = umbrac::Artifact { file_name: name, target: None, entry: None, contents: text.into_bytes() };
            match umbrac::output::write_artifacts(dir, &[a]) {
                Ok(()) => 0,
                Err(e) => {
                    reporter.plain(&Diagnostic::error_nowhere(e.to_string()));
                    EXIT_ERROR
                }
            }
        }
    }
}
