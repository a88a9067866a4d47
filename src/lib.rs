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

pub mod bindgen;
pub mod build;
pub mod diag;
pub mod emit;
#[cfg(feature = "golden")]
pub mod golden;
pub mod lower;
pub mod output;
pub mod sema;
pub mod source;
pub mod syntax;

#[cfg(feature = "render")]
pub mod render;

use std::path::{Path, PathBuf};

pub use diag::{Diagnostic, Diagnostics, Severity};
pub use emit::reflect_types::Reflection;
pub use lower::{Conventions, Lowered};
pub use source::{SourceMap, Span};

/// An output language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    Glsl330,
    Gles300,
    Wgsl,
    Spirv,
}

impl Target {
    pub const ALL: [Target; 4] = [Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Spirv];

    /// The name used on the command line and in the reflection manifest.
    pub fn name(self) -> &'static str {
        match self {
            Target::Glsl330 => "glsl330",
            Target::Gles300 => "gles300",
            Target::Wgsl => "wgsl",
            Target::Spirv => "spirv",
        }
    }

    pub fn from_name(s: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == s)
    }
}

/// What to compile and how.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Targets to emit; empty means all. The reflection manifest is always made.
    pub targets: Vec<Target>,
    /// `-D NAME[=VALUE]`.
    pub defines: Vec<(String, Option<String>)>,
    /// `-I DIR`, searched after the including file's directory.
    pub include_dirs: Vec<PathBuf>,
    /// Entry points to compile; empty means all.
    pub entries: Vec<String>,
    pub conventions: Conventions,
    /// Allow `#include` to reach files outside the input's directory and the
    /// include directories.
    pub allow_outside_includes: bool,
}

impl Options {
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

/// One output file's name and bytes.
#[derive(Clone, Debug)]
pub struct Artifact {
    /// File name without directory: `main_vs.330.vert`, `shadow.wgsl`, ...
    pub file_name: String,
    /// `None` for the reflection manifest.
    pub target: Option<Target>,
    /// The entry point, for per-entry-point outputs (the GLSL files).
    pub entry: Option<String>,
    pub contents: Vec<u8>,
}

impl Artifact {
    /// The contents as text (SPIR-V is binary; this is lossy for it).
    pub fn text(&self) -> std::borrow::Cow<'_, str> {
        String::from_utf8_lossy(&self.contents)
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
            s.push_str(&format!("error: {} more errors not shown\n", self.suppressed_errors));
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
    match syntax::read_source(path) {
        Ok(text) => {
            let root = sources.add(name, Some(path.to_path_buf()), text, None);
            on_compiler_stack(move || run(sources, root, opts))
        }
        Err(d) => Compilation { sources, diagnostics: vec![d], suppressed_errors: 0, result: None },
    }
}

/// Compiles text held in memory. `name` is shown in diagnostics and gives
/// the output stem; `#include`s resolve against `name`'s directory.
pub fn compile_source(name: &str, text: &str, opts: &Options) -> Compilation {
    let mut sources = SourceMap::new();
    let root = sources.add(name, Some(PathBuf::from(name)), text.to_string(), None);
    on_compiler_stack(move || run(sources, root, opts))
}

/// Stack size of the thread each compilation runs on.
///
/// The stages recurse over the program's nesting, which the limits in
/// [`syntax`] and [`sema`] bound, and naga's backends recurse over
/// expression trees with large frames (about 44 KiB per level in the GLSL
/// writer). The deepest program the limits accept needs under 8 MiB even
/// in debug builds; the caller's stack may be as small as 2 MiB (test
/// threads), so every compilation gets its own. 32 MiB keeps a 4x margin
/// and stays within glibc's cache of thread stacks (40 MiB), so repeated
/// compilations reuse one already-mapped stack (a 64 MiB stack was mapped
/// afresh each time: four times the page faults, ~30 us per compile).
pub const COMPILER_STACK_SIZE: usize = 32 << 20;

/// Runs `job` on a thread with [`COMPILER_STACK_SIZE`] bytes of stack (on
/// the current thread if none can be started). A panic, which would be a
/// bug in umbrac, becomes an internal compiler error.
fn on_compiler_stack(job: impl FnOnce() -> Compilation + Send) -> Compilation {
    let mut job = Some(job);
    let ran = std::thread::scope(|s| {
        let thread = std::thread::Builder::new().name("umbrac".into()).stack_size(COMPILER_STACK_SIZE);
        match thread.spawn_scoped(s, || job.take().map(|j| j())) {
            Ok(handle) => Some(handle.join()),
            Err(_) => None,
        }
    });
    let result = match ran {
        Some(joined) => joined,
        None => std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job.take().map(|j| j()))),
    };
    match result {
        Ok(Some(c)) => c,
        Ok(None) => panicked("the compilation did not run"),
        Err(payload) => {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            panicked(&format!("the compiler panicked: {msg}"))
        }
    }
}

fn panicked(msg: &str) -> Compilation {
    Compilation { sources: SourceMap::new(), diagnostics: vec![Diagnostic::bug(msg, None)], suppressed_errors: 0, result: None }
}

/// The output stem of an input path: `shaders/shadow.das` -> `shadow`.
pub fn stem_of(name: &str) -> String {
    Path::new(name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "shader".into())
}

fn run(mut sources: SourceMap, root: source::FileId, opts: &Options) -> Compilation {
    let mut diags = Diagnostics::new();
    let parse_opts = syntax::ParseOptions {
        defines: opts.defines.clone(),
        include_dirs: opts.include_dirs.clone(),
        entries: opts.entries.clone(),
        allow_outside_includes: opts.allow_outside_includes,
    };
    let program = syntax::parse(&mut sources, root, &parse_opts, &mut diags);
    let checked = if diags.has_errors() { None } else { sema::check(&program, &mut diags) };
    let result = checked.filter(|_| !diags.has_errors()).and_then(|checked| {
        let lowered = match lower::lower(&checked, opts.conventions) {
            Ok(l) => l,
            Err(d) => {
                diags.push(d);
                return None;
            }
        };
        let root_name = sources.file(root).name.clone();
        match emit::emit(&lowered, &stem_of(&root_name), &root_name, &opts.targets()) {
            Ok((artifacts, reflection)) => Some(Compiled { artifacts, reflection, lowered }),
            Err(d) => {
                diags.push(d);
                None
            }
        }
    });
    let suppressed_errors = diags.suppressed();
    Compilation { sources, diagnostics: diags.into_vec(), suppressed_errors, result }
}
