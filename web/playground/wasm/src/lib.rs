//! umbrac's compiler for the playground page: one call, a program's text
//! in, one [`umbrac::bundle::Bundle`] (JSON) out, the same document
//! `umbrac preview` serves, so the page reads one shape.
//!
//! There is no file system here: the program and any files it includes
//! come from the page (`files` in the options), through the same overlay
//! of texts the language server's open documents use.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use serde_json::Value;
use umbrac::bundle::Bundle;
use umbrac::diag::Diagnostic;
use umbrac::source::SourceMap;
use umbrac::{Compilation, Conventions, Options, Target};
use wasm_bindgen::prelude::wasm_bindgen;

thread_local! {
    /// The message of the last panic: a panic aborts the module (a trap the
    /// page catches), and the page asks for it before starting a new one.
    static LAST_PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        let msg = info.to_string();
        LAST_PANIC.with(|p| p.replace(msg));
    }));
}

/// The last panic's message ("" when none): an internal compiler error.
#[wasm_bindgen]
pub fn last_panic() -> String {
    LAST_PANIC.with(|p| p.borrow().clone())
}

/// umbrac's version, for the page's footer.
#[wasm_bindgen]
pub fn version() -> String {
    umbrac::VERSION.to_string()
}

/// Compiles `source` as the file `name` and returns the bundle's JSON.
///
/// `options_json` is an object, every key optional: `targets` (CLI names,
/// `["glsl330", "wgsl"]`; none: the defaults), `defines` (`{"NAME":
/// "VALUE" | null}`), `entries` (entry point names), `conventions`
/// (`"portable"` | `"native"`) and `files` (`{"path": "text"}`: what an
/// `#include` or `require` reads, paths relative to `name`'s folder as
/// written). Bad options are an error in the bundle, like a bad program.
#[wasm_bindgen]
pub fn compile(name: &str, source: &str, options_json: &str) -> String {
    let compilation = match parse_options(options_json) {
        Ok((opts, files)) => {
            let name = if name.is_empty() { "playground.das" } else { name };
            umbrac::syntax::overlay::with(files, || umbrac::compile_source(name, source, &opts))
        }
        Err(msg) => Compilation {
            sources: SourceMap::new(),
            diagnostics: vec![Diagnostic::error_nowhere(format!("playground options: {msg}"))],
            suppressed_errors: 0,
            result: None,
        },
    };
    Bundle::of(&compilation).to_json()
}

/// Compiles `source` and says whether it compiled, without making the
/// bundle: what web/playground/bench.mjs times against the native library.
#[wasm_bindgen]
pub fn compile_only(name: &str, source: &str) -> bool {
    !umbrac::compile_source(name, source, &Options::default()).has_errors()
}

fn parse_options(json: &str) -> Result<(Options, umbrac::syntax::overlay::Texts), String> {
    let v: Value = if json.trim().is_empty() { Value::Object(Default::default()) } else { serde_json::from_str(json).map_err(|e| e.to_string())? };
    let obj = v.as_object().ok_or("expected a JSON object")?;
    // Only what the page gave exists: an include may name any of it.
    let mut opts = Options { allow_outside_includes: true, ..Options::default() };
    let mut files = HashMap::new();
    for (key, value) in obj {
        match key.as_str() {
            "targets" => {
                for t in strings(value, key)? {
                    opts.targets.push(Target::from_name(t).ok_or_else(|| format!("unknown target `{t}`"))?);
                }
            }
            "entries" => opts.entries = strings(value, key)?.into_iter().map(String::from).collect(),
            "defines" => {
                let defs = value.as_object().ok_or("`defines` is an object of names to values or null")?;
                for (name, val) in defs {
                    let val = match val {
                        Value::Null => None,
                        Value::String(s) => Some(s.clone()),
                        other => Some(other.to_string()),
                    };
                    opts.defines.push((name.clone(), val));
                }
            }
            "conventions" => {
                opts.conventions = match value.as_str() {
                    Some("portable") => Conventions::Portable,
                    Some("native") => Conventions::Native,
                    _ => return Err("`conventions` is \"portable\" or \"native\"".into()),
                }
            }
            "files" => {
                let map = value.as_object().ok_or("`files` is an object of paths to texts")?;
                for (path, text) in map {
                    let text = text.as_str().ok_or_else(|| format!("`files.{path}` is not text"))?;
                    files.insert(umbrac::syntax::overlay::normalize(&PathBuf::from(path)), text.to_string());
                }
            }
            other => return Err(format!("unknown option `{other}`")),
        }
    }
    Ok((opts, Arc::new(files)))
}

fn strings<'a>(v: &'a Value, key: &str) -> Result<Vec<&'a str>, String> {
    let arr = v.as_array().ok_or_else(|| format!("`{key}` is an array of strings"))?;
    arr.iter().map(|s| s.as_str().ok_or_else(|| format!("`{key}` is an array of strings"))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const PROGRAM: &str = "var @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = float4(1.0, 0.5, 0.25, 1.0)\n}\n";

    #[test]
    fn compiles_to_a_bundle_with_the_spirv_disassembled() {
        let v: Value = serde_json::from_str(&compile("t.das", PROGRAM, "{}")).unwrap();
        assert_eq!(v["ok"], true, "{v}");
        let spv = v["files"].as_array().unwrap().iter().find(|f| f["target"] == "spirv").unwrap();
        assert!(spv["disassembly"].as_str().unwrap().contains("OpEntryPoint Fragment"));
    }

    #[test]
    fn options_choose_targets_and_bad_options_are_errors() {
        let v: Value = serde_json::from_str(&compile("t.das", PROGRAM, r#"{"targets":["wgsl"]}"#)).unwrap();
        let targets: Vec<_> = v["files"].as_array().unwrap().iter().filter_map(|f| f["target"].as_str()).collect();
        assert_eq!(targets, ["wgsl"]);
        let v: Value = serde_json::from_str(&compile("t.das", PROGRAM, r#"{"targets":["hlsl"]}"#)).unwrap();
        assert_eq!(v["ok"], false);
        assert!(v["diagnostics"][0]["message"].as_str().unwrap().contains("unknown target `hlsl`"), "{v}");
    }

    #[test]
    fn includes_come_from_the_files_the_page_gave() {
        let main = "#include \"colour.das\"\nvar @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = COLOUR\n}\n";
        let opts = r##"{"files":{"colour.das":"#define COLOUR float4(1.0, 0.0, 0.0, 1.0)\n"}}"##;
        let v: Value = serde_json::from_str(&compile("main.das", main, opts)).unwrap();
        assert_eq!(v["ok"], true, "{v}");
    }
}
