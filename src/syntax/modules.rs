//! daslang modules: `require NAME`, `require dir/name`, `require daslib/x`,
//! `require PREFIX/x`, `require ./file.das`, `require ../dir/file`.
//!
//! A required module that is a file is read, preprocessed and split into
//! top-level items like the input, and its items join the input's: a
//! shader reaches the functions, constants, structs and globals it names
//! from a module as from its own file, and only those are parsed (host
//! code in a module is never parsed, as in the input). A module's own
//! `require`s are followed only once something in it is reached. Entry
//! points are the input's: a module's `[vertex_program]`s are its own.
//!
//! Where a module is looked for, in daslang's order ([`candidates`]):
//! daslang's builtin modules (`math`, `strings`, ...) are no files;
//! `./x` and `../x` are relative to the requiring file and `%/x` to the
//! daslang root; `daslib/x` is in the daslib root; `PREFIX/x` goes through
//! `--module`s and a daslang tree's registrations and prefix folders
//! (`module_roots`); then `x.das` beside the requiring file and in each
//! `-I` directory.
//!
//! daslang's builtin-declaring modules ([`BUILTIN_DECLARING`]:
//! `shader_lingua_franca`, `glsl_common`, `spirv_builtins`, known by their
//! `module` line) are not user code: the names they declare are recorded
//! for the checker (umbrac's builtin of that name is meant, and one umbrac
//! lacks is refused by name) and their items never join the input's.
//!
//! A module that cannot be found is not an error by itself: daslang files
//! require host libraries (`glfw/glfw_boost`, `live/live_gc`) that
//! shaders never use. It is one when a shader uses a name nothing defines:
//! the checker's error shows each module that was not found, at its
//! `require`, with where it was looked for. A relative path, a `daslib/`
//! module with a daslib root given, or a name under a prefix umbrac knows
//! that is missing is an error at once, as is a module that exists but
//! cannot be read.

use std::collections::VecDeque;
use std::ops::Range;
use std::path::{Path, PathBuf};

pub use super::ast::{DaslangBuiltin, MissingModule};
use super::module_roots::Roots;
use super::items::{self, ItemKind, RawItem};
use super::token::{TokKind, Token, P};
use super::ParseOptions;
use crate::diag::{Diagnostic, Diagnostics};
use crate::source::{FileId, SourceMap, Span};

/// Deepest chain of modules requiring modules.
pub const MAX_MODULE_DEPTH: usize = 64;
/// Most module files read in one compilation.
pub const MAX_MODULES: usize = 1024;

/// daslang's builtin (C++) modules: no files to read.
const BUILTIN_MODULES: &[&str] = &["builtin", "math", "strings", "fio", "rtti", "ast", "debugapi", "jobque", "network", "uriparser", "glfw", "opengl", "stbimage", "$"];

/// The first path segments of daslang's host-side module packs (windows,
/// GL calls, live reload, ...), which no shader reaches: not worth a hint
/// when a name is unknown.
const HOST_PACKS: &[&str] = &["glfw", "opengl", "live", "imgui", "stbimage", "stbtruetype", "sound", "dashv", "pugixml", "dasbox", "sdl", "raylib"];

/// One `require` line.
struct Require {
    name: String,
    span: Span,
    /// The whole line, from `require` (where its file's diagnostics say
    /// "required from").
    site: Span,
}

/// The `require` of an item, if it is one.
fn require_of(toks: &[Token], item: &RawItem, map: &SourceMap) -> Option<Require> {
    if item.kind != ItemKind::Other {
        return None;
    }
    let r = item.body.clone();
    let first = toks.get(r.start)?;
    if first.kind != TokKind::Ident || map.slice(first.span) != "require" {
        return None;
    }
    let mut k = r.start + 1;
    // `require ?guard target`: the guard names a module that must exist for
    // the target to be loaded; umbrac loads the target if it finds it.
    if toks.get(k).is_some_and(|t| t.is(P::Question)) {
        k = path_end(toks, k + 1, r.end);
    }
    let end = path_end(toks, k, r.end);
    if end == k {
        return None;
    }
    let span = toks[k].span.to(toks[end - 1].span);
    let name = map.slice(span).to_string();
    Some(Require { name, span, site: first.span.to(span) })
}

/// The end of a module path starting at `k`: a run of tokens with no space
/// between them (`daslib/ast_boost`, `../shared/x.das`).
fn path_end(toks: &[Token], mut k: usize, end: usize) -> usize {
    let start = k;
    while k < end {
        let t = &toks[k];
        let adjacent = k == start || toks[k - 1].span.end == t.span.start;
        let part = matches!(t.kind, TokKind::Ident | TokKind::Int | TokKind::Kw(_)) || matches!(t.kind, TokKind::P(P::Slash | P::Dot | P::DotDot | P::Percent | P::Minus));
        if !adjacent || !part || t.kind == TokKind::Newline {
            break;
        }
        k += 1;
    }
    k
}

fn parent_dir(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Where a module name may be.
struct Candidates {
    /// The files to try, in order.
    files: Vec<PathBuf>,
    /// What to do when none exists.
    help: &'static str,
    /// A missing file is an error at once: a file path, or a name under a
    /// prefix umbrac knows (`daslib/` with a daslib directory, a
    /// `--module`, a prefix of the daslang tree).
    explicit: bool,
    /// `./x`, `../x`: relative to the requiring file, followed wherever it
    /// leads, as daslang follows it.
    relative: bool,
}

/// With `.das` added unless it ends so.
fn das_file(name: &str) -> String {
    if name.ends_with(".das") {
        name.to_string()
    } else {
        format!("{name}.das")
    }
}

/// Where a module name may be, in daslang's order: a relative path from
/// the requiring file; `daslib/` in the daslib root; a prefix's `--module`,
/// registrations and folders; then the requiring file's folder and the
/// `-I` directories. daslang separates a name's parts with `/` or `.`.
fn candidates(name: &str, dir: &Path, roots: &Roots, opts: &ParseOptions) -> Candidates {
    if name.starts_with("./") || name.starts_with("../") {
        return Candidates { files: vec![dir.join(das_file(name))], help: "check the path: it is relative to the requiring file", explicit: true, relative: true };
    }
    if let Some(rest) = name.strip_prefix("%/") {
        let help = "`%/` is the daslang root: pass `--daslang-root DIR`";
        return Candidates { files: roots.root().map(|r| r.join(das_file(rest))).into_iter().collect(), help, explicit: true, relative: false };
    }
    // `a.b` is `a/b`; a name with a `..` part or a `.das` file is a path.
    let name = if name.ends_with(".das") || name.contains("..") { name.to_string() } else { name.replace('.', "/") };
    let beside = |files: &mut Vec<PathBuf>| {
        let file = das_file(&name);
        files.push(dir.join(&file));
        files.extend(opts.include_dirs.iter().map(|d| d.join(&file)));
    };
    let Some((prefix, rest)) = name.split_once('/') else {
        let mut files = Vec::new();
        beside(&mut files);
        return Candidates { files, help: "add the directory holding it with `-I DIR`", explicit: false, relative: false };
    };
    let found = roots.lookup(prefix, rest);
    let mut files = found.files;
    let help = if prefix == "daslib" {
        if found.known_prefix {
            "check the module's name and the `--daslang-root` or `--daslib` directory"
        } else {
            "pass `--daslang-root DIR` (a daslang tree or install) or `--daslib DIR`"
        }
    } else if found.known_prefix {
        "check the module's name and where its prefix points (`--module PREFIX=DIR`, `--daslang-root DIR`)"
    } else {
        "pass `--daslang-root DIR`, state its prefix with `--module PREFIX=DIR`, or add the directory holding it with `-I DIR`"
    };
    if prefix != "daslib" {
        beside(&mut files);
    }
    Candidates { files, help, explicit: found.known_prefix, relative: false }
}

/// Whether a missing module named so can hold shader code (else it is a
/// builtin module or a host pack, and no hint names it).
fn may_hold_shader_code(name: &str) -> bool {
    let head = name.split('/').next().unwrap_or(name);
    !BUILTIN_MODULES.contains(&name) && (!name.contains('/') || !HOST_PACKS.contains(&head))
}

/// daslang's modules that declare its shader builtins, by their `module`
/// line (as dasGlsl recognises them, by module name): read as declarations
/// of builtins, never as user code. Their bodies are CPU stand-ins that
/// daslang's emitters never translate.
pub const BUILTIN_DECLARING: &[&str] = &["shader_lingua_franca", "glsl_common", "spirv_builtins"];

/// The name of a file's `module NAME` line, if it has one.
fn module_name<'a>(toks: &[Token], items: &[RawItem], map: &'a SourceMap) -> Option<&'a str> {
    items.iter().filter(|i| i.kind == ItemKind::Other).find_map(|i| {
        let first = toks.get(i.body.start)?;
        let name = toks.get(i.body.start + 1)?;
        (first.kind == TokKind::Ident && map.slice(first.span) == "module" && name.kind == TokKind::Ident).then(|| map.slice(name.span))
    })
}

/// Reads a `--module PREFIX=DIR` argument: PREFIX is a module prefix
/// (`[A-Za-z0-9_]+`, what `require PREFIX/NAME` starts with), DIR is not
/// empty.
pub fn parse_module_arg(s: &str) -> Result<(String, PathBuf), String> {
    let bad = || format!("`{s}` is not PREFIX=DIR (e.g. `--module geometry=modules/dasGlsl/glsl`)");
    let (prefix, dir) = s.split_once('=').ok_or_else(bad)?;
    if prefix.is_empty() || !prefix.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') || dir.is_empty() {
        return Err(bad());
    }
    if prefix == "daslib" {
        return Err("`daslib` is daslang's standard library: give its directory with `--daslang-root` or `--daslib`".into());
    }
    Ok((prefix.to_string(), PathBuf::from(dir)))
}

/// Reads a `--daslang-root DIR` argument: a directory (a daslang tree or
/// install, holding `daslib/` and `modules/`).
pub fn parse_daslang_root(s: &str) -> Result<PathBuf, String> {
    let dir = PathBuf::from(s);
    if !dir.is_dir() {
        return Err(format!("`{s}` is not a directory (want a daslang tree or install, holding `daslib/` and `modules/`)"));
    }
    if !dir.join("daslib").is_dir() && !dir.join("modules").is_dir() {
        return Err(format!("`{s}` holds neither `daslib/` nor `modules/`: it is not a daslang tree or install"));
    }
    Ok(dir)
}

/// Appends a module's tokens to `toks` and its items to `raw`. A
/// builtin-declaring module ([`BUILTIN_DECLARING`]) gives its names to
/// `builtins` and only its `require`s to `raw` (items never parsed); then
/// this returns true.
fn join_items(module_toks: Vec<Token>, map: &SourceMap, toks: &mut Vec<Token>, raw: &mut Vec<RawItem>, builtins: &mut Vec<DaslangBuiltin>) -> bool {
    let base = toks.len();
    let split = items::split(&module_toks, map);
    let declares = module_name(&module_toks, &split, map).filter(|n| BUILTIN_DECLARING.contains(n)).map(str::to_string);
    for mut item in split {
        if let Some(module) = &declares {
            for k in item.names() {
                let t = &module_toks[k];
                builtins.push(DaslangBuiltin { name: map.slice(t.span).to_string(), module: module.clone(), span: t.span });
            }
            if item.kind != ItemKind::Other {
                continue;
            }
        }
        let shift = |r: &mut Range<usize>| *r = r.start + base..r.end + base;
        shift(&mut item.annots);
        shift(&mut item.body);
        shift(&mut item.names);
        for k in &mut item.block_names {
            *k += base;
        }
        // A module's entry points are its own; its shader globals
        // count only where a shader reaches them by name.
        item.entry = false;
        item.from_module = true;
        raw.push(item);
    }
    toks.extend(module_toks);
    declares.is_some()
}

/// One module file read.
struct Module {
    /// Its items in the combined list.
    items: Range<usize>,
    depth: usize,
    /// Its own `require`s were followed.
    expanded: bool,
}

/// What [`load`] found besides items.
#[derive(Default)]
pub(super) struct Loaded {
    pub missing: Vec<MissingModule>,
    /// Names daslang's builtin-declaring modules declare.
    pub builtins: Vec<DaslangBuiltin>,
}

/// Reads the modules the program's `require`s name as far as shaders reach
/// into them: appends their tokens to `toks` and their items to `raw`
/// (marked `from_module`), and returns the modules not found and the
/// names daslang's builtin-declaring modules declare.
///
/// `probed` gets every path a `require` looked at and found no module file
/// at, before the one it took (or at all).
pub(super) fn load(map: &mut SourceMap, root: FileId, toks: &mut Vec<Token>, raw: &mut Vec<RawItem>, opts: &ParseOptions, diags: &mut Diagnostics, probed: &mut Vec<PathBuf>) -> Loaded {
    let mut out = Loaded::default();
    let mut modules: Vec<Module> = Vec::new();
    let mut seen: Vec<PathBuf> = Vec::new();
    // The input's requires, then those of each module once it is reached.
    let mut pending: VecDeque<(usize, usize)> = (0..raw.len()).map(|i| (i, 0)).collect();
    let root_dir = map.file(root).path.as_deref().map(parent_dir).unwrap_or_else(|| PathBuf::from("."));
    let mut roots: Option<Roots> = None;
    let mut allowed: Option<super::boundary::Boundary> = None;
    loop {
        while let Some((i, depth)) = pending.pop_front() {
            let Some(req) = require_of(toks, &raw[i], map) else { continue };
            // daslang's builtin modules come first, whatever files exist.
            if BUILTIN_MODULES.contains(&req.name.as_str()) {
                continue;
            }
            let roots = roots.get_or_insert_with(|| {
                let mut r = Roots::new(opts);
                for (path, text) in std::mem::take(&mut r.descriptors) {
                    map.add(path.display().to_string(), Some(path), text, None);
                }
                r
            });
            let requiring_dir = map.file_of(req.span.start).and_then(|f| map.file(f).path.as_deref().map(parent_dir)).unwrap_or_else(|| root_dir.clone());
            let cands = candidates(&req.name, &requiring_dir, roots, opts);
            // A text the host passed in (a page's files) is a file too.
            let taken = cands.files.iter().position(|p| super::overlay::holds(p) || p.is_file());
            probed.extend(cands.files[..taken.unwrap_or(cands.files.len())].iter().cloned());
            let Some(path) = taken.map(|i| cands.files[i].clone()) else {
                if let Some(dir) = cands.files.iter().find(|p| p.is_dir()) {
                    diags.push(Diagnostic::error(format!("`{}` is a directory, not a module file", dir.display()), req.span).with_label("required here"));
                    continue;
                }
                if cands.explicit {
                    let mut d = Diagnostic::error(format!("cannot find module `{}`", req.name), req.span).with_label("not found");
                    for c in &cands.files {
                        d = d.with_note(format!("searched `{}`", c.display()));
                    }
                    let registered = req.name.split_once('/').map(|(p, _)| roots.registered_under(p)).unwrap_or_default();
                    if !registered.is_empty() {
                        let prefix = req.name.split_once('/').map_or("", |p| p.0);
                        d = d.with_note(format!("the daslang tree registers `{prefix}/` for: {}", registered.join(", ")));
                    }
                    diags.push(d.with_note(format!("help: {}", cands.help)));
                } else if may_hold_shader_code(&req.name) && !out.missing.iter().any(|m| m.name == req.name) {
                    out.missing.push(MissingModule { name: req.name, span: req.span, searched: cands.files, help: cands.help });
                }
                continue;
            };
            if depth + 1 > MAX_MODULE_DEPTH {
                diags.push(Diagnostic::error(format!("modules require each other too deeply (limit {MAX_MODULE_DEPTH})"), req.span).with_label("the limit is reached here"));
                continue;
            }
            let canon = match std::fs::canonicalize(&path) {
                Ok(c) => c,
                // A text only the overlay has is known by its normalized path.
                Err(_) if super::overlay::holds(&path) => super::overlay::normalize(&path),
                Err(e) => {
                    diags.push(Diagnostic::error(format!("cannot resolve module `{}`: {e}", path.display()), req.span).with_label("cannot resolve"));
                    continue;
                }
            };
            if seen.contains(&canon) {
                continue; // one module, however often required
            }
            let allowed = allowed.get_or_insert_with(|| {
                super::boundary::Boundary::new(std::iter::once(&root_dir).chain(&opts.include_dirs).chain(roots.dirs()))
            });
            if !opts.allow_outside_includes && !cands.relative && !allowed.contains(&path, &canon) {
                let d = Diagnostic::error(format!("`require {}` reaches outside the input's directory and the include, module and daslang directories", req.name), req.span)
                    .with_label("outside the allowed directories")
                    .with_note(format!("it resolves to `{}`", canon.display()))
                    .with_note("help: add its directory with `-I DIR`, or pass `--allow-outside-includes` to permit it");
                diags.push(d);
                continue;
            }
            if seen.len() >= MAX_MODULES {
                diags.push(Diagnostic::error(format!("too many modules (limit {MAX_MODULES})"), req.span).with_label("the limit is reached at this require"));
                continue;
            }
            seen.push(canon);
            let text = match super::read_source(&path) {
                Ok(t) => t,
                Err(d) => {
                    let why = d.message;
                    diags.push(Diagnostic::error(format!("cannot read module `{}`", req.name), req.span).with_label("required here").with_note(why));
                    continue;
                }
            };
            let id = map.add(path.display().to_string(), Some(path.clone()), text, Some(req.site));
            let module_toks = super::preprocess::preprocess(map, id, opts, diags);
            let first_item = raw.len();
            let declares_builtins = join_items(module_toks, map, toks, raw, &mut out.builtins);
            if declares_builtins {
                // Its own requires (the lingua franca) are followed now.
                pending.extend((first_item..raw.len()).map(|i| (i, depth + 1)));
            } else {
                modules.push(Module { items: first_item..raw.len(), depth: depth + 1, expanded: false });
            }
        }
        if modules.iter().all(|m| m.expanded) {
            break;
        }
        // Follow the requires of the modules shaders reach into.
        let selected = items::select(raw, toks, map, &opts.entries, Span::default(), &mut Diagnostics::new());
        for m in modules.iter_mut().filter(|m| !m.expanded) {
            if selected.iter().any(|i| m.items.contains(i)) {
                m.expanded = true;
                pending.extend(m.items.clone().map(|i| (i, m.depth)));
            }
        }
        if pending.is_empty() {
            break;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The module name of each `require` line of `text` (none for other items).
    fn requires(text: &str) -> Vec<String> {
        let mut map = SourceMap::new();
        let id = map.add("t.das", None, text.to_string(), None);
        let mut toks = Vec::new();
        super::super::lexer::lex(&map.file(id).text, map.file(id).base, &mut toks);
        let items = items::split(&toks, &map);
        items.iter().filter_map(|i| require_of(&toks, i, &map)).map(|r| r.name).collect()
    }

    #[test]
    fn require_lines_name_their_modules() {
        let text = "options gen2\nrequire math\nrequire daslib/ast_boost public\nrequire ./helpers.das\nrequire ../shared/utility.das as util\nrequire %/daslib/random.das\nrequire ?pugixml pugixml/PUGIXML_boost public\nrequire glfw/glfw_boost\ndef f {\n    require_nothing()\n}\n";
        assert_eq!(requires(text), ["math", "daslib/ast_boost", "./helpers.das", "../shared/utility.das", "%/daslib/random.das", "pugixml/PUGIXML_boost", "glfw/glfw_boost"]);
    }

    #[test]
    fn where_modules_are_looked_for() {
        let opts = ParseOptions { include_dirs: vec![PathBuf::from("inc")], daslib: vec![PathBuf::from("das/daslib")], module_dirs: vec![("pack".into(), PathBuf::from("p"))], ..Default::default() };
        let roots = Roots::new(&opts);
        let dir = Path::new("src");
        let files = |name: &str| candidates(name, dir, &roots, &opts).files;
        assert_eq!(files("shaderlib/noise"), [PathBuf::from("src/shaderlib/noise.das"), PathBuf::from("inc/shaderlib/noise.das")]);
        assert_eq!(files("shaderlib.noise"), files("shaderlib/noise"));
        assert_eq!(files("daslib/math_boost"), [PathBuf::from("das/daslib/math_boost.das")]);
        assert_eq!(files("./x.das"), [PathBuf::from("src/./x.das")]);
        assert_eq!(files("../lib/x"), [PathBuf::from("src/../lib/x.das")]);
        assert_eq!(files("%/modules/x.das"), [PathBuf::from("das/modules/x.das")]);
        assert_eq!(files("pack/x")[0], PathBuf::from("p/x.das"));
        assert!(candidates("pack/x", dir, &roots, &opts).explicit && !candidates("other/x", dir, &roots, &opts).explicit);
        assert!(candidates("../x", dir, &roots, &opts).relative && !candidates("shaderlib/noise", dir, &roots, &opts).relative);
        let bare = ParseOptions::default();
        assert!(candidates("daslib/math_boost", dir, &Roots::new(&bare), &bare).files.is_empty());
        assert!(!may_hold_shader_code("glfw/glfw_boost") && !may_hold_shader_code("math") && !may_hold_shader_code("glfw"));
        assert!(may_hold_shader_code("shaderlib/noise") && may_hold_shader_code("daslib/math_boost"));
    }

    #[test]
    fn module_arguments() {
        assert_eq!(parse_module_arg("geometry=a/b"), Ok(("geometry".to_string(), PathBuf::from("a/b"))));
        for bad in ["geometry", "=a", "geometry=", "a/b=c", "daslib=x"] {
            assert!(parse_module_arg(bad).is_err(), "{bad}");
        }
    }
}
