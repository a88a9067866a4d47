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
        // 8 GLSL files, 2 profiles x 2 linked programs, 1 SPIR-V module: 13.
        assert!(runs >= 13, "only {runs} validator runs");
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

/// `@constant_id` constants are `OpSpecConstant`s decorated `SpecId N` in
/// the SPIR-V, with the manifest's defaults, initialising the private
/// variable of the same name that the code loads (issue 36); spirv-val
/// accepts the module, also the SPIR-V 1.3 one with subgroups.
#[test]
fn specialization_constants_are_spec_constants_in_the_spirv() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let spirv_only = |defines: Vec<(String, Option<String>)>| umbrac::Options { targets: vec![umbrac::Target::Spirv], defines, ..Default::default() };
    let cases = [
        ("shaders/features/specialization_constants.das", spirv_only(vec![])),
        ("shaders/compute/spec_reduce.das", spirv_only(vec![("SUBGROUPS".into(), None)])),
    ];
    for (file, opts) in &cases {
        let c = umbrac::compile_file(&root.join(file), opts);
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{file}:\n{}", c.render_diagnostics()));
        let spec = compiled.reflection.specialization_constants.clone().expect("specialization constants in the manifest");
        let spv = compiled.artifacts.iter().find(|a| a.file_name.ends_with(".spv")).expect("a SPIR-V module");
        let words: Vec<u32> = spv.contents.chunks_exact(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
        // The words: (opcode, operands) of each instruction.
        let mut insts = Vec::new();
        let mut at = 5;
        while at < words.len() {
            let n = (words[at] >> 16) as usize;
            insts.push((words[at] & 0xffff, &words[at + 1..at + n]));
            at += n;
        }
        for s in &spec {
            assert_eq!(s.spirv, "spec_constant", "{file}: {}", s.name);
            // OpDecorate %id SpecId N, once.
            let ids: Vec<u32> = insts.iter().filter(|(op, o)| *op == 71 && o[1] == 1 && o[2] == s.id).map(|(_, o)| o[0]).collect();
            let [id] = ids[..] else { panic!("{file}: {} ids decorated SpecId {}", ids.len(), s.id) };
            // Its definition: OpSpecConstant with the default's bits, or
            // OpSpecConstantTrue/False.
            let def = insts.iter().find(|(op, o)| matches!(op, 48..=50) && o[1] == id).unwrap_or_else(|| panic!("{file}: no spec constant %{id} for {}", s.name));
            match s.ty.as_str() {
                "bool" => assert_eq!(def.0, if s.default_bits == 1 { 48 } else { 49 }, "{file}: {}", s.name),
                _ => assert_eq!((def.0, def.1[2]), (50, s.default_bits), "{file}: {}", s.name),
            }
            // A private variable (storage class 6) it initialises.
            assert!(insts.iter().any(|(op, o)| *op == 59 && o.len() == 4 && o[2] == 6 && o[3] == id), "{file}: no variable initialised with {}", s.name);
        }
        let dir = tempfile::tempdir().unwrap();
        let paths = support::write_all(dir.path(), &compiled.artifacts);
        let spv_path = paths.iter().find(|p| p.extension().is_some_and(|e| e == "spv")).unwrap();
        if support::require_tool("spirv-val") {
            support::spirv_val(spv_path).unwrap_or_else(|e| panic!("{file}: {e}"));
        }
        if support::require_tool("spirv-dis") {
            let out = std::process::Command::new("spirv-dis").arg(spv_path).output().expect("spirv-dis runs");
            let text = String::from_utf8_lossy(&out.stdout);
            for s in &spec {
                assert!(text.contains(&format!(" SpecId {}\n", s.id)), "{file}: no SpecId {}:\n{text}", s.id);
            }
            assert!(text.contains("OpSpecConstant"), "{file}:\n{text}");
        }
    }
    // Without SPIR-V among the targets, the program is lowered once.
    let c = umbrac::compile_file(&root.join(cases[0].0), &umbrac::Options { targets: vec![umbrac::Target::Wgsl], ..Default::default() });
    assert!(c.result.as_ref().expect("compiles for WGSL").lowered.spirv.is_none());
}
