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

const EXIT_ERROR: u8 = 1;
const EXIT_USAGE: u8 = 2;
const EXIT_BUG: u8 = 3;

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
    Render(umbrac::render::cli::RenderArgs),
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
    #[command(flatten)]
    common: CommonArgs,
}

#[derive(Args, Debug)]
struct CheckArgs {
    /// Input files or directories (as for `compile`).
    #[arg(required = true, value_name = "FILE|DIR")]
    files: Vec<PathBuf>,
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
    /// Let #include reach files outside the input's directory and the -I directories.
    #[arg(long)]
    allow_outside_includes: bool,
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
    #[value(name = "wgsl")]
    Wgsl,
    #[value(name = "spirv")]
    Spirv,
    #[value(name = "all")]
    All,
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
            allow_outside_includes: self.allow_outside_includes,
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
            umbrac::render::cli::run(&args).clamp(0, 255) as u8
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
            self.diagnostic(&Diagnostic::error_nowhere(format!("{} more errors not shown", c.suppressed_errors)), &c.sources);
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

/// The files to compile: each FILE as given, and the programs under each
/// DIR ([`umbrac::batch::programs_under`]), each with the subdirectory its
/// outputs go to (relative to the output directory).
fn expand_inputs(inputs: &[PathBuf]) -> Result<Vec<(PathBuf, PathBuf)>, String> {
    let mut out = Vec::new();
    for input in inputs {
        if !input.is_dir() {
            out.push((input.clone(), PathBuf::new()));
            continue;
        }
        let found = umbrac::batch::programs_under(input).map_err(|e| e.to_string())?;
        if found.is_empty() {
            return Err(format!("no `.das` files under `{}`", input.display()));
        }
        out.extend(found.into_iter().map(|f| (f.path, f.subdir)));
    }
    Ok(out)
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
            TargetArg::Wgsl => t.push(Target::Wgsl),
            TargetArg::Spirv => t.push(Target::Spirv),
            TargetArg::All => t.extend(Target::ALL),
        }
    }
    t.sort();
    t.dedup();
    if t.is_empty() {
        Target::ALL.to_vec()
    } else {
        t
    }
}

fn compile(args: &CompileArgs) -> u8 {
    let targets = targets_of(&args.targets);
    let to_stdout = args.out.as_deref() == Some(Path::new("-"));
    if args.check && to_stdout {
        return usage_error("`--check` compares with the files in a directory; give `-o DIR`");
    }
    let inputs = match expand_inputs(&args.files) {
        Ok(i) => i,
        Err(e) => return usage_error(&e),
    };
    if args.check {
        return compile_check(args, targets, &inputs);
    }
    let files: Vec<PathBuf> = inputs.iter().map(|(f, _)| f.clone()).collect();
    if to_stdout {
        if files.len() != 1 {
            return usage_error("`-o -` prints one output to stdout; give exactly one FILE");
        }
        if targets.contains(&Target::Spirv) {
            return usage_error("`-o -` prints one text output; SPIR-V is binary (choose one --target of glsl330, gles300, wgsl)");
        }
    }
    let opts = args.common.options(targets);
    let comps = compile_all(&files, &opts);

    let mut reporter = Reporter::new(args.common.message_format);
    let mut code = 0;
    let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    let mut written: Vec<(PathBuf, &Path)> = Vec::new();
    for ((path, sub), c) in inputs.iter().zip(&comps) {
        reporter.compilation(c);
        code = code.max(exit_code(c));
        let Some(result) = c.result.as_ref().filter(|_| !c.has_errors()) else { continue };

        if to_stdout {
            let outputs: Vec<_> = result.artifacts.iter().filter(|a| a.target.is_some()).collect();
            if outputs.len() != 1 {
                let names: Vec<_> = outputs.iter().map(|a| a.file_name.as_str()).collect();
                return usage_error(&format!(
                    "`-o -` needs exactly one output, but this compile has {} ({}); narrow it with --target and --entry",
                    outputs.len(),
                    names.join(", ")
                ));
            }
            if let Err(e) = write_stdout(&outputs[0].contents) {
                reporter.plain(&e);
                code = code.max(EXIT_ERROR);
            }
            continue;
        }

        // `dir.join("")` would add a trailing separator.
        let out_dir = if sub.as_os_str().is_empty() { dir.clone() } else { dir.join(sub) };
        if let Some(a) = result.artifacts.iter().find(|a| written.iter().any(|(n, _)| *n == out_dir.join(&a.file_name))) {
            let (_, other) = written.iter().find(|(n, _)| *n == out_dir.join(&a.file_name)).expect("found above");
            reporter.plain(&Diagnostic::error_nowhere(format!(
                "`{}` is an output of both `{}` and `{}`; nothing was written for `{}` (compile them into different directories)",
                a.file_name,
                other.display(),
                path.display(),
                path.display()
            )));
            code = code.max(EXIT_ERROR);
            continue;
        }
        match umbrac::output::write_artifacts(&out_dir, &result.artifacts) {
            Ok(()) => written.extend(result.artifacts.iter().map(|a| (out_dir.join(&a.file_name), path.as_path()))),
            Err(e) => {
                reporter.plain(&Diagnostic::error_nowhere(format!("{e}; no output of `{}` was changed", path.display())));
                code = code.max(EXIT_ERROR);
            }
        }
    }
    code
}

fn check(args: &CheckArgs) -> u8 {
    let opts = args.common.options(Target::ALL.to_vec());
    let files: Vec<PathBuf> = match expand_inputs(&args.files) {
        Ok(i) => i.into_iter().map(|(f, _)| f).collect(),
        Err(e) => return usage_error(&e),
    };
    let comps = compile_all(&files, &opts);
    let mut reporter = Reporter::new(args.common.message_format);
    let mut code = 0;
    for c in &comps {
        reporter.compilation(c);
        code = code.max(exit_code(c));
    }
    code
}

fn reflect(args: &ReflectArgs) -> u8 {
    let opts = args.common.options(Target::ALL.to_vec());
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
fn compile_check(args: &CompileArgs, targets: Vec<Target>, inputs: &[(PathBuf, PathBuf)]) -> u8 {
    let opts = args.common.options(targets);
    let files: Vec<PathBuf> = inputs.iter().map(|(f, _)| f.clone()).collect();
    let comps = compile_all(&files, &opts);
    let mut reporter = Reporter::new(args.common.message_format);
    let mut code = 0;
    let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    // The outputs expected in each directory (a DIR input mirrors its
    // subdirectories under -o, as `compile` writes them).
    let mut expected: std::collections::BTreeMap<PathBuf, Vec<umbrac::Artifact>> = Default::default();
    for ((_, sub), c) in inputs.iter().zip(&comps) {
        reporter.compilation(c);
        code = code.max(exit_code(c));
        let out_dir = if sub.as_os_str().is_empty() { dir.clone() } else { dir.join(sub) };
        let slot = expected.entry(out_dir).or_default();
        if let Some(result) = c.result.as_ref().filter(|_| !c.has_errors()) {
            slot.extend(result.artifacts.iter().cloned());
        }
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
    let opts = args.common.options(Target::ALL.to_vec());
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
