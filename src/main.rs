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
//! umbrac lsp               (a language server on stdin/stdout)
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
use umbrac::{Compilation, Conventions, Diagnostic, Options, SourceMap, Target};

/// Subcommands' argument types that live in their own files.
mod cli;

use umbrac::run::{exit_code, Report, EXIT_ERROR, EXIT_USAGE};

#[derive(Parser, Debug)]
#[command(name = "umbrac", version, about = "Compiles daslang shaders to GLSL 330, GLSL ES 3.00, WGSL and SPIR-V")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// `umbrac compile ...` as `Cli` parses it, without building the other
/// subcommands' arguments (`render`'s are many): building the whole
/// command tree was a twentieth of a first compile's instructions
/// (docs/performance.md, "Whole process"). Its name, version, about and
/// the subcommand's doc are `Cli`'s, so help and errors read the same.
#[derive(Parser, Debug)]
#[command(name = "umbrac", version, about = "Compiles daslang shaders to GLSL 330, GLSL ES 3.00, WGSL and SPIR-V")]
struct CompileCli {
    #[command(subcommand)]
    command: CompileCommand,
}

#[derive(Subcommand, Debug)]
enum CompileCommand {
    /// Compile shader files and write the outputs.
    Compile(CompileArgs),
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Compile shader files and write the outputs.
    Compile(CompileArgs),
    /// Compile for every target and report diagnostics; write nothing.
    Check(CheckArgs),
    /// Print the files `compile` with the same arguments would write, one
    /// per line, and write nothing (what a build system declares).
    Outputs(CompileArgs),
    /// Print the reflection manifest of a shader file.
    Reflect(ReflectArgs),
    /// Write the Rust bindings module of a shader file (what umbrac::build generates).
    Bindgen(BindgenArgs),
    /// Render a program headless to PNG: the shadow scene, a scene file, or the scene inferred for any program.
    #[cfg(feature = "render")]
    Render(cli::render::RenderArgs),
    /// Serve the Language Server Protocol over stdin/stdout (docs/editor.md).
    Lsp,
    /// Serve a page on 127.0.0.1 that draws the program in WebGL2 and
    /// WebGPU and redraws it on every save (docs/preview.md).
    #[cfg(feature = "preview")]
    Preview(PreviewArgs),
}

#[cfg(feature = "preview")]
#[derive(Args, Debug)]
struct PreviewArgs {
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// The port on 127.0.0.1; default: any free one (the URL is printed).
    #[arg(long, value_name = "N", default_value_t = 0)]
    port: u16,
    /// Start the desktop's browser on the page (the playground's, when served).
    #[arg(long)]
    open: bool,
    /// Also serve this built playground (scripts/build-playground.sh) at
    /// /playground/ with FILE loaded; default: target/playground/ beside
    /// the binary, when it has been built.
    #[arg(long, value_name = "DIR")]
    playground: Option<PathBuf>,
    /// Draw FILE with this scene file (NAME.toml or NAME.json: passes,
    /// render targets, draws, values; docs/runner.md, "Scene files")
    /// instead of the scene inferred for it, as `umbrac render --scene`.
    #[arg(long, value_name = "FILE")]
    scene: Option<PathBuf>,
    #[command(flatten)]
    common: CommonArgs,
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
    /// `umbrac outputs`: list what would be written instead of writing.
    #[arg(skip)]
    list_outputs: bool,
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
    /// Do not read the project file (`umbrac.toml` at or above the first input).
    #[arg(long)]
    no_project: bool,
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

/// `opts` over the project file found from the first input (flags win;
/// docs/editor.md, "The project file"), unless `--no-project`; a bad
/// project file is reported and is the exit status.
fn with_project(common: &CommonArgs, opts: Options, files: &[PathBuf]) -> Result<Options, u8> {
    let Some(first) = files.first().filter(|_| !common.no_project) else { return Ok(opts) };
    umbrac::project::options_for(first, opts).map(|(o, _)| o).map_err(|e| {
        Reporter::new(common.message_format).diagnostic(&e.1, &e.0);
        EXIT_ERROR
    })
}

fn main() -> ExitCode {
    if std::env::args_os().nth(1).is_some_and(|a| a == "compile") {
        let CompileCli { command: CompileCommand::Compile(args) } = CompileCli::parse();
        return ExitCode::from(compile(&args));
    }
    let cli = Cli::parse(); // bad usage: clap prints it and exits with 2
    let code = match cli.command {
        Command::Compile(args) => compile(&args),
        Command::Outputs(args) => compile(&CompileArgs { list_outputs: true, ..args }),
        Command::Check(args) => check(&args),
        Command::Reflect(args) => reflect(&args),
        Command::Bindgen(args) => bindgen(&args),
        Command::Lsp => match umbrac::lsp::run_stdio() {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: umbrac lsp: {e}");
                EXIT_ERROR
            }
        },
        #[cfg(feature = "preview")]
        Command::Preview(args) => preview(&args),
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

}

/// The run's messages: diagnostics to stderr (or JSON lines to stdout),
/// `-v` to stderr, the output of `-o -` to stdout.
impl Report for Reporter {
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

    fn usage(&mut self, msg: &str) {
        usage_error(msg);
    }

    fn stdout(&mut self, bytes: &[u8]) -> Result<(), Diagnostic> {
        write_stdout(bytes)
    }

    fn verbose(&mut self, line: &str) {
        eprintln!("{line}");
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
    if args.list_outputs && (to_stdout || args.check || args.depfile.is_some() || args.watch) {
        return usage_error("`umbrac outputs` lists files: it does not take `-o -`, --check, --depfile or --watch");
    }
    if to_stdout && (args.variants.is_some() || args.depfile.is_some()) {
        return usage_error("`-o -` prints one output; --variants and --depfile need an output directory");
    }
    if args.check {
        return match umbrac::jobs::inputs_of(&args.files) {
            Ok(inputs) => compile_check(args, targets_of(&args.targets), inputs),
            Err(e) => usage_error(&e),
        };
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

/// One `compile` run ([`umbrac::run`]): the exit code, and what `--watch` waits on.
fn compile_once(args: &CompileArgs) -> (u8, umbrac::watch::Watched) {
    let options = match with_project(&args.common, args.common.options(targets_of(&args.targets)), &args.files) {
        Ok(o) => o,
        Err(code) => return (code, umbrac::watch::Watched { files: args.files.clone(), dirs: Vec::new() }),
    };
    let req = umbrac::run::Request {
        files: &args.files,
        options,
        out: args.out.clone(),
        variants: args.variants.clone(),
        load_variants: &load_spec,
        depfile: args.depfile.clone(),
        watch: args.watch,
        list_outputs: args.list_outputs,
        jobs: args.batch.jobs.map(|n| n as usize),
        cache: args.batch.cache(),
        verbose: args.batch.verbose,
    };
    umbrac::run::compile_once(req, &mut Reporter::new(args.common.message_format))
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

fn check(args: &CheckArgs) -> u8 {
    let opts = match with_project(&args.common, args.common.options(Vec::new()), &args.files) {
        Ok(o) => o,
        Err(code) => return code,
    };
    let inputs = match umbrac::jobs::inputs_of(&args.files) {
        Ok(i) => i,
        Err(e) => return usage_error(&e),
    };
    let cache = args.batch.cache();
    let settings = umbrac::jobs::Settings { options: &opts, workers: args.batch.workers(), cache: cache.as_ref(), process_ends: false };
    let batch = umbrac::jobs::Batch::compile(inputs, Vec::new(), &settings, None);
    let mut reporter = Reporter::new(args.common.message_format);
    let _trimming = umbrac::run::report_stats(args.batch.verbose, &batch, cache.as_ref(), &mut reporter);
    let mut code = 0;
    for f in batch.failures() {
        reporter.compilation(f.compilation);
        code = code.max(exit_code(f.compilation));
    }
    code
}

fn reflect(args: &ReflectArgs) -> u8 {
    let mut opts = match with_project(&args.common, args.common.options(Vec::new()), std::slice::from_ref(&args.file)) {
        Ok(o) => o,
        Err(code) => return code,
    };
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

/// `umbrac preview`: prints the page's URL, then serves until interrupted.
#[cfg(feature = "preview")]
fn preview(args: &PreviewArgs) -> u8 {
    if !args.file.is_file() {
        eprintln!("error: cannot read `{}`: not a file", args.file.display());
        return EXIT_ERROR;
    }
    let mut opts = umbrac::preview::options_for(&args.file, &args.common.options(Vec::new()));
    let scene = match args.scene.as_deref().map(umbrac::preview::SceneFile::open).transpose() {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_ERROR;
        }
    };
    let playground = match &args.playground {
        Some(dir) => match umbrac::preview::Playground::load(dir) {
            Ok(p) => Some(p),
            Err(e) => {
                eprintln!("error: {e}");
                return EXIT_ERROR;
            }
        },
        None => umbrac::preview::Playground::beside_executable().and_then(|d| umbrac::preview::Playground::load(&d).ok()),
    };
    if playground.is_some() {
        // The playground shows every output, not only what the page draws.
        opts.targets.clear();
    }
    let server = match umbrac::preview::Server::bind(args.port) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_ERROR;
        }
    };
    let url = server.url();
    let mut said = format!("umbrac preview: {} at {url}\n", args.file.display());
    let page = match &playground {
        Some(p) => {
            said += &format!("umbrac preview: the playground ({}) with {} at {url}playground/\n", p.dir().display(), args.file.display());
            format!("{url}playground/")
        }
        None => url.clone(),
    };
    if write_stdout(said.as_bytes()).is_err() {
        return EXIT_ERROR;
    }
    if args.open {
        if let Err(e) = umbrac::preview::open_browser(&page) {
            eprintln!("warning: {e}");
        }
    }
    let e = server.serve(args.file.clone(), opts, playground, scene).err().unwrap_or_default();
    eprintln!("error: umbrac preview: {e}");
    EXIT_ERROR
}

/// `compile --check`: every difference between the outputs and the files in
/// the directory, as unified diffs on stdout; nothing is written.
fn compile_check(args: &CompileArgs, targets: Vec<Target>, inputs: Vec<umbrac::jobs::Input>) -> u8 {
    let opts = match with_project(&args.common, args.common.options(targets), &args.files) {
        Ok(o) => o,
        Err(code) => return code,
    };
    let cache = args.batch.cache();
    let settings = umbrac::jobs::Settings { options: &opts, workers: args.batch.workers(), cache: cache.as_ref(), process_ends: false };
    let batch = umbrac::jobs::Batch::compile(inputs, Vec::new(), &settings, None);
    let mut reporter = Reporter::new(args.common.message_format);
    let _trimming = umbrac::run::report_stats(args.batch.verbose, &batch, cache.as_ref(), &mut reporter);
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
    let mut opts = match with_project(&args.common, args.common.options(Vec::new()), std::slice::from_ref(&args.file)) {
        Ok(o) => o,
        Err(code) => return code,
    };
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
