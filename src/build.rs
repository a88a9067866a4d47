//! Compiling shaders from a build script (`build.rs`).
//!
//! ```no_run
//! // build.rs, with `[build-dependencies] umbrac = { version = "...", default-features = false }`
//! umbrac::build::Build::new()
//!     .file("shaders/scene.das")
//!     .variant("shaders/scene.das", "scene_soft", &[("PCF_RADIUS", Some("2"))])
//!     .include_dir("shaders/include")
//!     .run();
//! ```
//!
//! ```ignore
//! // src/main.rs: one module per variant (`scene`, `scene_soft`).
//! include!(concat!(env!("OUT_DIR"), "/umbrac/shaders.rs"));
//! ```
//!
//! For each variant (a file, its defines and an output name) the build
//! compiles the file, writes the outputs into `OUT_DIR/umbrac/NAME/` and the
//! Rust module ([`crate::bindgen`]) into `OUT_DIR/umbrac/NAME.rs`;
//! `OUT_DIR/umbrac/shaders.rs` includes every module. It prints
//! `cargo:rerun-if-changed=` for every file each compilation read (the
//! inputs and all their `#include`s) and for every directory scanned, so
//! cargo reruns the script exactly when a shader changes.
//!
//! Compile errors are printed in full (codespan text with file:line:col) on
//! stderr, which cargo shows for a failed build script, and as one
//! `cargo:warning=` line each; [`Build::run`] then prints a short summary
//! and exits with status 1, so `cargo build` fails. [`Build::compile`] returns the error
//! instead.

use std::fmt;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use crate::bindgen::{self, BindgenOptions};
use crate::{Artifact, Compilation, Conventions, Options, Target};

/// One shader variant: a file compiled with some defines under a name.
#[derive(Clone, Debug)]
pub struct Variant {
    pub file: PathBuf,
    /// The Rust module's name and the output directory's name.
    pub name: String,
    /// Defines of this variant, after the build-wide ones.
    pub defines: Vec<(String, Option<String>)>,
}

/// A build of shader variants; see the module docs.
#[derive(Clone, Debug, Default)]
pub struct Build {
    variants: Vec<Variant>,
    dirs: Vec<PathBuf>,
    options: Options,
    out_dir: Option<PathBuf>,
    bytemuck: Option<bool>,
    no_bindings: bool,
    quiet: bool,
}

/// What one variant produced.
#[derive(Clone, Debug)]
pub struct Built {
    pub variant: Variant,
    /// Directory holding the emitted files (`OUT_DIR/umbrac/NAME`).
    pub dir: PathBuf,
    /// The generated Rust module (`OUT_DIR/umbrac/NAME.rs`), if bindings are on.
    pub module: Option<PathBuf>,
    /// Every file the compilation read, includes too.
    pub files_read: Vec<PathBuf>,
}

/// Everything a build produced.
#[derive(Clone, Debug)]
pub struct Output {
    pub built: Vec<Built>,
    /// `OUT_DIR/umbrac/shaders.rs`, which includes every module.
    pub index: Option<PathBuf>,
}

/// Why a build failed. `Display` is the short summary; `details` holds the
/// rendered diagnostics.
#[derive(Debug)]
pub struct Error {
    pub summary: String,
    pub details: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.summary)
    }
}

impl std::error::Error for Error {}

impl Build {
    pub fn new() -> Self {
        Build::default()
    }

    /// Compiles `file` with no extra defines into a module named after its stem.
    pub fn file(mut self, file: impl AsRef<Path>) -> Self {
        let file = file.as_ref().to_path_buf();
        let name = crate::stem_of(&file.to_string_lossy());
        self.variants.push(Variant { file, name, defines: vec![] });
        self
    }

    /// Compiles `file` with `defines` into a module named `name`.
    pub fn variant(mut self, file: impl AsRef<Path>, name: &str, defines: &[(&str, Option<&str>)]) -> Self {
        self.variants.push(Variant {
            file: file.as_ref().to_path_buf(),
            name: name.to_string(),
            defines: defines.iter().map(|(n, v)| (n.to_string(), v.map(str::to_string))).collect(),
        });
        self
    }

    /// Compiles the programs under `dir` (as the CLI finds them: every
    /// `*.das` file in it and its subdirectories, except in directories
    /// named `include` and hidden entries; [`crate::batch::programs_under`]),
    /// each into a module named after its stem. Adding a file reruns the
    /// build.
    pub fn dir(mut self, dir: impl AsRef<Path>) -> Self {
        self.dirs.push(dir.as_ref().to_path_buf());
        self
    }

    /// Targets to emit; default all. The manifest is always made.
    pub fn targets(mut self, targets: &[Target]) -> Self {
        self.options.targets = targets.to_vec();
        self
    }

    /// A define for every variant (`-D NAME[=VALUE]`).
    pub fn define(mut self, name: &str, value: Option<&str>) -> Self {
        self.options.defines.push((name.to_string(), value.map(str::to_string)));
        self
    }

    /// An include directory (`-I DIR`).
    pub fn include_dir(mut self, dir: impl AsRef<Path>) -> Self {
        self.options.include_dirs.push(dir.as_ref().to_path_buf());
        self
    }

    /// daslang's `daslib` directory, for `require daslib/NAME` (`--daslib DIR`).
    pub fn daslib(mut self, dir: impl AsRef<Path>) -> Self {
        self.options.daslib = Some(dir.as_ref().to_path_buf());
        self
    }

    /// Clip-space conventions of the WGSL/SPIR-V outputs (default portable).
    pub fn conventions(mut self, c: Conventions) -> Self {
        self.options.conventions = c;
        self
    }

    /// Let `#include` reach files outside the input's directory and the
    /// include directories.
    pub fn allow_outside_includes(mut self, allow: bool) -> Self {
        self.options.allow_outside_includes = allow;
        self
    }

    /// Where to write; default `$OUT_DIR`.
    pub fn out_dir(mut self, dir: impl AsRef<Path>) -> Self {
        self.out_dir = Some(dir.as_ref().to_path_buf());
        self
    }

    /// Derive `bytemuck::Pod`/`Zeroable` in the bindings (default true).
    pub fn bytemuck(mut self, on: bool) -> Self {
        self.bytemuck = Some(on);
        self
    }

    /// Write only the shader outputs, no Rust modules.
    pub fn without_bindings(mut self) -> Self {
        self.no_bindings = true;
        self
    }

    /// Print nothing on stdout/stderr (no `cargo:` lines); for tests.
    pub fn quiet(mut self) -> Self {
        self.quiet = true;
        self
    }

    /// Runs the build; on failure prints the diagnostics and a summary and
    /// exits with status 1, which fails `cargo build` (a panic would add a
    /// backtrace into umbrac's sources to what cargo shows).
    pub fn run(self) -> Output {
        match self.compile() {
            Ok(o) => o,
            Err(e) => {
                eprintln!("error: {}", e.summary);
                std::process::exit(1)
            }
        }
    }

    /// Runs the build and returns what it produced, or every error.
    pub fn compile(&self) -> Result<Output, Error> {
        let out_root = match &self.out_dir {
            Some(d) => d.clone(),
            None => PathBuf::from(std::env::var_os("OUT_DIR").ok_or_else(|| Error {
                summary: "OUT_DIR is not set: run from a build script or call Build::out_dir".into(),
                details: String::new(),
            })?),
        }
        .join("umbrac");

        let mut variants = self.variants.clone();
        for dir in &self.dirs {
            self.cargo(&format!("rerun-if-changed={}", dir.display()));
            let found = crate::batch::programs_under(dir).map_err(|e| Error { summary: format!("cannot list shader directory {}: {e}", dir.display()), details: String::new() })?;
            for f in found {
                let name = crate::stem_of(&f.path.to_string_lossy());
                variants.push(Variant { file: f.path, name, defines: vec![] });
            }
        }
        if variants.is_empty() {
            return Err(Error { summary: "no shader files to compile (Build::file, ::variant or ::dir)".into(), details: String::new() });
        }
        for (i, v) in variants.iter().enumerate() {
            if !valid_name(&v.name) {
                return Err(Error { summary: format!("variant name `{}` of {} is not a Rust identifier", v.name, v.file.display()), details: String::new() });
            }
            if variants[..i].iter().any(|o| o.name == v.name) {
                return Err(Error { summary: format!("two shader variants are named `{}`; give them different names", v.name), details: String::new() });
            }
        }

        let comps = self.compile_all(&variants);
        let mut failed = Vec::new();
        let mut details = String::new();
        let mut built = Vec::new();
        let mut modules = Vec::new();
        for (v, c) in variants.iter().zip(&comps) {
            let mut files_read = c.files_read();
            let mut seen = std::collections::HashSet::new();
            files_read.retain(|f| seen.insert(f.clone()));
            for f in &files_read {
                self.cargo(&format!("rerun-if-changed={}", f.display()));
            }
            if files_read.is_empty() {
                self.cargo(&format!("rerun-if-changed={}", v.file.display()));
            }
            self.report(c, &mut details);
            let Some(result) = c.result.as_ref().filter(|_| !c.has_errors()) else {
                failed.push(v.file.display().to_string());
                continue;
            };
            let dir = out_root.join(&v.name);
            write(&dir, &result.artifacts)?;
            remove_stale(&dir, &result.artifacts);
            let module = if self.no_bindings {
                None
            } else {
                let opts = BindgenOptions { module_name: Some(v.name.clone()), bytemuck: self.bytemuck.unwrap_or(true), sources: true };
                let text = bindgen::generate(result, &opts).map_err(|e| Error { summary: format!("{}: {e}", v.file.display()), details: String::new() })?;
                let file_name = format!("{}.rs", v.name);
                write(&out_root, &[Artifact { file_name: file_name.clone(), target: None, entry: None, contents: text.into_bytes() }])?;
                modules.push(file_name);
                Some(out_root.join(format!("{}.rs", v.name)))
            };
            built.push(Built { variant: v.clone(), dir, module, files_read });
        }
        if !failed.is_empty() {
            let summary = format!("umbrac: {} shader file(s) failed to compile: {} (diagnostics above)", failed.len(), failed.join(", "));
            return Err(Error { summary, details });
        }
        let index = if self.no_bindings {
            None
        } else {
            let mut text = String::from("// @generated by umbrac: every shader module of this build.\n");
            for m in &modules {
                text.push_str(&format!("include!(concat!(env!(\"OUT_DIR\"), \"/umbrac/{m}\"));\n"));
            }
            if self.out_dir.is_some() {
                // Not under OUT_DIR: include by absolute path.
                text = String::from("// @generated by umbrac: every shader module of this build.\n");
                for m in &modules {
                    text.push_str(&format!("include!({:?});\n", out_root.join(m).display().to_string()));
                }
            }
            write(&out_root, &[Artifact { file_name: "shaders.rs".into(), target: None, entry: None, contents: text.into_bytes() }])?;
            Some(out_root.join("shaders.rs"))
        };
        Ok(Output { built, index })
    }

    fn options_for(&self, v: &Variant) -> Options {
        let mut o = self.options.clone();
        o.defines.extend(v.defines.iter().cloned());
        o
    }

    /// Compiles the variants in parallel, as the CLI does
    /// ([`crate::batch::compile_many`]).
    fn compile_all(&self, variants: &[Variant]) -> Vec<Compilation> {
        let opts: Vec<Options> = variants.iter().map(|v| self.options_for(v)).collect();
        let jobs: Vec<crate::batch::Job> = variants.iter().zip(&opts).map(|(v, opts)| crate::batch::Job { path: &v.file, opts }).collect();
        crate::batch::compile_many(&jobs, crate::batch::default_workers())
    }

    fn cargo(&self, line: &str) {
        if !self.quiet {
            let mut out = std::io::stdout().lock();
            let _ = writeln!(out, "cargo:{line}");
        }
    }

    /// Prints the diagnostics: in full on stderr, one `cargo:warning=` line each.
    fn report(&self, c: &Compilation, details: &mut String) {
        if c.diagnostics.is_empty() && c.result.is_some() {
            return;
        }
        let text = c.render_diagnostics();
        details.push_str(&text);
        if self.quiet {
            return;
        }
        let _ = std::io::stderr().lock().write_all(text.as_bytes());
        for d in &c.diagnostics {
            let severity = match d.severity {
                crate::Severity::Warning => "warning",
                crate::Severity::Error => "error",
                crate::Severity::Bug => "internal compiler error",
            };
            let place = d
                .span
                .and_then(|s| c.sources.line_col(s))
                .map(|(f, line, col)| format!("{}:{line}:{col}: ", c.sources.file(f).name))
                .unwrap_or_default();
            self.cargo(&format!("warning={place}{severity}: {}", d.message.replace('\n', " ")));
        }
        if c.result.is_none() && c.diagnostics.is_empty() {
            self.cargo("warning=umbrac: compilation failed without a diagnostic");
        }
    }
}

fn valid_name(s: &str) -> bool {
    s.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Removes outputs of an earlier build that this one no longer makes.
fn remove_stale(dir: &Path, artifacts: &[Artifact]) {
    for file in crate::output::stale_outputs(dir, artifacts) {
        let _ = std::fs::remove_file(file);
    }
}

/// Writes files atomically, leaving unchanged ones alone (their mtimes too).
fn write(dir: &Path, artifacts: &[Artifact]) -> Result<(), Error> {
    let changed: Vec<Artifact> = artifacts.iter().filter(|a| std::fs::read(dir.join(&a.file_name)).ok().as_deref() != Some(&a.contents[..])).cloned().collect();
    if changed.is_empty() {
        return Ok(());
    }
    crate::output::write_artifacts(dir, &changed).map_err(|e| Error { summary: format!("umbrac: {e}"), details: String::new() })
}
