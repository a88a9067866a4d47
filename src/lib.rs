//! umbrac: the daslang shader DSL to GLSL 330, GLSL ES 3.00, WGSL and SPIR-V.
//!
//! The pipeline runs in one direction, one module per stage:
//!
//! ```text
//! source ─► syntax (preprocess, lex, parse) ─► sema (resolve, type-check)
//!        ─► lower (naga IR, validated) ─► emit (GLSL 330, ES 300, WGSL, SPIR-V, reflection)
//! ```
//!
//! [`compile_file`] and [`compile_source`] run all of it and return a
//! [`Compilation`]: the artifacts, or diagnostics that point into the
//! [`source::SourceMap`]. Nothing is written to disk here; see
//! [`output`] for atomic writes.

#[macro_use]
mod serialize;

pub mod batch;
pub mod bindgen;
pub mod bundle;
pub mod build;
pub mod cache;
pub mod depfile;
pub mod jobs;
pub mod diag;
pub mod emit;
#[cfg(feature = "golden")]
pub mod golden;
pub mod lower;
pub mod output;
#[cfg(feature = "spec")]
pub mod project;
pub mod rerun;
pub mod run;
mod sealed;
pub mod sema;
#[cfg(feature = "scene")]
pub mod scene;
pub mod source;
pub mod syntax;
pub mod target;
pub mod variants;
pub mod workspace;
#[cfg(any(feature = "cli", feature = "preview"))]
pub mod watch;

#[cfg(feature = "render")]
pub mod render;
#[cfg(feature = "lsp")]
pub mod lsp;
#[cfg(feature = "preview")]
pub mod preview;

use std::path::{Path, PathBuf};

pub use diag::{Diagnostic, Diagnostics, Severity};
pub use emit::reflect_types::Reflection;
pub use emit::limits::Limit;
pub use lower::{Conventions, GlUniforms, Lowered};
pub use source::{SourceMap, Span};
pub use target::{Artifact, Target};

/// umbrac's version (what the playground page shows).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// What to compile and how.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Targets to emit; empty means every target that can run the program
    /// (`Target::defaults`: GLSL 330 and ES 3.00, or GLSL 430 and ES 3.10
    /// for a program with compute, storage buffers or images; WGSL and
    /// SPIR-V). The reflection manifest is always made.
    pub targets: Vec<Target>,
    /// `-D NAME[=VALUE]`.
    pub defines: Vec<(String, Option<String>)>,
    /// `-I DIR`, searched after the including file's directory.
    pub include_dirs: Vec<PathBuf>,
    /// Entry points to compile; empty means all.
    pub entries: Vec<String>,
    pub conventions: Conventions,
    /// How GLSL declares the loose uniforms (`--gl-uniforms`): plain
    /// `uniform T name;` (the default) or std140 blocks.
    pub gl_uniforms: GlUniforms,
    /// `--limit NAME=N`: compile for devices with more of a resource than
    /// the targets' minimums (`emit::limits`).
    pub limits: Vec<(Limit, u64)>,
    /// `--strict-limits`: going over any guaranteed minimum is an error, not
    /// only over what devices in use report (a warning by default;
    /// docs/targets.md, "Device limits").
    pub strict_limits: bool,
    /// Allow `#include` to reach files outside the input's directory and the
    /// include directories.
    pub allow_outside_includes: bool,
    /// `--daslib DIR`: daslang's `daslib` directory, where `require
    /// daslib/NAME` finds `NAME.das`.
    pub daslib: Option<PathBuf>,
    /// `--daslang-root DIR`: a daslang tree or install, for `require`:
    /// `DIR/daslib`, the prefixes its `modules/*/.das_module` files
    /// register and its folders named after a prefix (docs/language.md,
    /// "Modules").
    pub daslang_root: Option<PathBuf>,
    /// `--module PREFIX=DIR`: `require PREFIX/NAME` finds `DIR/NAME.das`
    /// (before the daslang tree's registrations).
    pub modules: Vec<(String, PathBuf)>,
    /// The name the outputs record for the input (the manifest's `source`,
    /// the bindings' header); `None`: the name diagnostics show, the path
    /// as given. The CLI and [`build`] set a name that does not depend on
    /// the working directory or the machine (docs/build.md, "Determinism").
    pub source_name: Option<String>,
}

impl Options {
    /// The targets requested, sorted; every target when none are (what a
    /// cache key records: the default set follows from the source).
    pub fn targets(&self) -> Vec<Target> {
        if self.targets.is_empty() {
            Target::ALL.to_vec()
        } else {
            let mut t = self.targets.clone();
            t.sort();
            t.dedup();
            t
        }
    }
}

/// A successful compilation's products.
#[derive(Debug)]
pub struct Compiled {
    pub artifacts: Vec<Artifact>,
    pub reflection: Reflection,
    pub lowered: Lowered,
}

impl Compiled {
    pub fn artifact(&self, file_name: &str) -> Option<&Artifact> {
        self.artifacts.iter().find(|a| a.file_name == file_name)
    }
}

/// Everything one compilation produced: the files it read, its
/// diagnostics, and its products when there were no errors.
#[derive(Debug)]
pub struct Compilation {
    pub sources: SourceMap,
    pub diagnostics: Vec<Diagnostic>,
    /// Errors dropped past the cap of [`Diagnostics::MAX_ERRORS`].
    pub suppressed_errors: usize,
    pub result: Option<Compiled>,
}

impl Compilation {
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(|d| d.is_error()) || self.result.is_none()
    }

    /// All diagnostics rendered as plain codespan-reporting text.
    pub fn render_diagnostics(&self) -> String {
        let mut s: String = self.diagnostics.iter().map(|d| d.render(&self.sources)).collect();
        if self.suppressed_errors > 0 {
            s.push_str(&Diagnostic::suppressed(self.suppressed_errors).render(&self.sources));
        }
        s
    }

    /// Paths of every file read (the input and its includes), for build
    /// scripts' `rerun-if-changed`.
    pub fn files_read(&self) -> Vec<PathBuf> {
        self.sources.files().filter_map(|(_, f)| f.path.clone()).collect()
    }
}

/// Compiles a file from disk.
pub fn compile_file(path: &Path, opts: &Options) -> Compilation {
    let mut sources = SourceMap::new();
    let name = path.display().to_string();
    match read_input(path) {
        Ok(text) => {
            let root = sources.add(name.clone(), Some(path.to_path_buf()), text, None);
            on_compiler_stack(&name, move || run(sources, root, opts))
        }
        Err(d) => Compilation { sources, diagnostics: vec![d], suppressed_errors: 0, result: None },
    }
}

/// Compiles text held in memory. `name` is shown in diagnostics and gives
/// the output stem; `#include`s resolve against `name`'s directory.
pub fn compile_source(name: &str, text: &str, opts: &Options) -> Compilation {
    let mut sources = SourceMap::new();
    let root = sources.add(name, Some(PathBuf::from(name)), text.to_string(), None);
    on_compiler_stack(name, move || run(sources, root, opts))
}

/// Stack size of the threads umbrac starts for compilations.
///
/// The stages recurse over the program's nesting, which the limits in
/// [`syntax`] and [`sema`] bound. Measured on the deepest programs the
/// limits accept (`tests/compiler/limits.rs`): at most 0.4 MiB of stack in optimised
/// builds, but up to 5.5 MiB in unoptimised ones, where umbrac's own frames
/// are large. 32 MiB keeps a wide margin and stays within glibc's cache of
/// thread stacks (40 MiB), so repeated compilations reuse a mapped stack.
pub const COMPILER_STACK_SIZE: usize = 32 << 20;

/// Whether [`compile_file`] and [`compile_source`] run on the caller's
/// thread. In optimised builds (no debug assertions) the deepest accepted
/// program needs under 0.4 MiB, so any thread with Rust's default 2 MiB
/// (or the 8 MiB main thread) is enough, and staying on the caller's thread
/// saves 100-300 us per compile that moving the work and its results
/// between threads (and cores) costs. Unoptimised builds need more than a
/// 2 MiB thread has and start a [`COMPILER_STACK_SIZE`] thread instead.
/// (A build with debug assertions off *and* no optimisation would be
/// misjudged; cargo's default profiles never combine them.) WebAssembly
/// (the playground) has no threads to start: there the module links with
/// a stack sized for the compiler (web/playground/wasm/build.rs).
const RUNS_ON_CALLERS_STACK: bool = !cfg!(debug_assertions) || cfg!(target_family = "wasm");

thread_local! {
    /// Set on threads started by [`spawn_compiler_thread`]: they have the
    /// large stack already, so compilations run on them directly.
    static HAS_COMPILER_STACK: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Starts a scoped thread with [`COMPILER_STACK_SIZE`] bytes of stack on
/// which compilations run directly, whatever the build (the CLI's and
/// [`build`]'s workers).
pub fn spawn_compiler_thread<'scope, T: Send + 'scope>(
    scope: &'scope std::thread::Scope<'scope, '_>,
    f: impl FnOnce() -> T + Send + 'scope,
) -> std::io::Result<std::thread::ScopedJoinHandle<'scope, T>> {
    std::thread::Builder::new().name("umbrac".into()).stack_size(COMPILER_STACK_SIZE).spawn_scoped(scope, move || {
        HAS_COMPILER_STACK.set(true);
        f()
    })
}

/// Whether a compilation may run on the calling thread (the rule of
/// [`on_compiler_stack`]): a thread kept between compilations keeps the
/// validator and SPIR-V writer each thread holds (`crate::workspace`).
pub(crate) fn stack_suffices() -> bool {
    RUNS_ON_CALLERS_STACK || HAS_COMPILER_STACK.get()
}

/// Runs `job` where its stack is sure to suffice: on the calling thread
/// when [`RUNS_ON_CALLERS_STACK`] or the thread is one of umbrac's,
/// otherwise on a new [`COMPILER_STACK_SIZE`] thread (or the current one if
/// none can be started). A panic, which would be a bug in umbrac, becomes an
/// internal compiler error naming `name`, the file being compiled.
fn on_compiler_stack<F: FnOnce() -> Compilation + Send>(name: &str, job: F) -> Compilation {
    use std::panic::{catch_unwind, AssertUnwindSafe};
    let result = if RUNS_ON_CALLERS_STACK || HAS_COMPILER_STACK.get() {
        catch_unwind(AssertUnwindSafe(job))
    } else {
        let mut job = Some(job);
        // The caller's open documents stand for files on the new thread too.
        let texts = syntax::overlay::current();
        let run = |j: F| match texts.clone() {
            Some(t) => syntax::overlay::with(t, j),
            None => j(),
        };
        let ran = std::thread::scope(|s| spawn_compiler_thread(s, || job.take().map(run)).ok().map(|h| h.join()));
        match (ran, job) {
            (Some(joined), _) => joined.map(|c| c.unwrap_or_else(|| panicked("the compilation did not run"))),
            (None, Some(job)) => catch_unwind(AssertUnwindSafe(job)),
            (None, None) => Ok(panicked("the compilation did not run")),
        }
    };
    match result {
        Ok(c) => c,
        Err(payload) => panicked(&format!("the compiler panicked while compiling `{name}`: {}", diag::panic_message(&*payload))),
    }
}

fn panicked(msg: &str) -> Compilation {
    Compilation { sources: SourceMap::new(), diagnostics: vec![Diagnostic::bug(msg, None)], suppressed_errors: 0, result: None }
}

/// The output stem of an input path: `shaders/shadow.das` -> `shadow`.
pub fn stem_of(name: &str) -> String {
    Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "shader".into())
}

/// A file read and preprocessed, not yet parsed: what the cache key
/// ([`cache::Key`]) is computed from, and where a compilation goes on from
/// when the key is not in the cache.
#[derive(Debug)]
pub struct Preprocessed {
    sources: SourceMap,
    /// The root's name in diagnostics (kept apart: an unreadable root is
    /// not in `sources`).
    name: String,
    root: source::FileId,
    unit: syntax::Unit,
    diags: Diagnostics,
}

impl Preprocessed {
    /// Every file read (the input, its includes, the `-D` definitions).
    pub fn sources(&self) -> &SourceMap {
        &self.sources
    }

    /// The root file's name in diagnostics.
    pub fn root_name(&self) -> &str {
        &self.name
    }

    /// The preprocessed token stream of the whole translation unit (the
    /// input, its includes, and the modules it requires, as far as
    /// shaders reach them).
    pub fn tokens(&self) -> &[syntax::token::Token] {
        &self.unit.tokens
    }

    /// Whether reading or preprocessing failed (then [`Preprocessed::compile`]
    /// only reports why).
    pub fn has_errors(&self) -> bool {
        self.diags.has_errors()
    }

    /// Paths of every file read, as [`Compilation::files_read`] gives them.
    pub fn files_read(&self) -> Vec<PathBuf> {
        self.sources.files().filter_map(|(_, f)| f.path.clone()).collect()
    }

    /// Paths `#include`s and `require`s found no file at (see
    /// [`syntax::Unit::probed`]).
    pub fn probed(&self) -> &[PathBuf] {
        &self.unit.probed
    }

    /// Goes on from preprocessing to every output (`opts` must be the
    /// options it was preprocessed with). Runs where [`compile_file`] runs
    /// and, like it, turns a panic into an internal error.
    pub fn compile(self, opts: &Options) -> Compilation {
        let name = self.root_name().to_string();
        on_compiler_stack(&name, move || finish(self, opts))
    }
}

/// Reads and preprocesses a file from disk: the first step of
/// [`compile_file`], alone.
pub fn preprocess_file(path: &Path, opts: &Options) -> Preprocessed {
    let mut sources = SourceMap::new();
    let mut diags = Diagnostics::new();
    let name = path.display().to_string();
    match read_input(path) {
        Ok(text) => {
            let root = sources.add(name, Some(path.to_path_buf()), text, None);
            preprocess_root(sources, root, opts)
        }
        Err(d) => {
            diags.push(d);
            Preprocessed { sources, name, root: 0, unit: Default::default(), diags }
        }
    }
}

/// Reads an input file. The outputs are named after it (`shadow.das` ->
/// `shadow.wgsl`), and an output name is text: a lossy one would not be
/// the input's, so a file name that is not UTF-8 is an error.
fn read_input(path: &Path) -> Result<String, Diagnostic> {
    if path.file_stem().is_some_and(|s| s.to_str().is_none()) {
        let name = path.display();
        return Err(Diagnostic::error_nowhere(format!("the file name of `{name}` is not UTF-8, and the outputs are named after it"))
            .with_note("help: rename the file"));
    }
    syntax::read_source(path)
}

fn parse_options(opts: &Options) -> syntax::ParseOptions {
    syntax::ParseOptions {
        defines: opts.defines.clone(),
        include_dirs: opts.include_dirs.clone(),
        entries: opts.entries.clone(),
        allow_outside_includes: opts.allow_outside_includes,
        daslib: opts.daslib.iter().cloned().collect(),
        daslang_root: opts.daslang_root.clone(),
        module_dirs: opts.modules.clone(),
    }
}

fn preprocess_root(mut sources: SourceMap, root: source::FileId, opts: &Options) -> Preprocessed {
    let mut diags = Diagnostics::new();
    let unit = if syntax::root_fits(&sources, root, &mut diags) {
        syntax::preprocess_unit(&mut sources, root, &parse_options(opts), &mut diags)
    } else {
        Default::default()
    };
    let name = sources.file(root).name.clone();
    Preprocessed { sources, name, root, unit, diags }
}

fn run(sources: SourceMap, root: source::FileId, opts: &Options) -> Compilation {
    finish(preprocess_root(sources, root, opts), opts)
}

/// Everything after preprocessing: parse, check, lower, emit.
fn finish(pre: Preprocessed, opts: &Options) -> Compilation {
    finish_keeping(pre, opts, false).0
}

/// Compiles a file (read through [`syntax::overlay`] like any other) on
/// the calling thread, keeping the checked program, which
/// [`workspace`] answers queries from. A panic is the caller's to catch.
pub(crate) fn analyze_file(path: &Path, opts: &Options) -> (Compilation, Option<sema::tree::Program>) {
    match read_input(path) {
        Ok(text) => {
            let mut sources = SourceMap::new();
            let root = sources.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
            finish_keeping(preprocess_root(sources, root, opts), opts, true)
        }
        Err(d) => (Compilation { sources: SourceMap::new(), diagnostics: vec![d], suppressed_errors: 0, result: None }, None),
    }
}

/// [`finish`], also returning the checked program when `keep` (the
/// compiler alone drops it as soon as it is lowered).
fn finish_keeping(pre: Preprocessed, opts: &Options, keep: bool) -> (Compilation, Option<sema::tree::Program>) {
    let Preprocessed { sources, root, unit, mut diags, .. } = pre;
    if diags.has_errors() || sources.is_empty() {
        let suppressed_errors = diags.suppressed();
        return (Compilation { sources, diagnostics: diags.into_vec(), suppressed_errors, result: None }, None);
    }
    let program = syntax::parse_unit(&sources, root, unit, &parse_options(opts), &mut diags);
    let requested = if opts.targets.is_empty() { Vec::new() } else { opts.targets() };
    let checked = if diags.has_errors() { None } else { sema::check_for_targets(&program, &requested, &mut diags) };
    let targets = match &checked {
        Some(p) if requested.is_empty() => Target::defaults(p.needs_compute()).to_vec(),
        _ => requested,
    };
    // Each tree is dropped as soon as the next stage has been built from
    // it, so the next stage's allocations reuse its memory, still in cache.
    drop(program);
    let mut kept = None;
    let result = checked.filter(|_| !diags.has_errors()).and_then(|checked| {
        let lowered = lower::lower(&checked, lower::LowerOptions { conventions: opts.conventions, gl_uniforms: opts.gl_uniforms, spirv: targets.contains(&Target::Spirv) });
        if keep {
            kept = Some(checked);
        } else {
            drop(checked);
        }
        let lowered = match lowered {
            Ok(l) => l,
            Err(d) => {
                diags.push(d);
                return None;
            }
        };
        let mut over = Vec::new();
        emit::limits::check(&lowered, &targets, &opts.limits, opts.strict_limits, &mut over);
        let refused = over.iter().any(|d| d.is_error());
        for d in over {
            diags.push(d);
        }
        if refused {
            return None;
        }
        let root_name = &sources.file(root).name;
        let source_name = opts.source_name.as_deref().unwrap_or(root_name);
        match emit::emit(&lowered, &stem_of(root_name), source_name, &targets) {
            Ok((artifacts, reflection)) => Some(Compiled { artifacts, reflection, lowered }),
            Err(d) => {
                diags.push(d);
                None
            }
        }
    });
    let suppressed_errors = diags.suppressed();
    (Compilation { sources, diagnostics: diags.into_vec(), suppressed_errors, result }, kept)
}
