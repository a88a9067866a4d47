//! daslang modules: `require NAME`, `require dir/name`, `require daslib/x`,
//! `require ./file.das`.
//!
//! A required module that is a file is read, preprocessed and split into
//! top-level items like the input, and its items join the input's: a
//! shader reaches the functions, constants, structs and globals it names
//! from a module as from its own file, and only those are parsed (host
//! code in a module is never parsed, as in the input). A module's own
//! `require`s are followed only once something in it is reached. Entry
//! points are the input's: a module's `[vertex_program]`s are its own.
//!
//! Where a module is looked for: `NAME.das` beside the requiring file, then
//! in each `-I` directory; `daslib/NAME` in the `--daslib` directory;
//! `./x.das` and `../x.das` beside the requiring file, `%/x.das` in the
//! daslang root (the `--daslib` directory's parent). daslang's builtin
//! modules (`math`, `strings`, ...) are no files: umbrac's builtins are
//! `math`'s shader part, and the rest is host code.
//!
//! A module that cannot be found is not an error by itself: daslang files
//! require host libraries (`glfw/glfw_boost`, `opengl/opengl_boost`) that
//! shaders never use. It is one when a shader uses a name nothing defines:
//! the checker's error shows each module that was not found, at its
//! `require`, with where it was looked for. A file path (`./x.das`) or a
//! `daslib/` module with `--daslib` given that is missing is an error at
//! once, as is a module that exists but cannot be read.

use std::ops::Range;
use std::path::{Path, PathBuf};

pub use super::ast::MissingModule;
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
const BUILTIN_MODULES: &[&str] = &["builtin", "math", "strings", "fio", "rtti", "ast", "debugapi", "jobque", "network", "uriparser", "$"];

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

/// Where a module name may be: the files to try, in order, and what to do
/// when none exists.
fn candidates(name: &str, dir: &Path, opts: &ParseOptions) -> (Vec<PathBuf>, &'static str) {
    let file_form = (name.starts_with("./") || name.starts_with("../") || name.starts_with("%/")) && name.ends_with(".das");
    if file_form {
        return match name.strip_prefix("%/") {
            Some(rest) => (opts.daslib.iter().map(|d| parent_dir(d).join(rest)).collect(), "`%/` is the daslang root: pass `--daslib DIR` (its `daslib` directory)"),
            None => (vec![dir.join(name)], "check the path: it is relative to the requiring file"),
        };
    }
    if let Some(rest) = name.strip_prefix("daslib/") {
        return (opts.daslib.iter().map(|d| d.join(format!("{rest}.das"))).collect(), "pass `--daslib DIR` with daslang's `daslib` directory");
    }
    let file = format!("{name}.das");
    let mut out = vec![dir.join(&file)];
    out.extend(opts.include_dirs.iter().map(|d| d.join(&file)));
    (out, "add the directory holding it with `-I DIR`")
}

/// Whether a missing module named so can hold shader code (else it is a
/// builtin module or a host pack, and no hint names it).
fn may_hold_shader_code(name: &str) -> bool {
    let head = name.split('/').next().unwrap_or(name);
    !BUILTIN_MODULES.contains(&name) && (!name.contains('/') || !HOST_PACKS.contains(&head))
}

/// One module file read.
struct Module {
    /// Its items in the combined list.
    items: Range<usize>,
    depth: usize,
    /// Its own `require`s were followed.
    expanded: bool,
}

/// Reads the modules the program's `require`s name as far as shaders reach
/// into them: appends their tokens to `toks` and their items to `raw`
/// (marked `from_module`), and returns the modules not found.
///
/// `probed` gets every path a `require` looked at and found no module file
/// at, before the one it took (or at all).
pub(super) fn load(map: &mut SourceMap, root: FileId, toks: &mut Vec<Token>, raw: &mut Vec<RawItem>, opts: &ParseOptions, diags: &mut Diagnostics, probed: &mut Vec<PathBuf>) -> Vec<MissingModule> {
    let mut missing: Vec<MissingModule> = Vec::new();
    let mut modules: Vec<Module> = Vec::new();
    let mut seen: Vec<PathBuf> = Vec::new();
    // The input's requires, then those of each module once it is reached.
    let mut pending: Vec<(usize, usize)> = (0..raw.len()).map(|i| (i, 0)).collect();
    let root_dir = map.file(root).path.as_deref().map(parent_dir).unwrap_or_else(|| PathBuf::from("."));
    let mut allowed: Option<Vec<PathBuf>> = None;
    loop {
        for (i, depth) in std::mem::take(&mut pending) {
            let Some(req) = require_of(toks, &raw[i], map) else { continue };
            // daslang's builtin modules come first, whatever files exist.
            if BUILTIN_MODULES.contains(&req.name.as_str()) {
                continue;
            }
            let requiring_dir = map.file_of(req.span.start).and_then(|f| map.file(f).path.as_deref().map(parent_dir)).unwrap_or_else(|| root_dir.clone());
            let (cands, help) = candidates(&req.name, &requiring_dir, opts);
            let taken = cands.iter().position(|p| p.is_file());
            probed.extend(cands[..taken.unwrap_or(cands.len())].iter().cloned());
            let Some(path) = taken.map(|i| cands[i].clone()) else {
                if let Some(dir) = cands.iter().find(|p| p.is_dir()) {
                    diags.push(Diagnostic::error(format!("`{}` is a directory, not a module file", dir.display()), req.span).with_label("required here"));
                    continue;
                }
                let explicit = (req.name.starts_with("./") || req.name.starts_with("../") || req.name.starts_with("%/")) || (req.name.starts_with("daslib/") && !opts.daslib.is_empty());
                if explicit {
                    let mut d = Diagnostic::error(format!("cannot find module `{}`", req.name), req.span).with_label("not found");
                    for c in &cands {
                        d = d.with_note(format!("searched `{}`", c.display()));
                    }
                    let help = if req.name.starts_with("daslib/") { "check the module's name and the `--daslib` directory" } else { help };
                    diags.push(d.with_note(format!("help: {help}")));
                } else if may_hold_shader_code(&req.name) && !missing.iter().any(|m| m.name == req.name) {
                    missing.push(MissingModule { name: req.name, span: req.span, searched: cands, help });
                }
                continue;
            };
            if depth + 1 > MAX_MODULE_DEPTH {
                diags.push(Diagnostic::error(format!("modules require each other too deeply (limit {MAX_MODULE_DEPTH})"), req.span).with_label("the limit is reached here"));
                continue;
            }
            let canon = match std::fs::canonicalize(&path) {
                Ok(c) => c,
                Err(e) => {
                    diags.push(Diagnostic::error(format!("cannot resolve module `{}`: {e}", path.display()), req.span).with_label("cannot resolve"));
                    continue;
                }
            };
            if seen.contains(&canon) {
                continue; // one module, however often required
            }
            let allowed = allowed.get_or_insert_with(|| {
                std::iter::once(&root_dir).chain(&opts.include_dirs).chain(&opts.daslib).filter_map(|d| std::fs::canonicalize(d).ok()).collect()
            });
            if !opts.allow_outside_includes && !allowed.iter().any(|a| canon.starts_with(a)) {
                let d = Diagnostic::error(format!("`require {}` reaches outside the input's directory and the include and daslib directories", req.name), req.span)
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
            let base = toks.len();
            let first_item = raw.len();
            for mut item in items::split(&module_toks, map) {
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
            modules.push(Module { items: first_item..raw.len(), depth: depth + 1, expanded: false });
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
    missing
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
        let opts = ParseOptions { include_dirs: vec![PathBuf::from("inc")], daslib: vec![PathBuf::from("das/daslib")], ..Default::default() };
        let dir = Path::new("src");
        assert_eq!(candidates("shaderlib/noise", dir, &opts).0, [PathBuf::from("src/shaderlib/noise.das"), PathBuf::from("inc/shaderlib/noise.das")]);
        assert_eq!(candidates("daslib/math_boost", dir, &opts).0, [PathBuf::from("das/daslib/math_boost.das")]);
        assert_eq!(candidates("./x.das", dir, &opts).0, [PathBuf::from("src/./x.das")]);
        assert_eq!(candidates("%/modules/x.das", dir, &opts).0, [PathBuf::from("das/modules/x.das")]);
        assert!(candidates("daslib/math_boost", dir, &ParseOptions::default()).0.is_empty());
        assert!(!may_hold_shader_code("glfw/glfw_boost") && !may_hold_shader_code("math"));
        assert!(may_hold_shader_code("shaderlib/noise") && may_hold_shader_code("daslib/math_boost") && may_hold_shader_code("glfw"));
    }
}
