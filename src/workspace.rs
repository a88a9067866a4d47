//! The compiler as a service for editors: a workspace of files in which
//! open documents stand for the files on disk (also where they are
//! `#include`d or `require`d), compilations of any file in it, and queries
//! over the last good analysis of each: what is at a position, where it is
//! declared, who uses it, which symbols a file declares.
//!
//! `umbrac lsp` (`crate::lsp`) speaks the protocol over this; the queries
//! work on byte offsets into files, the protocol's UTF-16 positions are
//! converted by [`position_to_offset`] and [`offset_to_position`].

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::diag::{Diagnostic, Severity};
use crate::sema::builtins::name_of;
use crate::sema::tree::{self, ExprKind, GlobalKind, Stmt};
use crate::sema::types::{Ty, TyDisplay};
use crate::source::{SourceMap, Span};
use crate::syntax::overlay;
use crate::{Compilation, Options};

/// An open document.
#[derive(Clone, Debug)]
struct Document {
    text: String,
    version: i32,
}

/// Open documents over the disk, the options files compile with, and the
/// last good analysis of every file checked.
#[derive(Default)]
pub struct Workspace {
    options: Options,
    docs: HashMap<PathBuf, Document>,
    analyses: HashMap<PathBuf, Arc<Index>>,
}

/// A diagnostic placed in the file that was checked: one in an included
/// or required file sits at the `#include`/`require` line that brought it
/// in, its message naming the file.
#[derive(Clone, Debug, PartialEq)]
pub struct FileDiagnostic {
    pub severity: Severity,
    /// Byte range in the checked file.
    pub start: usize,
    pub end: usize,
    /// The message, its label, notes and help, as the CLI prints them.
    pub message: String,
    /// Other places the diagnostic points at (path, byte range, message).
    pub related: Vec<(PathBuf, usize, usize, String)>,
    /// For one placed at an `#include`/`require` line: where it is in the
    /// included file (path, byte range, message without the prefix).
    pub origin: Option<(PathBuf, usize, usize, String)>,
}

/// What a check of one file found.
#[derive(Debug)]
pub struct Checked {
    /// The document version the check compiled (`None` for a file not open).
    pub version: Option<i32>,
    pub diagnostics: Vec<FileDiagnostic>,
    /// Every file the compilation read (the root, includes, modules).
    pub files_read: Vec<PathBuf>,
}

impl Workspace {
    pub fn new(options: Options) -> Self {
        Workspace { options, ..Default::default() }
    }

    pub fn options(&self) -> &Options {
        &self.options
    }

    /// New options; every analysis is dropped (it was made with others).
    pub fn set_options(&mut self, options: Options) {
        self.options = options;
        self.analyses.clear();
    }

    /// Opens a document or replaces its text.
    pub fn set_document(&mut self, path: &Path, text: String, version: i32) {
        self.docs.insert(overlay::normalize(path), Document { text, version });
    }

    /// Closes a document: the file on disk counts again.
    pub fn close_document(&mut self, path: &Path) {
        self.docs.remove(&overlay::normalize(path));
    }

    /// The open document's version.
    pub fn version(&self, path: &Path) -> Option<i32> {
        self.docs.get(&overlay::normalize(path)).map(|d| d.version)
    }

    /// The text a compilation would read for `path` now.
    pub fn text(&self, path: &Path) -> Option<String> {
        match self.docs.get(&overlay::normalize(path)) {
            Some(d) => Some(d.text.clone()),
            None => std::fs::read_to_string(path).ok(),
        }
    }

    /// The open documents, by normalized path.
    pub fn documents(&self) -> impl Iterator<Item = &Path> {
        self.docs.keys().map(PathBuf::as_path)
    }

    /// Compiles `path` with the open documents standing for their files,
    /// keeping the analysis when the program checked. Never panics: a
    /// compiler panic is an internal-error diagnostic.
    pub fn check(&mut self, path: &Path) -> Checked {
        let path = overlay::normalize(path);
        let version = self.version(&path);
        let (diagnostics, files_read, index) = self.compile(&path);
        if let Some(index) = index {
            self.analyses.insert(path, Arc::new(index));
        }
        Checked { version, diagnostics, files_read }
    }

    /// The last good analysis of `path` as a root, or of a root that read it.
    pub fn index(&self, path: &Path) -> Option<Arc<Index>> {
        let path = overlay::normalize(path);
        if let Some(i) = self.analyses.get(&path) {
            return Some(i.clone());
        }
        self.analyses.values().find(|i| i.file(&path).is_some()).cloned()
    }

    /// Forgets a file's analysis (it was deleted).
    pub fn forget(&mut self, path: &Path) {
        self.analyses.remove(&overlay::normalize(path));
    }

    /// Compiles where the stack suffices (this thread when it may, as
    /// `compile_source` does, keeping the thread's validator and SPIR-V
    /// writer; otherwise a compiler thread, where the checked program,
    /// which is not `Send`, stays): the placed diagnostics, the files
    /// read, the index.
    fn compile(&self, path: &Path) -> (Vec<FileDiagnostic>, Vec<PathBuf>, Option<Index>) {
        let texts: overlay::Texts = Arc::new(self.docs.iter().map(|(p, d)| (p.clone(), d.text.clone())).collect());
        let (opts, project) = match self.options_for(path) {
            Ok(o) => o,
            Err(e) => return (vec![project_error(&e)], e.0.files().filter_map(|(_, f)| f.path.clone()).collect(), None),
        };
        let opts = &opts;
        let failed = |msg: &str| (place_diagnostics(&crate::panicked(msg), path), Vec::new(), None);
        let run = || {
            let job = || {
                let (c, program) = overlay::with(texts, || crate::analyze_file(path, opts));
                let diagnostics = place_diagnostics(&c, path);
                let mut files_read = c.files_read();
                files_read.extend(project.clone());
                (diagnostics, files_read, program.map(|p| Index::new(&p, c)))
            };
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(job)).unwrap_or_else(|payload| {
                failed(&format!("the compiler panicked while compiling `{}`: {}", path.display(), crate::diag::panic_message(&*payload)))
            })
        };
        if crate::stack_suffices() {
            return run();
        }
        std::thread::scope(|s| match crate::spawn_compiler_thread(s, run) {
            Ok(h) => h.join().unwrap_or_else(|_| failed("the compilation thread failed")),
            Err(e) => failed(&format!("cannot start a compilation thread: {e}")),
        })
    }
}

impl Workspace {
    /// What `target` writes for `path`, the open documents standing for
    /// their files: each output's file name and text; when it does not
    /// compile, its diagnostics as a check places them. SPIR-V is binary
    /// and is refused.
    pub fn output(&self, path: &Path, target: crate::Target) -> Result<Vec<(String, String)>, Vec<FileDiagnostic>> {
        let path = overlay::normalize(path);
        let nowhere = |msg: String| vec![FileDiagnostic { severity: Severity::Error, start: 0, end: 0, message: msg, related: Vec::new(), origin: None }];
        if target == crate::Target::Spirv {
            return Err(nowhere("SPIR-V is binary: choose a text target (glsl330, gles300, glsl430, gles310, wgsl)".into()));
        }
        let texts: overlay::Texts = Arc::new(self.docs.iter().map(|(p, d)| (p.clone(), d.text.clone())).collect());
        let mut opts = self.options_for(&path).map_err(|e| vec![project_error(&e)])?.0;
        opts.targets = vec![target];
        let run = || {
            let job = || {
                let c = overlay::with(texts, || crate::compile_file(&path, &opts));
                match &c.result {
                    Some(r) if !c.has_errors() => Ok(r
                        .artifacts
                        .iter()
                        .filter(|a| a.target == Some(target))
                        .map(|a| (a.file_name.clone(), String::from_utf8_lossy(&a.contents).into_owned()))
                        .collect()),
                    _ => Err(place_diagnostics(&c, &path)),
                }
            };
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(job))
                .unwrap_or_else(|payload| Err(nowhere(format!("the compiler panicked while compiling `{}`: {}", path.display(), crate::diag::panic_message(&*payload)))))
        };
        if crate::stack_suffices() {
            return run();
        }
        std::thread::scope(|s| match crate::spawn_compiler_thread(s, run) {
            Ok(h) => h.join().unwrap_or_else(|_| Err(nowhere("the compilation thread failed".into()))),
            Err(e) => Err(nowhere(format!("cannot start a compilation thread: {e}"))),
        })
    }

    /// The workspace's options over the project file found from `path`
    /// (`crate::project`: what the workspace's options set wins), and
    /// which file that was.
    #[cfg(feature = "spec")]
    pub fn options_for(&self, path: &Path) -> Result<(Options, Option<PathBuf>), crate::project::Error> {
        crate::project::options_for(path, self.options.clone())
    }

    /// Without the TOML reader there is no project file.
    #[cfg(not(feature = "spec"))]
    pub fn options_for(&self, _path: &Path) -> Result<(Options, Option<PathBuf>), Box<(SourceMap, Diagnostic)>> {
        Ok((self.options.clone(), None))
    }
}

/// A project file that cannot be used, at the start of the file checked.
fn project_error(e: &(SourceMap, Diagnostic)) -> FileDiagnostic {
    let (map, d) = e;
    let mut fd = place(d, map, &|_| None);
    if let Some((id, r)) = d.span.and_then(|s| map.locate(s)) {
        let (_, line, col) = map.line_col(d.span.unwrap_or_default()).unwrap_or_default();
        fd.origin = map.file(id).path.as_deref().map(|p| (overlay::normalize(p), r.start, r.end, fd.message.clone()));
        fd.message = format!("{}:{line}:{col}: {}", map.file(id).name, fd.message);
    }
    fd
}

/// Places each diagnostic of a compilation of `root` in `root`.
fn place_diagnostics(c: &Compilation, root: &Path) -> Vec<FileDiagnostic> {
    let map = &c.sources;
    let in_root = |span: Span| map.locate(span).filter(|(id, _)| map.file(*id).path.as_deref().map(overlay::normalize).as_deref() == Some(root));
    // A file without entry points (host code, an include, a module) is no
    // program: the CLI refuses it as an input, an editor says nothing.
    let not_a_program = |d: &&Diagnostic| d.code == Some(crate::diag::Code::NoEntryPoints);
    let mut out: Vec<FileDiagnostic> = c.diagnostics.iter().filter(|d| !not_a_program(d)).map(|d| place(d, map, &in_root)).collect();
    if c.suppressed_errors > 0 {
        let note = Diagnostic::suppressed(c.suppressed_errors);
        out.push(FileDiagnostic { severity: note.severity, start: 0, end: 0, message: note.message, related: Vec::new(), origin: None });
    }
    out
}

fn place(d: &Diagnostic, map: &SourceMap, in_root: &dyn Fn(Span) -> Option<(usize, std::ops::Range<usize>)>) -> FileDiagnostic {
    let mut message = d.message.clone();
    if let Some(label) = Some(&d.label).filter(|l| !l.is_empty()) {
        message.push_str(&format!(" ({label})"));
    }
    for n in &d.notes {
        message.push('\n');
        message.push_str(n);
    }
    let related = d
        .secondary
        .iter()
        .filter_map(|(s, m)| {
            let (id, r) = map.locate(*s)?;
            Some((map.file(id).path.clone().map(|p| overlay::normalize(&p))?, r.start, r.end, m.clone()))
        })
        .collect();
    let mut fd = FileDiagnostic { severity: d.severity, start: 0, end: 0, message, related, origin: None };
    let Some(span) = d.span else { return fd };
    if let Some((_, r)) = in_root(span) {
        fd.start = r.start;
        fd.end = r.end;
        return fd;
    }
    // In an included or required file: at the outermost site in the root.
    if let Some(site) = map.include_chain(span).into_iter().rev().find_map(in_root) {
        let (_, line, col) = map.line_col(span).unwrap_or_default();
        let name = map.file_of(span.start).map(|id| map.file(id).name.clone()).unwrap_or_default();
        if let Some((id, r)) = map.locate(span) {
            fd.origin = map.file(id).path.as_deref().map(|p| (overlay::normalize(p), r.start, r.end, fd.message.clone()));
        }
        fd.message = format!("{name}:{line}:{col}: {}", fd.message);
        fd.start = site.1.start;
        fd.end = site.1.end;
    }
    fd
}

/// What a name or expression refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Symbol {
    Global(usize),
    Const(usize),
    Function(usize),
    EntryPoint(usize),
    Struct(usize),
    Field(usize, u32),
    /// A local of a function (`Function` index, or entry point index + the
    /// function count) by its id.
    Local(usize, usize),
}

/// A place in the sources an [`Index`] holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    pub path: PathBuf,
    /// Byte range in that file.
    pub start: usize,
    pub end: usize,
}

/// The kind of a declaration, for document symbols.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SymbolKind {
    EntryPoint,
    Function,
    Global,
    Constant,
    Struct,
}

/// A declaration a file holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DocumentSymbol {
    pub name: String,
    pub kind: SymbolKind,
    /// Its type, or its stage for an entry point.
    pub detail: String,
    /// The declaration's name.
    pub start: usize,
    pub end: usize,
}

/// An expression's span and what to say about it.
#[derive(Clone, Debug)]
struct Occurrence {
    span: Span,
    ty: Arc<str>,
    symbol: Option<Symbol>,
    /// A builtin call's name and signature.
    builtin: Option<String>,
}

/// The answers of one good analysis: kept with the sources it was made
/// from, so that its byte offsets stay meaningful until the next one.
pub struct Index {
    sources: SourceMap,
    /// Every expression, sorted by start.
    occurrences: Vec<Occurrence>,
    /// Declarations: name span, name, kind, type or stage.
    decls: HashMap<Symbol, (Span, String, String)>,
    /// What `.` completes on a declaration's value.
    shapes: HashMap<Symbol, Shape>,
    /// Each function's span and key (`Symbol::Local`'s first field).
    functions: Vec<(Span, usize)>,
    /// Field names of each struct.
    fields: Vec<Vec<(String, String)>>,
    /// The reflection manifest's text, when the compilation emitted one,
    /// parsed on the first hover that needs it (not on every edit).
    manifest: Option<String>,
    manifest_parsed: std::sync::OnceLock<Option<serde_json::Value>>,
    /// The text outputs: entry point (`None`: the whole module), target, code.
    emitted: Vec<(Option<String>, crate::Target, String)>,
    /// Helper functions by name (overloads): label and parameter labels.
    signatures: HashMap<String, Vec<Signature>>,
}

/// A function's signature as shown, and its parameters'.
pub type Signature = (String, Vec<String>);

/// Lines of an output a hover shows.
const HOVER_CODE_LINES: usize = 40;

/// What follows a `.` on a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Struct(usize),
    Vector(u8),
}

fn shape_of(ty: &Ty) -> Option<Shape> {
    match ty {
        Ty::Struct(s) => Some(Shape::Struct(*s)),
        Ty::Vector(_, n) => Some(Shape::Vector(*n)),
        _ => None,
    }
}

/// A name to highlight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SemanticToken {
    /// Byte range in the file.
    pub start: usize,
    pub end: usize,
    pub kind: TokenKind,
    pub declaration: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenKind {
    Variable,
    Constant,
    Function,
    Struct,
    Field,
    BuiltinVariable,
    BuiltinFunction,
}

/// A completion item.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Completion {
    pub label: String,
    pub kind: CompletionKind,
    /// Its type or signature.
    pub detail: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompletionKind {
    Local,
    Global,
    Constant,
    Function,
    Struct,
    Field,
    Builtin,
    /// A variable annotation after `@`.
    Annotation,
    /// A builtin type's name.
    Type,
}

/// The annotations a shader global takes (`var @uniform @set = 1 x : T`).
const ANNOTATIONS: &[&str] = &["in", "out", "inout", "uniform", "location", "stage", "set", "binding", "format", "push_constant", "ssbo", "groupshared", "constant_id"];

/// Sampler type names (each checked against `SamplerKind::from_name` in a test).
const SAMPLER_NAMES: &[&str] = &["sampler2D", "sampler2DShadow", "sampler2DArray", "sampler2DArrayShadow", "sampler3D", "samplerCube", "samplerCubeShadow", "isampler2D", "usampler2D"];

/// Every builtin type name: scalars, vectors, matrices, samplers.
fn type_names() -> Vec<&'static str> {
    use crate::sema::types::Scalar;
    let mut out = Vec::new();
    for s in [Scalar::Float, Scalar::Int, Scalar::Uint, Scalar::Bool, Scalar::Half] {
        out.extend((1..=4).filter_map(|n| Ty::vec(s, n).builtin_name()));
    }
    out.extend((2..=4).flat_map(|c| (2..=4).filter_map(move |r| Ty::Matrix(c, r).builtin_name())));
    out.extend(SAMPLER_NAMES);
    out
}

/// What a hover shows.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hover {
    /// Markdown.
    pub text: String,
    /// The byte range it is about.
    pub start: usize,
    pub end: usize,
}

impl Index {
    fn new(p: &tree::Program, compilation: Compilation) -> Index {
        let structs = p.struct_names();
        let enums = p.enum_names();
        let show = |ty: &Ty| TyDisplay { ty, struct_names: &structs, enum_names: &enums }.to_string();
        let sources = compilation.sources;
        let mut decls = HashMap::new();
        let mut shapes = HashMap::new();
        for (i, g) in p.globals.iter().enumerate() {
            if !matches!(g.kind, GlobalKind::Builtin(_)) {
                decls.insert(Symbol::Global(i), (g.span, g.name.clone(), show(&g.ty)));
                shapes.extend(shape_of(&g.ty).map(|s| (Symbol::Global(i), s)));
            }
        }
        for (i, c) in p.consts.iter().enumerate() {
            decls.insert(Symbol::Const(i), (c.span, c.name.clone(), show(&c.ty)));
            shapes.extend(shape_of(&c.ty).map(|s| (Symbol::Const(i), s)));
        }
        let fields: Vec<Vec<(String, String)>> = p.structs.iter().map(|s| s.fields.iter().map(|(n, t, _)| (n.clone(), show(t))).collect()).collect();
        for (i, s) in p.structs.iter().enumerate() {
            decls.insert(Symbol::Struct(i), (name_within(&sources, s.span, &s.name), s.name.clone(), "struct".into()));
            for (k, (name, ty, span)) in s.fields.iter().enumerate() {
                decls.insert(Symbol::Field(i, k as u32), (*span, name.clone(), show(ty)));
            }
        }
        let nf = p.functions.len();
        let mut w = Walker { occurrences: Vec::new(), show: &show, types: HashMap::new(), func: 0 };
        let mut functions = Vec::new();
        let funcs = p.functions.iter().enumerate().chain(p.entry_points.iter().enumerate().map(|(i, e)| (nf + i, &e.func)));
        for (key, f) in funcs {
            functions.push((f.span, key));
            for (id, l) in f.locals.iter().enumerate() {
                shapes.extend(shape_of(&l.ty).map(|s| (Symbol::Local(key, id), s)));
            }
        }
        let mut signatures: HashMap<String, Vec<Signature>> = HashMap::new();
        for (i, f) in p.functions.iter().enumerate() {
            let params: Vec<String> = f.locals[..f.params].iter().map(|l| format!("{} : {}", l.name.as_str(), show(&l.ty))).collect();
            let label = format!("def {}({}) : {}", f.name, params.join("; "), show(&f.ret));
            signatures.entry(f.name.clone()).or_default().push((label.clone(), params));
            decls.insert(Symbol::Function(i), (name_within(&sources, f.span, &f.name), f.name.clone(), label));
            w.function(i, f, &mut decls);
        }
        for (i, e) in p.entry_points.iter().enumerate() {
            let stage = format!("{:?} entry point", e.stage).to_lowercase();
            decls.insert(Symbol::EntryPoint(i), (name_within(&sources, e.func.span, &e.name), e.name.clone(), stage));
            w.function(nf + i, &e.func, &mut decls);
        }
        let mut occurrences = w.occurrences;
        occurrences.sort_by_key(|o| (o.span.start, std::cmp::Reverse(o.span.end)));
        let manifest = compilation.result.as_ref().and_then(|r| r.artifacts.iter().find(|a| a.target.is_none())).and_then(|a| String::from_utf8(a.contents.clone()).ok());
        let emitted = compilation
            .result
            .into_iter()
            .flat_map(|r| r.artifacts)
            .filter_map(|a| Some((a.entry, a.target.filter(|t| *t != crate::Target::Spirv)?, String::from_utf8(a.contents).ok()?)))
            .collect();
        Index { sources, occurrences, decls, shapes, functions, fields, manifest, manifest_parsed: Default::default(), emitted, signatures }
    }

    /// The id and text of a file this analysis read.
    fn file(&self, path: &Path) -> Option<(usize, &str)> {
        self.sources.files().find(|(_, f)| f.path.as_deref().map(overlay::normalize).as_deref() == Some(path)).map(|(id, f)| (id, f.text.as_str()))
    }

    /// The text of `path` as this analysis read it (offsets are into it).
    pub fn text(&self, path: &Path) -> Option<&str> {
        self.file(&overlay::normalize(path)).map(|(_, t)| t)
    }

    fn global_offset(&self, path: &Path, offset: usize) -> Option<u32> {
        let (id, text) = self.file(&overlay::normalize(path))?;
        Some(self.sources.file(id).base + offset.min(text.len()) as u32)
    }

    fn location(&self, span: Span) -> Option<Location> {
        let (id, r) = self.sources.locate(span)?;
        Some(Location { path: overlay::normalize(self.sources.file(id).path.as_deref()?), start: r.start, end: r.end })
    }

    /// The innermost expression or declaration name at a byte offset.
    fn at(&self, path: &Path, offset: usize) -> Option<(Span, Option<Symbol>, Option<&Occurrence>)> {
        let at = self.global_offset(path, offset)?;
        let covers = |s: &Span| s.start <= at && at <= s.end && s.end > s.start;
        let occ = self.occurrences.iter().filter(|o| covers(&o.span)).min_by_key(|o| o.span.end - o.span.start);
        let decl = self.decls.iter().filter(|(_, (s, _, _))| covers(s)).min_by_key(|(_, (s, _, _))| s.end - s.start);
        match (occ, decl) {
            (_, Some((sym, (span, _, _)))) => Some((*span, Some(*sym), None)),
            (Some(o), None) => Some((o.span, o.symbol, Some(o))),
            (None, None) => None,
        }
    }

    /// What is at a byte offset of `path`: the type of a name or
    /// expression, a builtin's signature, a declaration's `//!` comment,
    /// and for a global what the manifest says of it.
    pub fn hover(&self, path: &Path, offset: usize) -> Option<Hover> {
        let (span, symbol, occ) = self.at(path, offset)?;
        let mut parts = Vec::new();
        if let Some(b) = occ.and_then(|o| o.builtin.as_ref()) {
            parts.push(format!("```das\n{b}\n```"));
            parts.push(builtin_doc(b.split('(').next().unwrap_or("")));
        } else if let Some((dspan, name, detail)) = symbol.and_then(|s| self.decls.get(&s)) {
            let what = match symbol {
                Some(Symbol::Struct(_)) => format!("struct {name}"),
                Some(Symbol::Function(_)) => detail.clone(),
                Some(Symbol::EntryPoint(_)) => format!("{name}: {detail}"),
                _ => format!("{name} : {detail}"),
            };
            parts.push(format!("```das\n{what}\n```"));
            if let Some(doc) = self.doc_comment(*dspan) {
                parts.push(doc);
            }
            if let Some(Symbol::EntryPoint(_)) = symbol {
                for (entry, target, code) in &self.emitted {
                    if entry.as_deref().is_none_or(|e| e == name) {
                        let lines: Vec<&str> = code.lines().collect();
                        let more = if lines.len() > HOVER_CODE_LINES { format!("\n... {} more lines", lines.len() - HOVER_CODE_LINES) } else { String::new() };
                        let lang = if *target == crate::Target::Wgsl { "wgsl" } else { "glsl" };
                        parts.push(format!("{}:\n```{lang}\n{}{more}\n```", target.name(), lines[..lines.len().min(HOVER_CODE_LINES)].join("\n")));
                    }
                }
            }
            let global = matches!(symbol, Some(Symbol::Global(_)));
            let manifest = || self.manifest_parsed.get_or_init(|| self.manifest.as_deref().and_then(|m| serde_json::from_str(m).ok())).as_ref();
            if let Some(m) = global.then(manifest).flatten() {
                let mut found = Vec::new();
                manifest_entries(m, name, &mut found);
                if !found.is_empty() {
                    parts.push(format!("manifest:\n```json\n{}\n```", found.join("\n")));
                }
            }
        } else if let Some(o) = occ {
            parts.push(format!("```das\n{}\n```", o.ty));
        }
        let (_, r) = self.sources.locate(span)?;
        Some(Hover { text: parts.join("\n\n"), start: r.start, end: r.end })
    }

    /// The `//!` lines right above a declaration.
    fn doc_comment(&self, span: Span) -> Option<String> {
        let (id, r) = self.sources.locate(span)?;
        let text = &self.sources.file(id).text;
        let line_start = text[..r.start].rfind('\n').map_or(0, |i| i + 1);
        let mut lines: Vec<&str> = Vec::new();
        for line in text[..line_start].lines().rev() {
            match line.trim_start().strip_prefix("//!") {
                Some(doc) => lines.push(doc.strip_prefix(' ').unwrap_or(doc)),
                None => break,
            }
        }
        lines.reverse();
        (!lines.is_empty()).then(|| lines.join("\n"))
    }

    /// Where the name at a byte offset is declared.
    pub fn definition(&self, path: &Path, offset: usize) -> Option<Location> {
        let (_, symbol, _) = self.at(path, offset)?;
        self.location(self.decls.get(&symbol?)?.0)
    }

    /// Every use of the name at a byte offset (and its declaration, first,
    /// when `with_declaration`), in every file the analysis read.
    pub fn references(&self, path: &Path, offset: usize, with_declaration: bool) -> Vec<Location> {
        let Some((_, Some(symbol), _)) = self.at(path, offset) else { return Vec::new() };
        let mut out = Vec::new();
        if with_declaration {
            out.extend(self.decls.get(&symbol).and_then(|d| self.location(d.0)));
        }
        let uses = self.occurrences.iter().filter(|o| o.symbol == Some(symbol)).filter_map(|o| self.location(o.span));
        for l in uses {
            if !out.contains(&l) {
                out.push(l);
            }
        }
        out
    }

    /// The declarations in `path`, in file order.
    pub fn symbols(&self, path: &Path) -> Vec<DocumentSymbol> {
        let path = overlay::normalize(path);
        let mut out: Vec<DocumentSymbol> = Vec::new();
        for (sym, (span, name, detail)) in &self.decls {
            let kind = match sym {
                Symbol::Global(_) => SymbolKind::Global,
                Symbol::Const(_) => SymbolKind::Constant,
                Symbol::Function(_) => SymbolKind::Function,
                Symbol::EntryPoint(_) => SymbolKind::EntryPoint,
                Symbol::Struct(_) => SymbolKind::Struct,
                Symbol::Field(..) | Symbol::Local(..) => continue,
            };
            if let Some(l) = self.location(*span).filter(|l| l.path == path) {
                out.push(DocumentSymbol { name: name.clone(), kind, detail: detail.clone(), start: l.start, end: l.end });
            }
        }
        out.sort_by_key(|s| s.start);
        out
    }

    /// The names in `path` for semantic highlighting, in file order and
    /// never overlapping: byte range, kind, and whether it is a declaration.
    pub fn semantic_tokens(&self, path: &Path) -> Vec<SemanticToken> {
        let path = overlay::normalize(path);
        let mut out: Vec<SemanticToken> = Vec::new();
        let kind_of = |sym: Symbol| match sym {
            Symbol::Global(_) | Symbol::Local(..) => TokenKind::Variable,
            Symbol::Const(_) => TokenKind::Constant,
            Symbol::Function(_) | Symbol::EntryPoint(_) => TokenKind::Function,
            Symbol::Struct(_) => TokenKind::Struct,
            Symbol::Field(..) => TokenKind::Field,
        };
        let mut push = |span: Span, kind: TokenKind, declaration: bool| {
            if let Some(l) = self.location(span).filter(|l| l.path == path && l.end > l.start) {
                out.push(SemanticToken { start: l.start, end: l.end, kind, declaration });
            }
        };
        for (sym, (span, name, _)) in &self.decls {
            if self.sources.slice(*span) == name.as_str() {
                push(*span, kind_of(*sym), true);
            }
        }
        for o in &self.occurrences {
            match (o.symbol, &o.builtin) {
                (Some(sym), _) => match self.decls.get(&sym) {
                    Some((_, name, _)) => {
                        if let Some(span) = self.name_in(o.span, name, sym) {
                            push(span, kind_of(sym), false);
                        }
                    }
                    // A builtin variable (`gl_Position`).
                    None => push(o.span, TokenKind::BuiltinVariable, false),
                },
                (None, Some(sig)) => {
                    let name = sig.split('(').next().unwrap_or("");
                    if self.sources.slice(o.span).starts_with(name) && !name.is_empty() {
                        push(Span::new(o.span.start, o.span.start + name.len() as u32), TokenKind::BuiltinFunction, false);
                    }
                }
                _ => {}
            }
        }
        out.sort_by_key(|t| (t.start, t.end));
        let mut last_end = 0;
        out.retain(|t| {
            let keep = t.start >= last_end;
            if keep {
                last_end = t.end;
            }
            keep
        });
        out
    }

    /// The signatures of the helper function whose call the offset of
    /// `text` is in, and which parameter it is at.
    pub fn signature_help(&self, text: &str, offset: usize) -> Option<(Vec<Signature>, usize)> {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let bytes = text.as_bytes();
        let (mut depth, mut commas) = (0usize, 0usize);
        let mut i = offset;
        // Back to the unmatched `(`, within a bounded stretch of the text.
        let open = loop {
            if i == 0 || offset - i > 4096 {
                return None;
            }
            i -= 1;
            match bytes[i] {
                b')' | b']' => depth += 1,
                b'(' | b'[' if depth > 0 => depth -= 1,
                b'(' => break i,
                b'[' => return None,
                b',' | b';' if depth == 0 => commas += 1,
                b'\n' if depth == 0 && offset - i > 1024 => return None,
                _ => {}
            }
        };
        let before = text[..open].trim_end();
        let name = &before[before.trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_').len()..];
        // A helper of the program's hides a builtin of the same name.
        if let Some(sigs) = self.signatures.get(name) {
            return Some((sigs.clone(), commas));
        }
        let builtin = crate::sema::builtins::signatures(name);
        (!builtin.is_empty()).then_some((builtin, commas))
    }

    /// Inlay hints for `path`: after each local whose type is inferred
    /// (`let k = ...`), the byte offset of its name's end and `: TYPE`.
    pub fn inlay_hints(&self, path: &Path) -> Vec<(usize, String)> {
        let path = overlay::normalize(path);
        let mut out: Vec<(usize, String)> = Vec::new();
        for (sym, (span, name, ty)) in &self.decls {
            // Locals the checker made up (no such name in the source) have none.
            if !matches!(sym, Symbol::Local(..)) || self.sources.slice(*span) != name.as_str() {
                continue;
            }
            let Some(l) = self.location(*span).filter(|l| l.path == path) else { continue };
            let written = self.text(&path).is_some_and(|t| t[l.end..].trim_start_matches([' ', '\t']).starts_with(':'));
            if !written {
                out.push((l.end, format!(": {ty}")));
            }
        }
        out.sort();
        out.dedup();
        out
    }

    /// The exact span of the name `name` in a use of it: the use itself,
    /// the field after the last `.`, or the callee of a call.
    fn name_in(&self, span: Span, name: &str, symbol: Symbol) -> Option<Span> {
        let text = self.sources.slice(span);
        if text == name {
            return Some(span);
        }
        let at = match symbol {
            Symbol::Field(..) => text.rfind(name)?,
            _ => {
                let s = name_within(&self.sources, span, name);
                return (s != span).then_some(s);
            }
        };
        Some(Span::new(span.start + at as u32, span.start + (at + name.len()) as u32))
    }

    /// The edits that rename the name at a byte offset to `new_name`,
    /// in every file the analysis read; an error says why it cannot be.
    pub fn rename(&self, path: &Path, offset: usize, new_name: &str) -> Result<Vec<Location>, String> {
        let Some((_, Some(symbol), _)) = self.at(path, offset) else { return Err("there is no name declared in this program here".into()) };
        let (decl, old, _) = self.decls.get(&symbol).ok_or("this name is not declared in this program")?;
        let ident = new_name.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && new_name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !ident {
            return Err(format!("`{new_name}` is not a name"));
        }
        if crate::syntax::token::Kw::from_name(new_name).is_some() {
            return Err(format!("`{new_name}` is a daslang keyword"));
        }
        if crate::sema::builtins::is_builtin(new_name) {
            return Err(format!("`{new_name}` is a builtin function"));
        }
        if crate::emit::glsl_names::is_reserved(new_name) || new_name.starts_with("gl_") {
            return Err(format!("`{new_name}` is reserved in GLSL"));
        }
        if naga::keywords::wgsl::RESERVED.contains(&new_name) {
            return Err(format!("`{new_name}` is reserved in WGSL"));
        }
        // A name it would collide with or shadow: fields of the same
        // struct, locals of the same function, any top-level name.
        let clash = self.decls.iter().find(|(other, (_, name, _))| {
            name == new_name
                && match (symbol, **other) {
                    (Symbol::Field(s, _), Symbol::Field(t, _)) => s == t,
                    (Symbol::Field(..), _) | (_, Symbol::Field(..)) => false,
                    (Symbol::Local(f, _), Symbol::Local(g, _)) => f == g,
                    (_, Symbol::Local(..)) => true,
                    _ => true,
                }
        });
        if let Some((_, (span, _, _))) = clash {
            let (id, line, col) = self.sources.line_col(*span).unwrap_or_default();
            return Err(format!("`{new_name}` is already declared at {}:{line}:{col}", self.sources.file(id).name));
        }
        let mut spans = vec![*decl];
        for o in self.occurrences.iter().filter(|o| o.symbol == Some(symbol)) {
            spans.push(self.name_in(o.span, old, symbol).ok_or_else(|| format!("cannot find `{old}` in one of its uses"))?);
        }
        spans.sort();
        spans.dedup();
        spans.into_iter().map(|s| self.location(s).ok_or_else(|| format!("a use of `{old}` is in no file on disk"))).collect()
    }

    /// What may be written at a byte offset of `text` (the document now;
    /// the analysis may be older): after `name.`, its fields or swizzle
    /// components; otherwise the names in scope and the builtins.
    pub fn completions(&self, path: &Path, text: &str, offset: usize) -> Vec<Completion> {
        let (mut out, builtins) = self.completions_here(path, text, offset);
        if builtins {
            out.extend(builtin_completions().iter().cloned());
            out.dedup_by(|a, b| a.label == b.label);
        }
        out
    }

    /// [`Index::completions`] without the builtins, which are the same
    /// everywhere ([`builtin_completions`]): what this place adds, and
    /// whether the builtins follow it.
    pub fn completions_here(&self, path: &Path, text: &str, offset: usize) -> (Vec<Completion>, bool) {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
        let before = &text[..offset];
        let start = before.trim_end_matches(word).len();
        let at = self.global_offset(path, start).unwrap_or(u32::MAX);
        let func = self.functions.iter().filter(|(s, _)| s.start <= at && at <= s.end).min_by_key(|(s, _)| s.end - s.start).map(|(_, k)| *k);
        if before[..start].ends_with('@') {
            return (ANNOTATIONS.iter().map(|a| Completion { label: a.to_string(), kind: CompletionKind::Annotation, detail: "annotation".into() }).collect(), false);
        }
        if let Some(dotted) = before[..start].strip_suffix('.') {
            let name = &dotted[dotted.trim_end_matches(word).len()..];
            let visible = |sym: &Symbol| match sym {
                Symbol::Local(f, _) => Some(*f) == func,
                Symbol::Field(..) => false,
                _ => true,
            };
            let shape = self
                .decls
                .iter()
                .filter(|(sym, (_, n, _))| n == name && visible(sym))
                .min_by_key(|(sym, _)| !matches!(sym, Symbol::Local(..)))
                .and_then(|(sym, _)| self.shapes.get(sym));
            let fields = match shape {
                Some(Shape::Struct(s)) => self.fields[*s].iter().map(|(n, t)| Completion { label: n.clone(), kind: CompletionKind::Field, detail: t.clone() }).collect(),
                Some(Shape::Vector(n)) => ["xyzw", "rgba"]
                    .iter()
                    .flat_map(|set| set.chars().take(*n as usize))
                    .map(|c| Completion { label: c.to_string(), kind: CompletionKind::Field, detail: "component".into() })
                    .collect(),
                None => Vec::new(),
            };
            return (fields, false);
        }
        let mut out: Vec<Completion> = Vec::new();
        for (sym, (_, name, detail)) in &self.decls {
            let kind = match sym {
                Symbol::Local(f, _) if Some(*f) == func => CompletionKind::Local,
                Symbol::Local(..) | Symbol::Field(..) | Symbol::EntryPoint(_) => continue,
                Symbol::Global(_) => CompletionKind::Global,
                Symbol::Const(_) => CompletionKind::Constant,
                Symbol::Function(_) => CompletionKind::Function,
                Symbol::Struct(_) => CompletionKind::Struct,
            };
            out.push(Completion { label: name.clone(), kind, detail: detail.clone() });
        }
        // Builtins sort after every declared kind: appended, in order.
        out.sort_by(|a, b| (a.kind as u8, &a.label).cmp(&(b.kind as u8, &b.label)));
        out.dedup_by(|a, b| a.label == b.label);
        (out, true)
    }
}

/// The builtin functions (each with its first signature) and types, in
/// completion order: the same in every completion, so made once.
pub fn builtin_completions() -> &'static [Completion] {
    static ALL: std::sync::OnceLock<Vec<Completion>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| {
        let mut out: Vec<Completion> = crate::sema::builtins::all_names()
            .map(|n| {
                let sigs = crate::sema::builtins::signatures(n);
                let more = if sigs.len() > 1 { format!(" (+{} more)", sigs.len() - 1) } else { String::new() };
                let detail = sigs.first().map_or_else(|| "builtin".to_string(), |(s, _)| format!("{s}{more}"));
                Completion { label: n.to_string(), kind: CompletionKind::Builtin, detail }
            })
            .collect();
        out.extend(type_names().into_iter().map(|n| Completion { label: n.to_string(), kind: CompletionKind::Type, detail: "type".into() }));
        out.sort_by(|a, b| (a.kind as u8, &a.label).cmp(&(b.kind as u8, &b.label)));
        out
    })
}

/// What a builtin function means and its overloads, for a hover.
fn builtin_doc(name: &str) -> String {
    let mut doc = format!("builtin: {}", crate::sema::builtin_docs::meaning(name).unwrap_or("a builtin function"));
    let sigs = crate::sema::builtins::signatures(name);
    if sigs.len() > 1 {
        doc.push_str("\n\n```das\n");
        doc.push_str(&sigs.iter().map(|(s, _)| s.as_str()).collect::<Vec<_>>().join("\n"));
        doc.push_str("\n```");
    }
    doc
}

/// The objects of a manifest whose `name` is `name`, as compact JSON.
fn manifest_entries(v: &serde_json::Value, name: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Object(m) => {
            if m.get("name").and_then(|n| n.as_str()) == Some(name) {
                out.extend(serde_json::to_string(v).ok());
                return;
            }
            m.values().for_each(|x| manifest_entries(x, name, out));
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| manifest_entries(x, name, out)),
        _ => {}
    }
}

/// The span of the first whole-word `name` inside `span` (a function's
/// span covers its whole declaration); `span` itself if there is none.
fn name_within(sources: &SourceMap, span: Span, name: &str) -> Span {
    let text = sources.slice(span);
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(i) = text.get(from..).and_then(|t| t.find(name)).map(|i| i + from) {
        let before = text[..i].chars().next_back().is_some_and(word);
        let after = text[i + name.len()..].chars().next().is_some_and(word);
        if !before && !after {
            let start = span.start + i as u32;
            return Span::new(start, start + name.len() as u32);
        }
        from = i + name.len();
    }
    span
}

/// Collects every expression of the checked functions.
struct Walker<'a, 'p> {
    occurrences: Vec<Occurrence>,
    show: &'a dyn Fn(&Ty) -> String,
    /// Each type's text, made once: most expressions share a few types.
    types: HashMap<&'p Ty, Arc<str>>,
    func: usize,
}

impl<'p> Walker<'_, 'p> {
    fn ty(&mut self, ty: &'p Ty) -> Arc<str> {
        let show = self.show;
        self.types.entry(ty).or_insert_with(|| Arc::from(show(ty))).clone()
    }

    fn function(&mut self, key: usize, f: &'p tree::Function, decls: &mut HashMap<Symbol, (Span, String, String)>) {
        self.func = key;
        for (id, l) in f.locals.iter().enumerate() {
            decls.insert(Symbol::Local(key, id), (l.span, l.name.as_str().to_string(), (self.show)(&l.ty)));
        }
        self.stmts(&f.body);
    }

    fn stmts(&mut self, body: &'p [Stmt]) {
        for s in body {
            match s {
                Stmt::Local { init, .. } => init.iter().for_each(|e| self.expr(e)),
                Stmt::Assign { target, value, .. } => {
                    self.expr(target);
                    self.expr(value);
                }
                Stmt::Expr(e) => self.expr(e),
                Stmt::If { cond, then, otherwise, .. } => {
                    self.expr(cond);
                    self.stmts(then);
                    self.stmts(otherwise);
                }
                Stmt::While { cond, body, .. } => {
                    self.expr(cond);
                    self.stmts(body);
                }
                Stmt::For { start, end, body, .. } => {
                    self.expr(start);
                    self.expr(end);
                    self.stmts(body);
                }
                Stmt::Return(e, _) => e.iter().for_each(|e| self.expr(e)),
                Stmt::Break(_) | Stmt::Continue(_) | Stmt::Discard(_) => {}
            }
        }
    }

    fn expr(&mut self, e: &'p tree::Expr) {
        let mut builtin = None;
        let symbol = match &e.kind {
            ExprKind::Local(id) => Some(Symbol::Local(self.func, *id)),
            ExprKind::Global(g) => Some(Symbol::Global(*g)),
            ExprKind::Const(c) => Some(Symbol::Const(*c)),
            ExprKind::Call(f, _) => Some(Symbol::Function(*f)),
            ExprKind::Field(base, k) => match base.ty {
                Ty::Struct(s) => Some(Symbol::Field(s, *k)),
                _ => None,
            },
            ExprKind::Builtin(b, args) => {
                let params: Vec<String> = args.iter().map(|a| (self.show)(&a.ty)).collect();
                builtin = Some(format!("{}({}) : {}", name_of(*b), params.join(", "), (self.show)(&e.ty)));
                None
            }
            _ => None,
        };
        if !e.span.is_empty() {
            let ty = self.ty(&e.ty);
            self.occurrences.push(Occurrence { span: e.span, ty, symbol, builtin });
        }
        match &e.kind {
            ExprKind::Unary(_, x) | ExprKind::Swizzle(x, _) | ExprKind::Field(x, _) => self.expr(x),
            ExprKind::Binary(_, pair) => {
                self.expr(&pair.0);
                self.expr(&pair.1);
            }
            ExprKind::Select { cond, accept, reject } => {
                self.expr(cond);
                self.expr(accept);
                self.expr(reject);
            }
            ExprKind::Call(_, args) | ExprKind::Builtin(_, args) | ExprKind::Construct(args) => args.iter().for_each(|a| self.expr(a)),
            ExprKind::Index(a, b) => {
                self.expr(a);
                self.expr(b);
            }
            _ => {}
        }
    }
}

/// The byte offset of an LSP position (line, UTF-16 column) in `text`:
/// a column past the line's end is its end, a line past the last is the
/// text's end, a column inside a surrogate pair is the character's start.
pub fn position_to_offset(text: &str, line: u32, character: u32) -> usize {
    let mut start = 0;
    for _ in 0..line {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    let line_text = text[start..].split('\n').next().unwrap_or("");
    let mut units = 0u32;
    for (i, c) in line_text.char_indices() {
        units += c.len_utf16() as u32;
        if units > character {
            return start + i;
        }
    }
    start + line_text.trim_end_matches('\r').len()
}

/// The LSP position (line, UTF-16 column) of a byte offset in `text`
/// (clamped to the text, and to a character boundary).
pub fn offset_to_position(text: &str, offset: usize) -> (u32, u32) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() as u32;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let character = before[line_start..].chars().map(|c| c.len_utf16() as u32).sum();
    (line, character)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MAIN: &str = "//! The light's colour.\nvar @uniform light : float3\nvar @out f_color : float4\n\ndef shade(c : float3) : float3 {\n    return c * light\n}\n\n[vertex_program]\ndef vs {\n    gl_Position = float4(shade(light), 1.0)\n}\n\n[fragment_program]\ndef fs {\n    let k = length(light)\n    f_color = float4(float3(k), 1.0)\n}\n";

    fn dir_with(files: &[(&str, &str)]) -> tempfile::TempDir {
        let d = tempfile::tempdir().unwrap();
        for (name, text) in files {
            std::fs::write(d.path().join(name), text).unwrap();
        }
        d
    }

    #[test]
    fn positions_convert_in_utf16_and_clamp() {
        let text = "a\u{1F600}b\nxy";
        assert_eq!(position_to_offset(text, 0, 0), 0);
        assert_eq!(position_to_offset(text, 0, 1), 1);
        // Inside the surrogate pair: the character's start.
        assert_eq!(position_to_offset(text, 0, 2), 1);
        assert_eq!(position_to_offset(text, 0, 3), 5);
        assert_eq!(position_to_offset(text, 0, 99), 6);
        assert_eq!(position_to_offset(text, 1, 1), 8);
        assert_eq!(position_to_offset(text, 7, 0), text.len());
        assert_eq!(offset_to_position(text, 5), (0, 3));
        assert_eq!(offset_to_position(text, 2), (0, 1));
        assert_eq!(offset_to_position(text, 99), (1, 2));
    }

    #[test]
    fn an_open_document_stands_for_its_file_also_when_included() {
        let d = dir_with(&[("main.das", "#include \"inc.das\"\n"), ("inc.das", MAIN)]);
        let main = d.path().join("main.das");
        let mut ws = Workspace::new(Options::default());
        let ok = ws.check(&main);
        assert!(ok.diagnostics.is_empty(), "{:?}", ok.diagnostics);
        // An unsaved error in the included file shows at the #include line.
        ws.set_document(&d.path().join("inc.das"), MAIN.replace("c * light", "c * nothing"), 3);
        let bad = ws.check(&main);
        assert_eq!(bad.diagnostics.len(), 1, "{:?}", bad.diagnostics);
        let diag = &bad.diagnostics[0];
        assert_eq!(&"#include \"inc.das\"\n"[diag.start..diag.end], "#include \"inc.das\"", "{diag:?}");
        assert!(diag.message.contains("nothing") && diag.message.contains("inc.das:6:"), "{}", diag.message);
        let (origin, start, _, _) = diag.origin.clone().unwrap();
        assert_eq!((origin, start), (overlay::normalize(&d.path().join("inc.das")), MAIN.find("c * light").unwrap() + 4));
        // The last good analysis is kept.
        assert!(ws.index(&main).is_some());
        ws.close_document(&d.path().join("inc.das"));
        assert!(ws.check(&main).diagnostics.is_empty());
    }

    #[test]
    fn hover_definition_references_and_symbols() {
        let d = dir_with(&[("m.das", MAIN)]);
        let path = d.path().join("m.das");
        let mut ws = Workspace::new(Options::default());
        assert!(ws.check(&path).diagnostics.is_empty());
        let index = ws.index(&path).unwrap();
        let use_at = MAIN.find("c * light").unwrap() + 4;
        let h = index.hover(&path, use_at).unwrap();
        assert!(h.text.contains("light : float3") && h.text.contains("The light's colour.") && h.text.contains("manifest"), "{}", h.text);
        let decl = index.definition(&path, use_at).unwrap();
        assert_eq!(&MAIN[decl.start..decl.end], "light");
        assert_eq!(decl.start, MAIN.find("light :").unwrap());
        let refs = index.references(&path, use_at, true);
        assert_eq!(refs.len(), 4, "{refs:?}");
        let b = index.hover(&path, MAIN.find("length").unwrap() + 1).unwrap();
        assert!(b.text.contains("length(float3) : float"), "{}", b.text);
        let k = index.hover(&path, MAIN.find("float3(k)").unwrap() + 7).unwrap();
        assert!(k.text.contains("k : float"), "{}", k.text);
        let f = index.definition(&path, MAIN.find("shade(light)").unwrap()).unwrap();
        assert_eq!(f.start, MAIN.find("shade(c").unwrap());
        let names: Vec<_> = index.symbols(&path).into_iter().map(|s| (s.name, s.kind)).collect();
        assert_eq!(
            names,
            [("light".into(), SymbolKind::Global), ("f_color".into(), SymbolKind::Global), ("shade".into(), SymbolKind::Function), ("vs".into(), SymbolKind::EntryPoint), ("fs".into(), SymbolKind::EntryPoint)]
        );
        // Rename: every use, refused on a clash or a reserved name.
        let edits = index.rename(&path, use_at, "sun").unwrap();
        assert_eq!(edits.len(), 4, "{edits:?}");
        assert!(edits.iter().all(|e| &MAIN[e.start..e.end] == "light"), "{edits:?}");
        let shade = index.rename(&path, MAIN.find("shade(light)").unwrap() + 1, "tone").unwrap();
        assert!(shade.len() == 2 && shade.iter().all(|e| &MAIN[e.start..e.end] == "shade"), "{shade:?}");
        assert!(index.rename(&path, use_at, "f_color").unwrap_err().contains("already declared"));
        assert!(index.rename(&path, use_at, "sample").unwrap_err().contains("reserved in GLSL"));
        assert!(index.rename(&path, use_at, "fn").unwrap_err().contains("WGSL"));
        assert!(index.rename(&path, use_at, "length").unwrap_err().contains("builtin"));
        assert!(index.rename(&path, use_at, "2x").is_err());
        // Completion: names in scope and builtins; components after `.`.
        let in_fs = MAIN.find("f_color = float4").unwrap();
        let labels: Vec<String> = index.completions(&path, MAIN, in_fs).into_iter().map(|c| c.label).collect();
        for want in ["k", "light", "shade", "length", "f_color"] {
            assert!(labels.iter().any(|l| l == want), "{want} in {labels:?}");
        }
        assert!(!labels.iter().any(|l| l == "c"), "a local of another function: {labels:?}");
        let typed = MAIN.replace("f_color = float4(float3(k), 1.0)", "f_color = float4(light.");
        let dot = typed.find("light.").unwrap() + 6;
        let comps: Vec<String> = index.completions(&path, &typed, dot).into_iter().map(|c| c.label).collect();
        assert_eq!(comps, ["x", "y", "z", "r", "g", "b"]);
        let at = MAIN.find("@uniform").unwrap() + 1;
        let annotations: Vec<String> = index.completions(&path, MAIN, at).into_iter().map(|c| c.label).collect();
        assert!(annotations.contains(&"location".to_string()) && !annotations.contains(&"light".to_string()), "{annotations:?}");
        assert!(labels.iter().any(|l| l == "float4x3") && labels.iter().any(|l| l == "sampler2DShadow"), "{labels:?}");
        // Every type offered is one the checker knows.
        for n in type_names() {
            assert!(crate::sema::types::SamplerKind::from_name(n).is_some() || SAMPLER_NAMES.iter().all(|s| *s != n), "{n}");
        }
        assert_eq!(type_names().len(), 5 * 4 + 9 + SAMPLER_NAMES.len());
        // Semantic tokens: `light` declared, `length` a builtin, `gl_Position` too.
        let tokens = index.semantic_tokens(&path);
        let token_at = |at: usize| tokens.iter().find(|t| t.start == at).map(|t| (t.kind, t.declaration, &MAIN[t.start..t.end]));
        assert_eq!(token_at(MAIN.find("light :").unwrap()), Some((TokenKind::Variable, true, "light")));
        assert_eq!(token_at(MAIN.find("length").unwrap()), Some((TokenKind::BuiltinFunction, false, "length")));
        assert_eq!(token_at(MAIN.find("gl_Position").unwrap()), Some((TokenKind::BuiltinVariable, false, "gl_Position")));
        assert_eq!(token_at(MAIN.find("shade(light)").unwrap()), Some((TokenKind::Function, false, "shade")));
        assert!(tokens.windows(2).all(|w| w[0].end <= w[1].start));
        // Signature help inside `shade(`, and the emitted code on an entry point.
        let (sigs, active) = index.signature_help(MAIN, MAIN.find("shade(light)").unwrap() + 6).unwrap();
        assert_eq!((sigs[0].0.as_str(), active), ("def shade(c : float3) : float3", 0));
        assert!(index.signature_help(MAIN, MAIN.find("light :").unwrap()).is_none());
        let vs = index.hover(&path, MAIN.find("def vs").unwrap() + 4).unwrap();
        assert!(vs.text.contains("glsl330:") && vs.text.contains("gl_Position") && vs.text.contains("wgsl:"), "{}", vs.text);
        // Inlay hints: `k`'s inferred type, not `c`'s written one.
        let hints = index.inlay_hints(&path);
        assert_eq!(hints, [(MAIN.find("k = length").unwrap() + 1, ": float".to_string())]);
        // Past the end: nothing, no panic.
        assert!(index.hover(&path, 1 << 20).is_none());
    }
}
