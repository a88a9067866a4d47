//! The project file, `umbrac.toml`: the options a directory's programs
//! compile with (targets, include directories, the daslang tree, defines,
//! limits), read by the CLI and the language server alike (feature
//! `spec`, for the TOML reader). It is found by walking up from an input
//! file's directory; relative paths in it are relative to its own
//! directory. What a command line or an editor's settings say wins, key by
//! key ([`Project::under`]; docs/editor.md, "The project file").

use std::path::{Path, PathBuf};

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use crate::diag::Diagnostic;
use crate::source::{FileId, SourceMap, Span};
use crate::{Limit, Options, Target};

/// The project file's name.
pub const FILE_NAME: &str = "umbrac.toml";

/// What a project file says; every path absolute.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Project {
    /// The file it was read from.
    pub path: PathBuf,
    pub targets: Vec<Target>,
    pub include_dirs: Vec<PathBuf>,
    pub daslang_root: Option<PathBuf>,
    pub daslib: Option<PathBuf>,
    pub modules: Vec<(String, PathBuf)>,
    pub defines: Vec<(String, Option<String>)>,
    pub limits: Vec<(Limit, u64)>,
    pub strict_limits: bool,
}

/// A project file that cannot be used: the diagnostic and the file it points into.
pub type Error = Box<(SourceMap, Diagnostic)>;

/// The nearest `umbrac.toml` at or above `start` (a file's directory, or
/// the directory itself).
pub fn find(start: &Path) -> Option<PathBuf> {
    let start = std::path::absolute(start).ok()?;
    let first = if start.is_dir() { Some(start.as_path()) } else { start.parent() };
    first?.ancestors().map(|d| d.join(FILE_NAME)).find(|p| p.is_file())
}

/// The options for an input at `start`: `opts` over its project file, if
/// there is one (and which file that was).
pub fn options_for(start: &Path, opts: Options) -> Result<(Options, Option<PathBuf>), Error> {
    match find(start) {
        None => Ok((opts, None)),
        Some(file) => {
            let p = load(&file)?;
            Ok((p.under(opts), Some(file)))
        }
    }
}

/// Reads and parses a project file; errors point into it.
pub fn load(path: &Path) -> Result<Project, Error> {
    let mut map = SourceMap::new();
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => return Err(Box::new((map, Diagnostic::error_nowhere(format!("cannot read the project file `{}`: {e}", path.display()))))),
    };
    let id = map.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
    match parse(&map, id) {
        Ok(p) => Ok(p),
        Err(d) => Err(Box::new((map, d))),
    }
}

impl Project {
    /// `opts` with what they leave unsaid taken from the project: its
    /// targets when `opts` name none; its include directories after
    /// theirs; its daslang root, daslib and `strict-limits` unless they
    /// set them; its modules, defines and limits unless they set the same
    /// prefix, name or limit.
    pub fn under(&self, mut opts: Options) -> Options {
        if opts.targets.is_empty() {
            opts.targets = self.targets.clone();
        }
        opts.include_dirs.extend(self.include_dirs.iter().filter(|d| !opts.include_dirs.contains(d)).cloned().collect::<Vec<_>>());
        opts.daslang_root = opts.daslang_root.or_else(|| self.daslang_root.clone());
        opts.daslib = opts.daslib.or_else(|| self.daslib.clone());
        opts.strict_limits |= self.strict_limits;
        let mut modules: Vec<_> = self.modules.iter().filter(|(p, _)| !opts.modules.iter().any(|(q, _)| q == p)).cloned().collect();
        modules.append(&mut opts.modules);
        opts.modules = modules;
        let mut defines: Vec<_> = self.defines.iter().filter(|(n, _)| !opts.defines.iter().any(|(m, _)| m == n)).cloned().collect();
        defines.append(&mut opts.defines);
        opts.defines = defines;
        let mut limits: Vec<_> = self.limits.iter().filter(|(l, _)| !opts.limits.iter().any(|(m, _)| m == l)).cloned().collect();
        limits.append(&mut opts.limits);
        opts.limits = limits;
        opts
    }
}

/// Parses the project file held in `map` as `file`.
pub fn parse(map: &SourceMap, file: FileId) -> Result<Project, Diagnostic> {
    let f = map.file(file);
    let base = f.base;
    let at = |r: std::ops::Range<usize>| Span::new(base + r.start as u32, base + r.end as u32);
    let path = f.path.clone().unwrap_or_default();
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let doc = DeTable::parse(&f.text).map_err(|e| {
        let span = e.span().map(at).unwrap_or(Span::new(base, base));
        Diagnostic::error(format!("the project file is not valid TOML: {}", e.message().trim_end()), span).with_label("here")
    })?;
    let mut p = Project { path: path.clone(), ..Default::default() };
    let expected = |v: &Spanned<DeValue>, what: &str| {
        Diagnostic::error(format!("expected {what}, found a {}", v.get_ref().type_str()), at(v.span())).with_label(format!("this is a {}", v.get_ref().type_str()))
    };
    let string = |v: &Spanned<DeValue>, what: &str| -> Result<String, Diagnostic> {
        match v.get_ref() {
            DeValue::String(s) => Ok(s.to_string()),
            _ => Err(expected(v, what)),
        }
    };
    let strings = |v: &Spanned<DeValue>, what: &str| -> Result<Vec<(String, Span)>, Diagnostic> {
        let list = v.get_ref().as_array().ok_or_else(|| expected(v, what))?;
        list.iter().map(|x| string(x, "a string").map(|s| (s, at(x.span())))).collect()
    };
    let dir_at = |s: &str, span: Span| -> Result<PathBuf, Diagnostic> {
        let d = dir.join(s);
        if d.is_dir() {
            Ok(d)
        } else {
            Err(Diagnostic::error(format!("`{s}` is not a directory"), span).with_label(format!("not a directory, relative to `{}`", dir.display())))
        }
    };
    for (key, value) in doc.get_ref() {
        match &**key.get_ref() {
            "targets" => {
                for (t, span) in strings(value, "a list of targets: [\"glsl330\", \"wgsl\"]")? {
                    let target = Target::from_name(&t).ok_or_else(|| {
                        let names: Vec<&str> = Target::ALL.iter().map(|t| t.name()).collect();
                        Diagnostic::error(format!("unknown target `{t}`"), span).with_label("no such target").with_note(format!("targets: {}", names.join(", ")))
                    })?;
                    p.targets.push(target);
                }
            }
            "include-dirs" => {
                for (d, span) in strings(value, "a list of directories")? {
                    p.include_dirs.push(dir_at(&d, span)?);
                }
            }
            "daslang-root" => {
                let s = string(value, "a directory")?;
                let d = dir_at(&s, at(value.span()))?;
                crate::syntax::modules::parse_daslang_root(&d.to_string_lossy()).map_err(|e| Diagnostic::error(e, at(value.span())).with_label("here"))?;
                p.daslang_root = Some(d);
            }
            "daslib" => p.daslib = Some(dir_at(&string(value, "a directory")?, at(value.span()))?),
            "strict-limits" => match value.get_ref() {
                DeValue::Boolean(b) => p.strict_limits = *b,
                _ => return Err(expected(value, "true or false")),
            },
            "modules" => {
                for (prefix, d) in value.get_ref().as_table().ok_or_else(|| expected(value, "a table of module prefixes: { PREFIX = \"DIR\" }"))? {
                    p.modules.push((prefix.get_ref().to_string(), dir_at(&string(d, "a directory")?, at(d.span()))?));
                }
            }
            "defines" => {
                for (name, v) in value.get_ref().as_table().ok_or_else(|| expected(value, "a table of defines: { NAME = \"VALUE\" }"))? {
                    let n: &str = name.get_ref();
                    if !crate::variants::is_define_name(n) {
                        return Err(Diagnostic::error(format!("`{n}` is not a preprocessor name"), at(name.span())).with_label("letters, digits and `_`, not starting with a digit"));
                    }
                    let val = match v.get_ref() {
                        DeValue::Boolean(false) => continue,
                        DeValue::Boolean(true) => None,
                        DeValue::String(s) if s.is_empty() => None,
                        DeValue::String(s) if !s.contains(['\n', '\r']) => Some(s.to_string()),
                        DeValue::Integer(i) => Some(i.as_str().to_string()),
                        DeValue::Float(x) => Some(x.as_str().to_string()),
                        _ => return Err(expected(v, "a one-line string, a number or a boolean")),
                    };
                    p.defines.push((n.to_string(), val));
                }
            }
            "limits" => {
                for (name, v) in value.get_ref().as_table().ok_or_else(|| expected(value, "a table of limits: { uniform-blocks = 16 }"))? {
                    let limit = Limit::from_name(name.get_ref()).ok_or_else(|| {
                        let names: Vec<&str> = Limit::ALL.iter().map(|l| l.name()).collect();
                        Diagnostic::error(format!("no limit is named `{}`", name.get_ref()), at(name.span())).with_label("unknown").with_note(format!("limits: {}", names.join(", ")))
                    })?;
                    let n = match v.get_ref() {
                        DeValue::Integer(i) => u64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok(),
                        _ => None,
                    };
                    p.limits.push((limit, n.ok_or_else(|| expected(v, "a count"))?));
                }
            }
            other => {
                return Err(Diagnostic::error(format!("unknown key `{other}` in the project file"), at(key.span()))
                    .with_label("not a project setting")
                    .with_note("settings: targets, include-dirs, daslang-root, daslib, modules, defines, limits, strict-limits"))
            }
        }
    }
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(dir: &Path, text: &str) -> Result<Project, String> {
        let mut map = SourceMap::new();
        let path = dir.join(FILE_NAME);
        let id = map.add(path.display().to_string(), Some(path), text.to_string(), None);
        parse(&map, id).map_err(|d| d.render(&map))
    }

    #[test]
    fn a_project_file_reads_and_its_errors_point_into_it() {
        let d = tempfile::tempdir().unwrap();
        std::fs::create_dir(d.path().join("inc")).unwrap();
        let p = parsed(
            d.path(),
            "targets = [\"wgsl\"]\ninclude-dirs = [\"inc\"]\nstrict-limits = true\n[defines]\nA = true\nB = 2\nC = false\n[limits]\nuniform-blocks = 16\n",
        )
        .unwrap();
        assert_eq!(p.targets, [Target::Wgsl]);
        assert_eq!(p.include_dirs, [d.path().join("inc")]);
        assert_eq!(p.defines, [("A".into(), None), ("B".into(), Some("2".into()))]);
        assert_eq!(p.limits, [(Limit::from_name("uniform-blocks").unwrap(), 16)]);
        assert!(p.strict_limits);
        let e = parsed(d.path(), "targets = [\"wgsl\", \"dx12\"]\n").unwrap_err();
        assert!(e.contains("umbrac.toml:1:20") && e.contains("unknown target `dx12`"), "{e}");
        let e = parsed(d.path(), "include-dirs = [\"nowhere\"]\n").unwrap_err();
        assert!(e.contains("umbrac.toml:1:17") && e.contains("not a directory"), "{e}");
        let e = parsed(d.path(), "\ntarget = 1\n").unwrap_err();
        assert!(e.contains("umbrac.toml:2:1") && e.contains("unknown key `target`"), "{e}");
        let e = parsed(d.path(), "[limits]\nvaryings = -1\n").unwrap_err();
        assert!(e.contains("umbrac.toml:2:12") && e.contains("a count"), "{e}");
        let e = parsed(d.path(), "targets = [").unwrap_err();
        assert!(e.contains("umbrac.toml:1:") && e.contains("not valid TOML"), "{e}");
    }

    #[test]
    fn what_is_set_wins_key_by_key() {
        let p = Project {
            targets: vec![Target::Wgsl],
            include_dirs: vec!["/p/inc".into()],
            daslang_root: Some("/p/das".into()),
            defines: vec![("A".into(), Some("1".into())), ("B".into(), None)],
            limits: vec![(Limit::ALL[0], 20), (Limit::ALL[1], 30)],
            ..Default::default()
        };
        let set = Options {
            targets: vec![Target::Glsl330],
            include_dirs: vec!["/mine".into()],
            defines: vec![("A".into(), Some("2".into()))],
            limits: vec![(Limit::ALL[1], 40)],
            ..Default::default()
        };
        let o = p.under(set);
        assert_eq!(o.targets, [Target::Glsl330]);
        assert_eq!(o.include_dirs, [PathBuf::from("/mine"), PathBuf::from("/p/inc")]);
        assert_eq!(o.daslang_root, Some(PathBuf::from("/p/das")));
        assert_eq!(o.defines, [("B".into(), None), ("A".into(), Some("2".into()))]);
        assert_eq!(o.limits, [(Limit::ALL[0], 20), (Limit::ALL[1], 40)]);
        assert_eq!(p.under(Options::default()).targets, [Target::Wgsl]);
    }

    #[test]
    fn found_by_walking_up() {
        let d = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(d.path().join("a/b")).unwrap();
        std::fs::write(d.path().join(FILE_NAME), "").unwrap();
        std::fs::write(d.path().join("a/b/x.das"), "").unwrap();
        assert_eq!(find(&d.path().join("a/b/x.das")), Some(d.path().join(FILE_NAME)));
        assert_eq!(find(&d.path().join("a")), Some(d.path().join(FILE_NAME)));
    }
}
