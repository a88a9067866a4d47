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
    /// Files compiled in every variant of a spec: (file, spec).
    specs: Vec<(PathBuf, SpecSource)>,
    dirs: Vec<PathBuf>,
    /// `None`: `OUT_DIR/umbrac-cache`; `Some(None)`: no cache.
    cache: Option<Option<PathBuf>>,
    options: Options,
    out_dir: Option<PathBuf>,
    bytemuck: Option<bool>,
    no_bindings: bool,
    quiet: bool,
}

#[derive(Clone, Debug)]
enum SpecSource {
    Spec(crate::variants::Spec),
    #[cfg(feature = "spec")]
    Toml(PathBuf),
}

/// One module to build: a file, its defines, and where it goes.
#[derive(Clone, Debug)]
struct Planned {
    variant: Variant,
    /// For a spec's variant, the file's module (its stem) holding the
    /// variant's module.
    group: Option<String>,
    /// The manifest's `source`: the file's name, or its path under a `dir`.
    source_name: String,
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

    /// Compiles `file` with no extra defines into a module named after its
    /// stem, made a Rust identifier (`08_shadow.das` -> `_08_shadow`,
    /// `bindgen::module_name_of`).
    pub fn file(mut self, file: impl AsRef<Path>) -> Self {
        let file = file.as_ref().to_path_buf();
        let name = crate::bindgen::module_name_of(&crate::stem_of(&file.to_string_lossy()));
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

    /// Compiles `file` in every variant of `spec` (named variants and the
    /// product of its axes, [`crate::variants`]) into one module named
    /// after the file's stem, holding a module per variant and a
    /// `VARIANTS` table of `(name, defines)`; outputs go to
    /// `OUT_DIR/umbrac/STEM/VARIANT/`.
    pub fn variants(mut self, file: impl AsRef<Path>, spec: &crate::variants::Spec) -> Self {
        self.specs.push((file.as_ref().to_path_buf(), SpecSource::Spec(spec.clone())));
        self
    }

    /// [`Build::variants`] with the spec read from a TOML file (the
    /// format of `umbrac compile --variants`; feature `spec`). The build
    /// reruns when it changes.
    #[cfg(feature = "spec")]
    pub fn variants_file(mut self, file: impl AsRef<Path>, spec: impl AsRef<Path>) -> Self {
        self.specs.push((file.as_ref().to_path_buf(), SpecSource::Toml(spec.as_ref().to_path_buf())));
        self
    }

    /// The compile cache's directory; default `OUT_DIR/umbrac-cache`
    /// (docs/build.md, "The cache").
    pub fn cache_dir(mut self, dir: impl AsRef<Path>) -> Self {
        self.cache = Some(Some(dir.as_ref().to_path_buf()));
        self
    }

    /// Compile everything, reading and writing no cache.
    pub fn no_cache(mut self) -> Self {
        self.cache = Some(None);
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

    /// A daslang tree or install, for `require` (`--daslang-root DIR`).
    pub fn daslang_root(mut self, dir: impl AsRef<Path>) -> Self {
        self.options.daslang_root = Some(dir.as_ref().to_path_buf());
        self
    }

    /// Where `require PREFIX/NAME` finds `NAME.das` (`--module PREFIX=DIR`).
    pub fn module(mut self, prefix: &str, dir: impl AsRef<Path>) -> Self {
        self.options.modules.push((prefix.to_string(), dir.as_ref().to_path_buf()));
        self
    }

    /// Clip-space conventions of the WGSL/SPIR-V outputs (default portable).
    pub fn conventions(mut self, c: Conventions) -> Self {
        self.options.conventions = c;
        self
    }

    /// How GLSL declares the loose uniforms (`--gl-uniforms`; default plain).
    pub fn gl_uniforms(mut self, g: crate::GlUniforms) -> Self {
        self.options.gl_uniforms = g;
        self
    }

    /// Compile for devices with `n` of `limit` (`--limit NAME=N`).
    pub fn limit(mut self, limit: crate::Limit, n: u64) -> Self {
        self.options.limits.push((limit, n));
        self
    }

    /// Make going over any guaranteed device minimum an error, not only over
    /// what devices in use report (`--strict-limits`).
    pub fn strict_limits(mut self, strict: bool) -> Self {
        self.options.strict_limits = strict;
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

        let err = |summary: String| Error { summary, details: String::new() };
        let file_name = |f: &Path| f.file_name().map_or_else(|| f.display().to_string(), |n| n.to_string_lossy().into_owned());
        let mut planned: Vec<Planned> =
            self.variants.iter().map(|v| Planned { variant: v.clone(), group: None, source_name: file_name(&v.file) }).collect();
        for dir in &self.dirs {
            self.cargo(&format!("rerun-if-changed={}", dir.display()));
            let found = crate::batch::programs_under(dir).map_err(|e| err(format!("cannot list shader directory {}: {e}", dir.display())))?;
            for f in found {
                let name = crate::bindgen::module_name_of(&crate::stem_of(&f.path.to_string_lossy()));
                let mut rel: Vec<String> = f.subdir.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
                rel.push(file_name(&f.path));
                planned.push(Planned { variant: Variant { file: f.path, name, defines: vec![] }, group: None, source_name: rel.join("/") });
            }
        }
        for (file, source) in &self.specs {
            let variants = match source {
                SpecSource::Spec(s) => s.expand().map_err(|e| err(format!("variants of {}: {e}", file.display())))?,
                #[cfg(feature = "spec")]
                SpecSource::Toml(path) => {
                    self.cargo(&format!("rerun-if-changed={}", path.display()));
                    read_spec(path)?
                }
            };
            let group = crate::stem_of(&file.to_string_lossy());
            for v in variants {
                planned.push(Planned { variant: Variant { file: file.clone(), name: v.name, defines: v.defines }, group: Some(group.clone()), source_name: file_name(file) });
            }
        }
        if planned.is_empty() {
            return Err(err("no shader files to compile (Build::file, ::variant, ::variants or ::dir)".into()));
        }
        let mut seen = std::collections::HashSet::new();
        for p in &planned {
            let v = &p.variant;
            if !valid_name(&v.name) || p.group.as_ref().is_some_and(|g| !valid_name(g)) {
                return Err(err(format!("variant name `{}` of {} is not a Rust identifier", p.group.as_ref().unwrap_or(&v.name), v.file.display())));
            }
            let top = p.group.as_ref().unwrap_or(&v.name);
            if !seen.insert((p.group.clone(), v.name.clone())) || (p.group.is_none() && planned.iter().any(|o| o.group.as_ref() == Some(top))) {
                return Err(err(format!("two shader variants are named `{top}`; give them different names")));
            }
        }

        let bytemuck = self.bytemuck.unwrap_or(true);
        let units: Vec<crate::batch::Unit> = planned
            .iter()
            .map(|p| {
                let mut opts = self.options_for(&p.variant);
                opts.source_name = Some(p.source_name.clone());
                let extra = if self.no_bindings { String::new() } else { format!("bindgen module={} bytemuck={bytemuck}", p.variant.name) };
                crate::batch::Unit { path: &p.variant.file, opts, extra }
            })
            .collect();
        let derive = |i: usize, compiled: &crate::Compiled| -> Result<Vec<Artifact>, String> {
            let opts = BindgenOptions { module_name: Some(planned[i].variant.name.clone()), bytemuck, sources: true };
            let text = bindgen::generate(compiled, &opts)?;
            Ok(vec![Artifact { file_name: BINDINGS.into(), target: None, entry: None, contents: text.into_bytes() }])
        };
        let cache = match &self.cache {
            Some(None) => None,
            Some(Some(d)) => Some(crate::cache::Cache::new(d, crate::cache::DEFAULT_MAX_BYTES)),
            None => Some(crate::cache::Cache::new(out_root.with_file_name("umbrac-cache"), crate::cache::DEFAULT_MAX_BYTES)),
        };
        let derive_ref: Option<&crate::batch::Derive> = if self.no_bindings { None } else { Some(&derive) };
        let (outcomes, stats) = crate::batch::compile_cached(&units, crate::batch::default_workers(), cache.as_ref(), crate::batch::Hooks { derive: derive_ref, ready: None, output_hashes: false, process_ends: false });
        if stats.stored > 0 {
            if let Some(c) = cache.as_ref().filter(|c| c.may_need_trim()) {
                c.trim();
            }
        }

        // Which outputs already on disk need not be read back (see
        // `output::stamps`): kept beside the cache.
        let stamps = match &cache {
            Some(c) => crate::output::stamps::Stamps::load(c.dir(), &out_root),
            None => Default::default(),
        };
        let mut failed = Vec::new();
        let mut details = String::new();
        let mut built = Vec::new();
        let mut modules: Vec<String> = Vec::new();
        let mut groups: Vec<(String, Vec<(String, String)>)> = Vec::new();
        let mut rerun = std::collections::BTreeSet::new();
        for (p, o) in planned.iter().zip(&outcomes) {
            let v = &p.variant;
            let mut files_read = o.files_read.clone();
            let mut seen = std::collections::HashSet::new();
            files_read.retain(|f| seen.insert(f.clone()));
            rerun.extend(files_read.iter().cloned());
            if files_read.is_empty() {
                rerun.insert(v.file.clone());
            }
            // A unit that shares another's compilation shares its report too.
            if let Some(c) = &o.compilation {
                self.report(c, &mut details);
            }
            let Some(artifacts) = &o.artifacts else {
                failed.push(v.file.display().to_string());
                continue;
            };
            let hashed = o.hashes.len() == artifacts.len();
            let (mut outputs, mut output_hashes, mut bindings) = (Vec::new(), Vec::new(), Vec::new());
            for (i, a) in artifacts.iter().enumerate() {
                let hash = o.hashes.get(i).copied();
                if a.file_name == BINDINGS {
                    bindings.push((a.clone(), hash));
                } else {
                    outputs.push(a.clone());
                    output_hashes.extend(hash);
                }
            }
            let (dir, module_dir) = match &p.group {
                None => (out_root.join(&v.name), out_root.clone()),
                Some(g) => (out_root.join(g).join(&v.name), out_root.join(g)),
            };
            let known = hashed.then_some(crate::output::Known { hashes: &output_hashes, stamps: &stamps });
            write(&dir, &outputs, known.as_ref())?;
            remove_stale(&dir, &outputs);
            let module = match bindings.into_iter().next() {
                Some((b, hash)) => {
                    let file_name = format!("{}.rs", v.name);
                    let hash: Vec<crate::cache::Key> = hash.into_iter().collect();
                    let known = hashed.then_some(crate::output::Known { hashes: &hash, stamps: &stamps });
                    write(&module_dir, &[Artifact { file_name: file_name.clone(), ..b }], known.as_ref())?;
                    match &p.group {
                        None => modules.push(file_name),
                        Some(g) => {
                            let at = groups.iter().position(|(n, _)| n == g).unwrap_or_else(|| {
                                groups.push((g.clone(), Vec::new()));
                                modules.push(format!("{g}.rs"));
                                groups.len() - 1
                            });
                            groups[at].1.push((v.name.clone(), crate::variants::describe(&v.defines)));
                        }
                    }
                    Some(module_dir.join(format!("{}.rs", v.name)))
                }
                None => None,
            };
            built.push(Built { variant: v.clone(), dir, module, files_read });
        }
        stamps.save();
        for f in &rerun {
            self.cargo(&format!("rerun-if-changed={}", f.display()));
        }
        if !failed.is_empty() {
            failed.dedup();
            let summary = format!("umbrac: {} shader file(s) failed to compile: {} (diagnostics above)", failed.len(), failed.join(", "));
            return Err(Error { summary, details });
        }
        let include_of = |rel: &str| {
            if self.out_dir.is_some() {
                // Not under OUT_DIR: include by absolute path.
                format!("include!({:?});\n", out_root.join(rel).display().to_string())
            } else {
                format!("include!(concat!(env!(\"OUT_DIR\"), \"/umbrac/{rel}\"));\n")
            }
        };
        for (g, variants) in &groups {
            let mut text = format!("// @generated by umbrac: the variants of `{g}`, one module each.\npub mod {g} {{\n");
            for (name, _) in variants {
                text.push_str("    ");
                text.push_str(&include_of(&format!("{g}/{name}.rs")));
            }
            text.push_str("    /// Every variant: its module's name and its defines.\n    pub const VARIANTS: &[(&str, &str)] = &[\n");
            for (name, defines) in variants {
                text.push_str(&format!("        ({name:?}, {defines:?}),\n"));
            }
            text.push_str("    ];\n}\n");
            write(&out_root, &[Artifact { file_name: format!("{g}.rs"), target: None, entry: None, contents: text.into_bytes() }], None)?;
        }
        let index = if self.no_bindings {
            None
        } else {
            let mut text = String::from("// @generated by umbrac: every shader module of this build.\n");
            for m in &modules {
                text.push_str(&include_of(m));
            }
            write(&out_root, &[Artifact { file_name: "shaders.rs".into(), target: None, entry: None, contents: text.into_bytes() }], None)?;
            Some(out_root.join("shaders.rs"))
        };
        Ok(Output { built, index })
    }

    fn options_for(&self, v: &Variant) -> Options {
        let mut o = self.options.clone();
        o.defines.extend(v.defines.iter().cloned());
        o
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
                crate::Severity::Note => "note",
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

/// The name a variant's bindings travel under in its cache entry.
const BINDINGS: &str = "umbrac-bindings.rs";

#[cfg(feature = "spec")]
/// Reads and expands a TOML variant spec; errors, the expansion's too,
/// point into it.
fn read_spec(path: &Path) -> Result<Vec<crate::variants::Variant>, Error> {
    let text = std::fs::read_to_string(path).map_err(|e| Error { summary: format!("cannot read the variant spec {}: {e}", path.display()), details: String::new() })?;
    let mut map = crate::SourceMap::new();
    let id = map.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
    let parsed = crate::variants::Spec::parse_toml_spanned(&map, id);
    let expanded = parsed.and_then(|(spec, spans)| spec.expand().map_err(|e| crate::Diagnostic::error(e.0, spans.of(e.1)).with_label("here")));
    expanded.map_err(|d| {
        let details = d.render(&map);
        eprint!("{details}");
        Error { summary: format!("umbrac: the variant spec {} is not valid (diagnostics above)", path.display()), details }
    })
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
fn write(dir: &Path, artifacts: &[Artifact], known: Option<&crate::output::Known<'_>>) -> Result<(), Error> {
    crate::output::write_outputs_known(dir, artifacts, crate::output::Unchanged::Leave, known).map_err(|e| Error { summary: format!("umbrac: {e}"), details: String::new() })
}
