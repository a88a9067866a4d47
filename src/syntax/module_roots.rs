//! Where `require a/b` looks, as daslang resolves it: the requiring file's
//! folder for relative names, the daslib root for `daslib/`, and the
//! module prefixes a daslang tree or install registers.
//!
//! daslang splits a module name at its first `/` (or `.`) into a prefix
//! and the rest. `daslib` is its standard library; other prefixes are
//! registered: by a module pack's `modules/NAME/.das_module`, whose
//! `initialize` calls `register_native_path(PREFIX, REST, FILE)`, by
//! daslang's own C++ build (a folder `modules/NAME/PREFIX/`), or by the
//! host (`glfw/`, `geometry/`). umbrac reads the same: `--daslang-root DIR`
//! gives `DIR/daslib`, every `.das_module`'s registrations (read
//! statically, never run) and every folder named after a prefix;
//! `--module PREFIX=DIR` states one more, ahead of the tree's.

use std::path::{Path, PathBuf};

use super::token::{Kw, TokKind, Token, P};
use super::ParseOptions;
use crate::source::SourceMap;

/// A name's prefix resolved: each file it may be, in order.
pub(super) struct Lookup {
    pub files: Vec<PathBuf>,
    /// The prefix is one umbrac knows (`daslib` with a daslib directory, a
    /// `--module` or a prefix of the daslang tree): a missing file is an
    /// error at once, not a host library left unread.
    pub known_prefix: bool,
}

/// The module prefixes of a daslang tree and the command line.
#[derive(Default)]
pub(super) struct Roots {
    daslib: Vec<PathBuf>,
    /// `--module PREFIX=DIR`: `require PREFIX/REST` may be `DIR/REST.das`.
    user: Vec<(String, PathBuf)>,
    /// The tree's folders named after a prefix (`modules/*/PREFIX/`).
    folders: Vec<(String, PathBuf)>,
    /// `(PREFIX, REST, FILE)` from `.das_module` files.
    registered: Vec<(String, String, PathBuf)>,
    /// The daslang root (`%/` names): `--daslang-root`, else the
    /// `--daslib` directory's parent.
    root: Option<PathBuf>,
    /// The `.das_module` files read, with their text: they decide where
    /// modules are, so they count as read (depfiles, reruns, `--watch`).
    pub descriptors: Vec<(PathBuf, String)>,
}

impl Roots {
    pub fn new(opts: &ParseOptions) -> Roots {
        let mut r = Roots { daslib: opts.daslib.clone(), user: opts.module_dirs.clone(), ..Default::default() };
        r.root = opts.daslang_root.clone().or_else(|| opts.daslib.first().and_then(|d| d.parent()).map(Path::to_path_buf));
        if let Some(root) = &opts.daslang_root {
            r.daslib.push(root.join("daslib"));
            let mut packs: Vec<PathBuf> = std::fs::read_dir(root.join("modules")).into_iter().flatten().flatten().map(|e| e.path()).filter(|p| p.is_dir()).collect();
            packs.sort();
            for pack in packs {
                let descriptor = pack.join(".das_module");
                if let Ok(text) = std::fs::read_to_string(&descriptor) {
                    r.registered.extend(registrations(&pack, &text));
                    r.descriptors.push((descriptor, text));
                }
                let mut subs: Vec<PathBuf> = std::fs::read_dir(&pack).into_iter().flatten().flatten().map(|e| e.path()).filter(|p| p.is_dir()).collect();
                subs.sort();
                for sub in subs {
                    let name = sub.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
                    if is_prefix_name(&name) {
                        r.folders.push((name, sub));
                    }
                }
            }
        }
        r
    }

    /// The directories a module found through a prefix may be in (the
    /// confinement of `syntax::modules`).
    pub fn dirs(&self) -> impl Iterator<Item = &PathBuf> {
        self.daslib.iter().chain(self.user.iter().chain(&self.folders).map(|f| &f.1)).chain(self.root.iter())
    }

    pub fn has_daslib(&self) -> bool {
        !self.daslib.is_empty()
    }

    /// The files `prefix/rest` may be, in order: daslib; else the
    /// `--module`s, the tree's registrations, its prefix-named folders.
    pub fn lookup(&self, prefix: &str, rest: &str) -> Lookup {
        if prefix == "daslib" {
            return Lookup { files: self.daslib.iter().map(|d| d.join(format!("{rest}.das"))).collect(), known_prefix: self.has_daslib() };
        }
        let in_folders = |folders: &[(String, PathBuf)]| folders.iter().filter(|f| f.0 == prefix).map(|f| f.1.join(format!("{rest}.das"))).collect::<Vec<_>>();
        let mut files = in_folders(&self.user);
        files.extend(self.registered.iter().filter(|r| r.0 == prefix && r.1 == rest).map(|r| r.2.clone()));
        files.extend(in_folders(&self.folders));
        let known = self.user.iter().chain(&self.folders).any(|f| f.0 == prefix) || self.registered.iter().any(|r| r.0 == prefix);
        Lookup { files, known_prefix: known }
    }

    /// The names `.das_module` files register under `prefix`, sorted.
    pub fn registered_under(&self, prefix: &str) -> Vec<&str> {
        let mut v: Vec<&str> = self.registered.iter().filter(|r| r.0 == prefix).map(|r| r.1.as_str()).collect();
        v.sort_unstable();
        v.dedup();
        v
    }

    /// `%/x`: the daslang root.
    pub fn root(&self) -> Option<&Path> {
        self.root.as_deref()
    }
}

/// A folder name daslang could use as a `require` prefix.
fn is_prefix_name(s: &str) -> bool {
    !s.is_empty() && !s.starts_with('.') && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The `register_native_path(PREFIX, REST, FILE)` calls of `pack/.das_module`
/// (`text`),
/// read without running it: `{project_path}` is the pack's folder, and a
/// `{v}` bound by `for (v in LIST)` to a `let LIST = ["a", "b"]` of string
/// literals expands to each. A call umbrac cannot read so is skipped
/// (`--module` states it instead).
pub(super) fn registrations(pack: &Path, text: &str) -> Vec<(String, String, PathBuf)> {
    let mut map = SourceMap::new();
    let id = map.add(".das_module", None, text.to_string(), None);
    let mut toks = Vec::new();
    super::lexer::lex(&map.file(id).text, map.file(id).base, &mut toks);
    toks.retain(|t| t.kind != TokKind::Newline);
    let text_of = |t: &Token| map.slice(t.span).to_string();
    let str_of = |t: &Token| (t.kind == TokKind::Str).then(|| text_of(t).trim_matches('"').to_string());
    // `let NAME = [ "a", "b", ... ]`
    let mut lists: Vec<(String, Vec<String>)> = Vec::new();
    // `for ( V in NAME )`
    let mut loops: Vec<(String, String)> = Vec::new();
    let mut calls: Vec<[String; 3]> = Vec::new();
    for k in 0..toks.len() {
        let t = &toks[k];
        let at = |j: usize| toks.get(k + j);
        if matches!(t.kind, TokKind::Kw(Kw::Let | Kw::Var)) && at(2).is_some_and(|t| t.is(P::Eq)) && at(3).is_some_and(|t| t.is(P::LBracket)) {
            let mut items = Vec::new();
            let mut j = k + 4;
            while let Some(s) = toks.get(j).and_then(str_of) {
                items.push(s);
                j += 1;
                if toks.get(j).is_some_and(|t| t.is(P::Comma)) {
                    j += 1;
                }
            }
            if toks.get(j).is_some_and(|t| t.is(P::RBracket)) {
                lists.push((text_of(&toks[k + 1]), items));
            }
        } else if t.kind == TokKind::Kw(Kw::For) && at(1).is_some_and(|t| t.is(P::LParen)) && at(3).is_some_and(|t| t.kind == TokKind::Kw(Kw::In)) && at(5).is_some_and(|t| t.is(P::RParen)) {
            loops.push((text_of(&toks[k + 2]), text_of(&toks[k + 4])));
        } else if t.kind == TokKind::Ident && text_of(t) == "register_native_path" && at(1).is_some_and(|t| t.is(P::LParen)) && at(7).is_some_and(|t| t.is(P::RParen)) {
            if let (Some(a), Some(b), Some(c)) = (at(2).and_then(str_of), at(4).and_then(str_of), at(6).and_then(str_of)) {
                calls.push([a, b, c]);
            }
        }
    }
    let project = pack.to_string_lossy().into_owned();
    let mut out = Vec::new();
    for call in calls {
        let vars: Vec<String> = call.iter().flat_map(|s| placeholders(s)).filter(|v| v != "project_path").collect();
        let mut bindings: Vec<Vec<(String, String)>> = vec![vec![("project_path".into(), project.clone())]];
        let mut readable = true;
        for v in dedup(vars) {
            let values = loops.iter().find(|l| l.0 == v).and_then(|l| lists.iter().find(|x| x.0 == l.1)).map(|x| x.1.clone());
            let Some(values) = values else {
                readable = false;
                break;
            };
            let mut next = Vec::new();
            for b in &bindings {
                for val in &values {
                    let mut b = b.clone();
                    b.push((v.clone(), val.clone()));
                    next.push(b);
                }
            }
            bindings = next;
        }
        if !readable {
            continue;
        }
        for b in bindings {
            let [p, r, f] = call.clone().map(|s| substitute(&s, &b));
            if let (Some(p), Some(r), Some(f)) = (p, r, f) {
                out.push((p, r, PathBuf::from(f)));
            }
        }
    }
    out
}

fn dedup(mut v: Vec<String>) -> Vec<String> {
    v.sort();
    v.dedup();
    v
}

/// The `{name}`s of an interpolated string.
fn placeholders(s: &str) -> Vec<String> {
    s.split('{').skip(1).filter_map(|p| p.split_once('}').map(|(n, _)| n.trim().to_string())).collect()
}

/// `s` with each `{name}` replaced; `None` if one is not bound.
fn substitute(s: &str, bindings: &[(String, String)]) -> Option<String> {
    let mut out = String::new();
    let mut rest = s;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        let (name, after) = rest[i + 1..].split_once('}')?;
        out.push_str(&bindings.iter().find(|b| b.0 == name.trim())?.1);
        rest = after;
    }
    out.push_str(rest);
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn das_module_registrations_are_read_without_running_them() {
        let t = tempfile::tempdir().unwrap();
        let pack = t.path().join("dasPack");
        std::fs::create_dir(&pack).unwrap();
        let text = "options gen2\nrequire daslib/fio\n[export]\ndef initialize(project_path : string) {\n    register_native_path(\"one\", \"solo\", \"{project_path}/x/solo.das\")\n    let names = [\n        \"a\", \"b\"\n    ]\n    for (n in names) {\n        register_native_path(\"two\", \"{n}\", \"{project_path}/lib/{n}.das\")\n    }\n    register_native_path(\"three\", \"{unknown}\", \"{project_path}/{unknown}.das\")\n}\n";
        let got = registrations(&pack, text);
        let want = [("one", "solo", pack.join("x/solo.das")), ("two", "a", pack.join("lib/a.das")), ("two", "b", pack.join("lib/b.das"))];
        assert_eq!(got.len(), want.len(), "{got:?}");
        for (g, w) in got.iter().zip(want) {
            assert_eq!((g.0.as_str(), g.1.as_str(), &g.2), (w.0, w.1, &w.2));
        }
        assert!(registrations(&pack, "def initialize(project_path : string) {\n    register_native_path(\"x\", y, \"{project_path}/z.das\")\n}\n").is_empty());
    }
}
