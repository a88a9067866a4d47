//! One compilation as one JSON document: what a page needs to show and
//! draw a program (the diagnostics, every output, the manifest).
//!
//! The preview server (`umbrac preview`) sends it over HTTP and the
//! playground's WebAssembly build returns it from its `compile` call, so
//! the page reads one shape whichever side compiled. The shape is
//! documented in docs/preview.md; it only grows (new keys), so a page
//! keeps reading older bundles.

use crate::diag::{Diagnostic, JsonDiagnostic};
use crate::target::Artifact;
use crate::Compilation;

/// One output file. Text outputs carry `text`; SPIR-V carries its words.
#[derive(Debug)]
pub struct BundleFile {
    /// `main_vs.300.vert`, `shadow.wgsl`, `shadow.spv`, `shadow.json`, ...
    pub name: String,
    /// The target's CLI name (`glsl330`, `wgsl`, ...); `None` for the manifest.
    pub target: Option<&'static str>,
    /// The entry point, for per-entry-point outputs (the GLSL files).
    pub entry: Option<String>,
    pub text: Option<String>,
    pub words: Option<Vec<u32>>,
    /// SPIR-V in assembly text (feature `spirv-text`), for reading.
    pub disassembly: Option<String>,
}

serialize_struct!(BundleFile {
    "name": name,
    "target": target?,
    "entry": entry?,
    "text": text?,
    "words": words?,
    "disassembly": disassembly?,
});

/// A compilation as a page reads it.
#[derive(Debug)]
pub struct Bundle {
    /// No errors: `files` and `manifest` are there.
    pub ok: bool,
    /// As `--message-format json` prints them (file, line, column, the
    /// rendered excerpt), the cap's note last.
    pub diagnostics: Vec<JsonDiagnostic>,
    pub files: Vec<BundleFile>,
    /// The reflection manifest, parsed (the object the `.json` output holds).
    pub manifest: Option<serde_json::Value>,
    /// The scene the program is drawn with when no scene file is given
    /// (`umbrac::scene::Scene::infer`, as JSON; docs/runner.md, "Scene
    /// files"): absent on errors, and for a program no scene draws (a
    /// compute program).
    pub scene: Option<serde_json::Value>,
    /// The program's text and its included files' (`{name, text, files}`):
    /// set by the preview server for the playground it serves, whose
    /// editor shows them (docs/preview.md); absent elsewhere.
    pub source: Option<serde_json::Value>,
}

serialize_struct!(Bundle {
    "ok": ok,
    "diagnostics": diagnostics,
    "files": files,
    "manifest": manifest?,
    "scene": scene?,
    "source": source?,
});

impl Bundle {
    pub fn of(c: &Compilation) -> Bundle {
        let mut diagnostics: Vec<JsonDiagnostic> = c.diagnostics.iter().map(|d| d.to_json(&c.sources)).collect();
        if c.suppressed_errors > 0 {
            diagnostics.push(Diagnostic::suppressed(c.suppressed_errors).to_json(&c.sources));
        }
        let artifacts: &[Artifact] = c.result.as_ref().map(|r| r.artifacts.as_slice()).unwrap_or(&[]);
        let files = artifacts.iter().map(file_of).collect();
        let manifest = artifacts
            .iter()
            .find(|a| a.target.is_none())
            .and_then(|a| serde_json::from_slice(&a.contents).ok());
        Bundle { ok: !c.has_errors(), diagnostics, files, manifest, scene: scene_of(c), source: None }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a bundle is plain data")
    }
}

#[cfg(feature = "scene")]
fn scene_of(c: &Compilation) -> Option<serde_json::Value> {
    let r = c.result.as_ref().filter(|_| !c.has_errors())?;
    crate::scene::Scene::infer(&r.reflection).ok().map(|s| s.to_json())
}

#[cfg(not(feature = "scene"))]
fn scene_of(_: &Compilation) -> Option<serde_json::Value> {
    None
}

fn file_of(a: &Artifact) -> BundleFile {
    let binary = a.target == Some(crate::Target::Spirv);
    let words: Option<Vec<u32>> = binary.then(|| a.contents.chunks_exact(4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]])).collect());
    BundleFile {
        name: a.file_name.clone(),
        target: a.target.map(|t| t.name()),
        entry: a.entry.clone(),
        text: (!binary).then(|| a.text().into_owned()),
        disassembly: words.as_deref().and_then(disassemble),
        words,
    }
}

/// SPIR-V words as assembly text; `None` where the feature is off (or, a
/// bug, the words umbrac wrote do not parse).
#[cfg(feature = "spirv-text")]
fn disassemble(words: &[u32]) -> Option<String> {
    use rspirv::binary::Disassemble;
    rspirv::dr::load_words(words).ok().map(|m| m.disassemble())
}

#[cfg(not(feature = "spirv-text"))]
fn disassemble(_: &[u32]) -> Option<String> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_good_program_carries_every_output_and_the_manifest() {
        let src = "var @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = float4(1.0, 0.5, 0.25, 1.0)\n}\n";
        let c = crate::compile_source("t.das", src, &crate::Options::default());
        let b = Bundle::of(&c);
        assert!(b.ok, "{}", c.render_diagnostics());
        assert!(b.files.iter().any(|f| f.name.ends_with(".wgsl") && f.text.as_deref().is_some_and(|t| t.contains("@fragment"))));
        assert!(b.files.iter().filter(|f| f.words.is_some()).all(|f| f.words.as_ref().unwrap()[0] == 0x0723_0203));
        assert!(b.manifest.is_some());
        // Assembly text only where the feature asks for it.
        let spv = b.files.iter().find(|f| f.words.is_some()).unwrap();
        assert_eq!(spv.disassembly.as_deref().is_some_and(|d| d.contains("OpEntryPoint Fragment")), cfg!(feature = "spirv-text"));
        let json: serde_json::Value = serde_json::from_str(&b.to_json()).unwrap();
        assert_eq!(json["ok"], true);
    }

    #[cfg(feature = "scene")]
    #[test]
    fn a_drawable_program_carries_its_inferred_scene() {
        let src = "var @out f_color : float4\n[vertex_program]\ndef vs {\n    gl_Position = float4(float(gl_VertexID), 0.0, 0.0, 1.0)\n}\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n";
        let json: serde_json::Value = serde_json::from_str(&Bundle::of(&crate::compile_source("t.das", src, &crate::Options::default())).to_json()).unwrap();
        assert_eq!(json["scene"]["passes"][0]["draws"][0]["mesh"], "none", "three vertices: {}", json["scene"]);
        assert_eq!(json["scene"]["passes"][0]["color"], "screen");
    }

    #[test]
    fn a_bad_program_carries_located_diagnostics_and_no_outputs() {
        let c = crate::compile_source("t.das", "var @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = nope\n}\n", &crate::Options::default());
        let json: serde_json::Value = serde_json::from_str(&Bundle::of(&c).to_json()).unwrap();
        assert_eq!(json["ok"], false);
        assert!(json["files"].as_array().unwrap().is_empty());
        assert_eq!(json["diagnostics"][0]["location"]["line"], 4);
        assert!(json["manifest"].is_null());
    }
}
