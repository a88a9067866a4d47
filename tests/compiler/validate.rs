//! Every emitted output passes the independent validators: glslangValidator
//! on each GLSL file (both profiles) and on each linkable vertex+fragment
//! pair, spirv-val on each SPIR-V module, tint on each WGSL module. Runs on the golden outputs (which
//! tests/compiler/golden.rs proves are exactly what the compiler emits) and on the
//! tutorial compiled verbatim.

use crate::support;

use std::path::Path;

#[test]
fn golden_outputs_pass_the_validators() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut runs = 0;
    for e in std::fs::read_dir(&root).expect("tests/golden exists") {
        let dir = e.unwrap().path();
        let stem = dir.file_name().unwrap().to_string_lossy().into_owned();
        let manifest = std::fs::read_to_string(dir.join(format!("{stem}.reflect.json"))).expect("every golden dir has a manifest");
        let r: umbrac::Reflection = serde_json::from_str(&manifest).expect("manifest parses");
        runs += support::validate_dir(&dir, &r);
    }
    eprintln!("{runs} validator runs");
}

/// The tutorial, host code and all, compiles as a whole file and its four
/// entry points validate.
#[test]
fn tutorial_compiles_verbatim_and_validates() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/08_shadow.das");
    if !path.exists() {
        eprintln!("skipping: {} is not present", path.display());
        return;
    }
    let c = umbrac::compile_file(&path, &umbrac::Options::default());
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("the tutorial does not compile:\n{}", c.render_diagnostics()));
    assert!(c.diagnostics.is_empty(), "{}", c.render_diagnostics());
    let names: Vec<&str> = compiled.reflection.entry_points.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["shadow_vs", "shadow_fs", "main_vs", "main_fs"]);
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &compiled.artifacts);
    let runs = support::validate_dir(dir.path(), &compiled.reflection);
    if support::require_tool("glslangValidator") {
        // 8 GLSL files, 2 profiles x 2 linked programs, 1 SPIR-V module.
        assert!(runs >= 8 + 4 + 1, "only {runs} validator runs");
    }
    // The shadow pass vertex shader declares what it reaches and nothing else.
    let vs = compiled.artifact("shadow_vs.330.vert").unwrap().text().into_owned();
    for name in ["uniform mat4x4 u_light_vp;", "uniform mat4x4 u_model;", "layout(location = 0) in vec3 a_pos;"] {
        assert!(vs.contains(name), "shadow_vs lacks {name}:\n{vs}");
    }
    // Source names only: none made up by location.
    for a in &compiled.artifacts {
        let text = a.text();
        assert!(!text.contains("_p2vs_") && !text.contains("_vs2fs_") && !text.contains("_fs2p_") && !text.contains("_block"), "{}:\n{text}", a.file_name);
    }
    for name in ["u_view", "u_proj", "u_light_dir", "u_cam_pos", "u_is_floor", "shadow_map", "a_normal", "pcf_shadow"] {
        assert!(!vs.contains(name), "shadow_vs declares {name}:\n{vs}");
    }
}
