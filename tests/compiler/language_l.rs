//! Issue 17 (builtins, conversions, modules, types): what the corpus and
//! the feature matrix cannot show with one first error or one snippet per
//! target. Modules are followed only as far as shaders reach, found in
//! `-I` and `--daslib` directories, read once; `half` compiles for exactly
//! the targets that have it; a folded constant is the same literal in
//! every output.

use std::path::Path;

use umbrac::{Options, Target};

fn write(dir: &Path, name: &str, text: &str) {
    let p = dir.join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}

const SHADER: &str = "require lib/util\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(BODY)\n}\n";

/// A module's own `require`s are followed once a shader reaches into it:
/// its missing file path is no error while nothing of it is used, and an
/// error with the require chain once something is.
#[test]
fn module_requires_are_followed_as_far_as_shaders_reach() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lib/util.das", "require ./missing_helpers.das\ndef scale(x : float) : float {\n    return x * 2.0\n}\n");
    write(dir.path(), "untouched.das", &SHADER.replace("BODY", "1.0"));
    write(dir.path(), "reached.das", &SHADER.replace("BODY", "scale(0.5)"));
    let c = umbrac::compile_file(&dir.path().join("untouched.das"), &Options::default());
    assert!(c.result.is_some() && c.diagnostics.is_empty(), "{}", c.render_diagnostics());
    let c = umbrac::compile_file(&dir.path().join("reached.das"), &Options::default());
    let text = c.render_diagnostics();
    assert!(c.result.is_none(), "compiles:\n{text}");
    assert!(text.contains("cannot find module `./missing_helpers.das`") && text.contains("required from"), "{text}");
}

/// `-I` directories, `--daslib`, a module required twice (read once), and
/// `--entry`: only the entry point asked for, with what it reaches.
#[test]
fn modules_come_from_include_and_daslib_directories_once() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "inc/shaderlib/color.das", "require daslib/tone\nlet GREY = float3(0.5)\ndef tint(c : float3) : float3 {\n    return tone_curve(c) * GREY\n}\n");
    write(dir.path(), "das/daslib/tone.das", "module tone\ndef tone_curve(c : float3) : float3 {\n    return c / (c + float3(1.0))\n}\ndef host {\n    print(\"{not shader code}\")\n}\n");
    let main = "require shaderlib/color\nrequire shaderlib/color\nvar @out f_color : float4\n[fragment_program]\ndef a_fs {\n    f_color = float4(tint(float3(1.0)), 1.0)\n}\n[fragment_program]\ndef b_fs {\n    f_color = float4(1.0)\n}\n";
    write(dir.path(), "src/main.das", main);
    let opts = Options { include_dirs: vec![dir.path().join("inc")], daslib: Some(dir.path().join("das/daslib")), entries: vec!["b_fs".into()], targets: vec![Target::Glsl330], ..Default::default() };
    let c = umbrac::compile_file(&dir.path().join("src/main.das"), &opts);
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let b = compiled.artifact("b_fs.330.frag").unwrap().text().into_owned();
    assert!(!b.contains("tint") && !b.contains("tone_curve"), "{b}");
    let opts = Options { entries: vec!["a_fs".into()], ..opts };
    let c = umbrac::compile_file(&dir.path().join("src/main.das"), &opts);
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let a = compiled.artifact("a_fs.330.frag").unwrap().text().into_owned();
    assert!(a.contains("tone_curve(") && a.matches("vec3 tint(").count() == 1, "{a}");
    // The two modules were read once each.
    let read: Vec<String> = c.files_read().iter().map(|p| p.display().to_string()).collect();
    assert_eq!(read.iter().filter(|p| p.ends_with("color.das")).count(), 1, "{read:?}");
    assert_eq!(read.iter().filter(|p| p.ends_with("tone.das")).count(), 1, "{read:?}");
    // Without --daslib, `daslib/tone` is missing, and the unknown name says so.
    let opts = Options { daslib: None, ..opts };
    let c = umbrac::compile_file(&dir.path().join("src/main.das"), &opts);
    let text = c.render_diagnostics();
    assert!(text.contains("unknown function `tone_curve`") && text.contains("module `daslib/tone` not found"), "{text}");
}

/// A name nothing defines shows the modules that were not found, but not
/// daslang's builtin modules or its host packs.
#[test]
fn unknown_names_show_only_modules_that_could_define_them() {
    let src = "require math\nrequire glfw/glfw_boost\nrequire opengl/opengl_boost\nrequire mylib/noise\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(fbm(1.0))\n}\n";
    let c = umbrac::compile_source("x.das", src, &Options::default());
    let d = c.diagnostics.iter().find(|d| d.is_error()).expect("an error");
    assert!(d.message.contains("unknown function `fbm`"), "{}", c.render_diagnostics());
    let labels: Vec<&str> = d.secondary.iter().map(|(_, l)| l.as_str()).collect();
    assert_eq!(labels, ["module `mylib/noise` not found: it may define this"], "{}", c.render_diagnostics());
}

/// `half` compiles for every set of targets that has it, and fails naming
/// exactly the requested ones that do not.
#[test]
fn half_compiles_for_exactly_the_targets_that_have_it() {
    let src = "var @out f_color : float4\n[fragment_program]\ndef fs {\n    let h = half3(0.25h, 0.5h, 1.0h) * half(2)\n    f_color = float4(float3(h), 1.0)\n}\n";
    for targets in [vec![Target::Wgsl], vec![Target::Spirv], vec![Target::Wgsl, Target::Spirv]] {
        let c = umbrac::compile_source("h.das", src, &Options { targets: targets.clone(), ..Default::default() });
        assert!(c.result.is_some(), "{targets:?}: {}", c.render_diagnostics());
    }
    let cases: [(Vec<Target>, &str); 4] = [
        (vec![], "the glsl330 and gles300 targets"),
        (vec![Target::Glsl330, Target::Wgsl], "the glsl330 target"),
        (vec![Target::Gles300], "the gles300 target"),
        (vec![Target::Glsl330, Target::Gles300, Target::Spirv], "the glsl330 and gles300 targets"),
    ];
    for (targets, names) in cases {
        let c = umbrac::compile_source("h.das", src, &Options { targets: targets.clone(), ..Default::default() });
        let errors: Vec<&str> = c.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.message.as_str()).collect();
        assert!(c.result.is_none() && errors == [format!("`half` is not supported by {names}")], "{targets:?}: {errors:?}");
    }
}

/// A constant folded from builtin calls is one literal, the same in the
/// GLSL, WGSL and SPIR-V outputs (shortest round-trip digits of one f32).
#[test]
fn folded_constants_are_one_literal_in_every_output() {
    let src = "let SUN : float3 = normalize(float3(0.45, 0.55, 0.85))\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(SUN, 1.0)\n}\n";
    let c = umbrac::compile_source("k.das", src, &Options::default());
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let x = (0.45f32 as f64) / ((0.45f32 as f64).powi(2) + (0.55f32 as f64).powi(2) + (0.85f32 as f64).powi(2)).sqrt();
    let x = x as f32;
    let digits = format!("{x:?}");
    for file in ["fs.330.frag", "fs.300es.frag", "k.wgsl"] {
        let text = compiled.artifact(file).unwrap().text().into_owned();
        assert!(text.contains(&digits), "{file} lacks {digits}:\n{text}");
    }
    let spv = &compiled.artifact("k.spv").unwrap().contents;
    let words: Vec<u32> = spv.chunks_exact(4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]])).collect();
    assert!(words.contains(&x.to_bits()), "the SPIR-V module lacks {x:?} ({:#x})", x.to_bits());
}

/// Modules requiring modules stop at `MAX_MODULE_DEPTH`, with an error at
/// the `require` that goes too deep; as many files as `MAX_MODULES` are read.
#[test]
fn module_limits() {
    use umbrac::syntax::modules::{MAX_MODULES, MAX_MODULE_DEPTH};
    let dir = tempfile::tempdir().unwrap();
    let n = MAX_MODULE_DEPTH + 2;
    for i in 0..n {
        let next = if i + 1 < n { format!("require m{}\n", i + 1) } else { String::new() };
        let call = if i + 1 < n { format!("f{}(x)", i + 1) } else { "x".into() };
        write(dir.path(), &format!("m{i}.das"), &format!("{next}def f{i}(x : float) : float {{\n    return {call}\n}}\n"));
    }
    write(dir.path(), "deep.das", "require m0\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(f0(1.0))\n}\n");
    let c = umbrac::compile_file(&dir.path().join("deep.das"), &Options::default());
    let text = c.render_diagnostics();
    assert!(c.result.is_none() && text.contains(&format!("modules require each other too deeply (limit {MAX_MODULE_DEPTH})")), "{text}");

    let wide = tempfile::tempdir().unwrap();
    let mut main = String::new();
    for i in 0..=MAX_MODULES {
        write(wide.path(), &format!("w{i}.das"), "let UNUSED = 1\n");
        main.push_str(&format!("require w{i}\n"));
    }
    main.push_str("var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n");
    write(wide.path(), "wide.das", &main);
    let c = umbrac::compile_file(&wide.path().join("wide.das"), &Options::default());
    let text = c.render_diagnostics();
    assert!(c.result.is_none() && text.contains(&format!("too many modules (limit {MAX_MODULES})")), "{text}");
}

/// Modules that require each other are each read once.
#[test]
fn cyclic_requires_end() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "a.das", "require b\ndef fa(x : float) : float {\n    return fb(x) + 1.0\n}\n");
    write(dir.path(), "b.das", "require a\ndef fb(x : float) : float {\n    return x * 2.0\n}\n");
    write(dir.path(), "main.das", "require a\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(fa(1.0))\n}\n");
    let c = umbrac::compile_file(&dir.path().join("main.das"), &Options::default());
    assert!(c.result.is_some() && c.diagnostics.is_empty(), "{}", c.render_diagnostics());
    assert_eq!(c.files_read().len(), 3, "{:?}", c.files_read());
}

/// A module's `let { ... }` block and module variable, and a uniform's
/// default, all from builtin calls folded at compile time.
#[test]
fn module_let_blocks_variables_and_defaults_fold_builtin_calls() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lib.das", "let {\n    SUN = normalize(float3(1.0, 2.0, 2.0))\n    K = PI / 4.0\n}\nvar counter = 0\ndef bump : float {\n    counter++\n    return float(counter) * K\n}\n");
    write(dir.path(), "main.das", "require lib\nvar @uniform u_dir : float3 = normalize(float3(0.0, 3.0, 4.0))\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(SUN * bump() + u_dir, 1.0)\n}\n");
    let c = umbrac::compile_file(&dir.path().join("main.das"), &Options { targets: vec![Target::Wgsl], ..Default::default() });
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let wgsl = compiled.artifact("main.wgsl").unwrap().text().into_owned();
    assert!(wgsl.contains("const SUN: vec3<f32> = vec3<f32>(0.33333334f, 0.6666667f, 0.6666667f);") && wgsl.contains("var<private> counter: i32"), "{wgsl}");
    let json = serde_json::to_string(&compiled.reflection).unwrap();
    assert!(json.contains("\"default\""), "{json}");
}
