//! The built playground (scripts/build-playground.sh) served by `umbrac
//! preview` under `/playground/`, with the previewed file loaded: one page
//! that is the editor, every output and the live picture of the file on
//! disk (docs/preview.md, "The playground with the file loaded").
//!
//! Its files are a fixed list of names, read once when the server starts:
//! a request never reads the disk, as for the built-in page.

use std::path::{Path, PathBuf};

use crate::Compilation;

/// The built playground's files that the page loads, and their types. The
/// glue `umbrac_web.js` is left out: the worker bundle carries it.
pub const FILES: &[(&str, &str)] = &[
    ("index.html", "text/html; charset=utf-8"),
    ("style.css", "text/css; charset=utf-8"),
    ("main.js", "text/javascript; charset=utf-8"),
    ("worker.js", "text/javascript; charset=utf-8"),
    ("umbrac_web_bg.wasm", "application/wasm"),
    ("examples.json", "application/json"),
];

/// The playground's files, in memory.
pub struct Playground {
    dir: PathBuf,
    files: Vec<Vec<u8>>,
}

impl Playground {
    /// Reads every file of [`FILES`] from `dir`; a missing one is an error
    /// that says how to build it.
    pub fn load(dir: &Path) -> Result<Playground, String> {
        let files = FILES
            .iter()
            .map(|(name, _)| {
                std::fs::read(dir.join(name)).map_err(|e| {
                    format!("`{}` is not a built playground (`{name}`: {e}); build it with scripts/build-playground.sh", dir.display())
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(Playground { dir: dir.to_path_buf(), files })
    }

    /// Where a cargo build finds the playground built beside it: the
    /// binary is `target/PROFILE/umbrac`, the page `target/playground/`.
    pub fn beside_executable() -> Option<PathBuf> {
        let exe = std::env::current_exe().ok()?;
        let dir = exe.parent()?.parent()?.join("playground");
        dir.join("index.html").is_file().then_some(dir)
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// A file's content type and bytes, by its name in [`FILES`].
    pub fn file(&self, name: &str) -> Option<(&'static str, &[u8])> {
        let i = FILES.iter().position(|(n, _)| *n == name)?;
        Some((FILES[i].1, &self.files[i]))
    }
}

/// What the page learns at `/playground/live.json`: that it runs under a
/// preview server, the file's name as diagnostics give it (the name its
/// own compiles use), where the bundles come from, and the options of the
/// server's compiles, so that an edit compiled in the page gets the same.
pub fn live_json(file: &Path, opts: &crate::Options) -> String {
    let defines: serde_json::Map<String, serde_json::Value> =
        opts.defines.iter().map(|(n, v)| (n.clone(), v.clone().map_or(serde_json::Value::Null, serde_json::Value::String))).collect();
    let conventions = match opts.conventions {
        crate::Conventions::Native => "native",
        crate::Conventions::Portable => "portable",
    };
    serde_json::json!({
        "file": file.display().to_string(),
        "events": "/events",
        "defines": defines,
        "conventions": conventions,
    })
    .to_string()
}

/// The bundle's `source` key: the text the server compiled and the texts
/// of the files it read (`#include`s, `require`d modules), by the names
/// diagnostics give them, so that the page's editor holds the file and
/// its own compiles find the same includes.
pub fn source_of(file: &Path, c: &Compilation) -> serde_json::Value {
    let mut text = None;
    let mut files = serde_json::Map::new();
    for (_, f) in c.sources.files() {
        match &f.path {
            Some(p) if p == file && text.is_none() => text = Some(f.text.clone()),
            Some(_) => {
                files.insert(f.name.clone(), serde_json::Value::String(f.text.clone()));
            }
            None => {}
        }
    }
    serde_json::json!({ "name": file.display().to_string(), "text": text, "files": files })
}
