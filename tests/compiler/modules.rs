//! Issue 35: `require` resolved as daslang resolves it (relative paths, the
//! daslib root, module prefixes of a daslang tree, `--module`), and
//! daslang's builtin-declaring modules (`daslib/shader_lingua_franca`,
//! `glsl/glsl_common`, `spirv/spirv_builtins`) read as declarations of
//! builtins. The daslang tree is `../shared/reference/daslang` (missing:
//! skipped, or failed with `CI=true`); `tests/bad_inputs/include/daslang/`
//! is a small tree of our own with a registered and a folder prefix.

use std::path::{Path, PathBuf};

use crate::support;
use umbrac::{Compilation, Options};

fn daslang_tree() -> Option<PathBuf> {
    let dir = support::repo().join("../shared/reference/daslang");
    if dir.join("daslib/shader_lingua_franca.das").is_file() {
        Some(dir)
    } else {
        support::skip(format!("no daslang tree at {}", dir.display()));
        None
    }
}

fn own_tree() -> PathBuf {
    support::repo().join("tests/bad_inputs/include/daslang")
}

fn compile(path: &Path, opts: &Options) -> Compilation {
    umbrac::compile_file(path, opts)
}

fn read_names(c: &Compilation) -> Vec<String> {
    c.files_read().iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect()
}

fn outputs(c: &Compilation) -> Vec<(String, Vec<u8>)> {
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    compiled.artifacts.iter().map(|a| (a.file_name.clone(), a.contents.clone())).collect()
}

const FEATURE: &str = "shaders/features/daslang/daslang_modules.das";

/// The feature program compiles alone (the daslang modules not found, the
/// names umbrac's builtins), and with the real daslang tree given by
/// `--daslang-root`, by `--daslib` and `--module glsl=DIR`, and by `-I`:
/// the lingua franca and `glsl_common` are then read, and change nothing.
#[test]
fn the_feature_program_is_the_same_with_a_daslang_tree_however_it_is_given() {
    let input = support::repo().join(FEATURE);
    let alone = compile(&input, &Options::default());
    let want = outputs(&alone);
    assert!(read_names(&alone).contains(&"grade.das".to_string()), "{:?}", read_names(&alone));
    let Some(tree) = daslang_tree() else { return };
    let daslib = Some(tree.join("daslib"));
    let ways = [
        Options { daslang_root: Some(tree.clone()), ..Default::default() },
        Options { daslib: daslib.clone(), modules: vec![("glsl".into(), tree.join("modules/dasGlsl/glsl"))], ..Default::default() },
        Options { daslib, include_dirs: vec![tree.join("modules/dasGlsl")], ..Default::default() },
    ];
    for opts in ways {
        let c = compile(&input, &opts);
        assert_eq!(outputs(&c), want, "{opts:?}");
        let read = read_names(&c);
        for f in ["shader_lingua_franca.das", "glsl_common.das", "grade.das"] {
            assert!(read.contains(&f.to_string()), "{f} not read with {opts:?}: {read:?}");
        }
    }
    // With the tree, `opengl/opengl_boost` (host code) is found and read too.
    let c = compile(&input, &Options { daslang_root: Some(tree), ..Default::default() });
    assert!(read_names(&c).contains(&"opengl_boost.das".to_string()));
}

/// Every module of the daslang tree a shader may require (the shader
/// modules of daslib, dasGlsl, dasOpenGL's glsl/, dasSpirv, and dasVulkan's
/// shader annotations) is found by its daslang name and required without
/// a false error: host code, `options`, generics, macros and their own
/// `require`s of host modules are never compiled.
#[test]
fn every_shader_module_of_the_daslang_tree_can_be_required() {
    let Some(tree) = daslang_tree() else { return };
    let mut names: Vec<String> = Vec::new();
    for (dir, prefix) in [("daslib", "daslib"), ("modules/dasGlsl/glsl", "glsl"), ("modules/dasOpenGL/glsl", "glsl"), ("modules/dasSpirv/spirv", "spirv")] {
        for e in std::fs::read_dir(tree.join(dir)).unwrap() {
            let p = e.unwrap().path();
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            if p.extension().is_some_and(|x| x == "das") && (prefix != "daslib" || stem.starts_with("shader_")) {
                names.push(format!("{prefix}/{stem}"));
            }
        }
    }
    names.push("vulkan/spirv_vulkan_shader".into());
    names.sort();
    assert!(names.len() >= 10, "{names:?}");
    let t = tempfile::tempdir().unwrap();
    let mut failures = Vec::new();
    for name in &names {
        let src = format!(
            "options gen2\nrequire {name} public\nvar @uniform tex : sampler2D\nvar @uniform u_m : float4x4\nvar @in @location = 0 a_pos : float3\nvar @inout v_uv : float2\nvar @out f_color : float4\n[vertex_program]\ndef vs {{\n    v_uv = a_pos.xy\n    gl_Position = u_m * float4(a_pos, 1.0)\n}}\n[fragment_program]\ndef fs {{\n    let c = texture(tex, v_uv) + float4(dFdx(v_uv.x), dFdy(v_uv.y), fwidth(v_uv.x), 0.0)\n    f_color = float4(fract(c.xyz * 2.0) + floor(c.xyz), length(c))\n}}\n"
        );
        let path = t.path().join("req.das");
        std::fs::write(&path, src).unwrap();
        let c = compile(&path, &Options { daslang_root: Some(tree.clone()), ..Default::default() });
        let file = format!("{}.das", name.rsplit('/').next().unwrap());
        if c.result.is_none() || !c.diagnostics.is_empty() {
            failures.push(format!("`require {name}`:\n{}", c.render_diagnostics()));
        } else if !read_names(&c).contains(&file) {
            failures.push(format!("`require {name}` did not read {file}: {:?}", read_names(&c)));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A name the real lingua franca declares that umbrac does not implement
/// is refused by name, at the call, pointing at daslang's declaration; a
/// name umbrac implements is umbrac's builtin.
#[test]
fn lingua_franca_names_umbrac_lacks_are_refused_by_name() {
    let Some(tree) = daslang_tree() else { return };
    let t = tempfile::tempdir().unwrap();
    let path = t.path().join("lf.das");
    for (call, refused) in [("float(sdot4(1u, 2u))", Some("sdot4")), ("float(pack32(unpack8(3u)))", Some("unpack8")), ("unpackHalf2x16(packHalf2x16(float2(0.5))).x", None)] {
        let src = format!("options gen2\nrequire spirv/spirv_builtins\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    f_color = float4({call})\n}}\n");
        std::fs::write(&path, src).unwrap();
        let c = compile(&path, &Options { daslang_root: Some(tree.clone()), ..Default::default() });
        let text = c.render_diagnostics();
        match refused {
            Some(name) => {
                let want = format!("`{name}` (a builtin of daslang's `shader_lingua_franca`) is not supported by umbrac on glsl330, gles300, glsl430, gles310, wgsl, spirv");
                assert!(text.contains(&want) && text.contains("shader_lingua_franca.das") && text.contains("daslang declares it here"), "{call}:\n{text}");
                assert!(!text.contains("unknown function"), "{text}");
            }
            None => assert!(c.result.is_some(), "{call}:\n{text}"),
        }
    }
}

/// A user module through a prefix a `.das_module` registers, one through
/// a folder named after its prefix, and the same through `--module`; with
/// neither, the unknown names show the modules that were not found.
#[test]
fn user_modules_through_registered_and_stated_prefixes() {
    let t = tempfile::tempdir().unwrap();
    let path = t.path().join("main.das");
    let src = "options gen2\nrequire reg/glow\nrequire pack.tint\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(tint(float3(glow(0.5))), 1.0)\n}\n";
    std::fs::write(&path, src).unwrap();
    let tree = own_tree();
    let by_root = compile(&path, &Options { daslang_root: Some(tree.clone()), ..Default::default() });
    let want = outputs(&by_root);
    // The `.das_module` that registered `reg/` counts as read (depfiles, reruns).
    assert!(by_root.files_read().iter().any(|p| p.ends_with("dasReg/.das_module")), "{:?}", by_root.files_read());
    let stated = Options { modules: vec![("reg".into(), tree.join("modules/dasReg/lib")), ("pack".into(), tree.join("modules/dasPack/pack"))], ..Default::default() };
    assert_eq!(outputs(&compile(&path, &stated)), want);
    // A `--module` comes before the tree's registration of the prefix.
    let shadowed = Options { daslang_root: Some(tree.clone()), modules: vec![("reg".into(), t.path().join("mine"))], ..Default::default() };
    std::fs::create_dir(t.path().join("mine")).unwrap();
    std::fs::write(t.path().join("mine/glow.das"), "def glow(x : float) : float {\n    return x + 100.0\n}\n").unwrap();
    let c = compile(&path, &shadowed);
    assert!(outputs(&c) != want && c.files_read().iter().any(|p| p.starts_with(t.path().join("mine"))), "{:?}", c.files_read());
    let c = compile(&path, &Options::default());
    let text = c.render_diagnostics();
    assert!(text.contains("unknown function `glow`") && text.contains("module `reg/glow` not found") && text.contains("--daslang-root"), "{text}");
}

/// `require ../x` is relative to the requiring file and followed out of
/// the input's directory, as daslang follows it; a name searched beside the
/// file (or in `-I`) may not climb out.
#[test]
fn relative_requires_follow_the_requiring_file() {
    let t = tempfile::tempdir().unwrap();
    let write = |rel: &str, text: &str| {
        let p = t.path().join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    };
    write("lib/m.das", "require ./n\ndef helper(x : float) : float {\n    return n_scale(x)\n}\n");
    write("lib/n.das", "def n_scale(x : float) : float {\n    return x * 2.0\n}\n");
    let body = "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(helper(0.5))\n}\n";
    for (i, req) in ["../lib/m.das", "../lib/m", "./../lib/m"].iter().enumerate() {
        write(&format!("app/{i}.das"), &format!("require {req}\n{body}"));
        let c = compile(&t.path().join(format!("app/{i}.das")), &Options::default());
        assert!(c.result.is_some(), "{req}:\n{}", c.render_diagnostics());
    }
    std::fs::create_dir_all(t.path().join("app/sub")).unwrap();
    write("app/climb.das", &format!("require sub/../../lib/m\n{body}"));
    let c = compile(&t.path().join("app/climb.das"), &Options::default());
    assert!(c.render_diagnostics().contains("reaches outside the input's directory"), "{}", c.render_diagnostics());
}

/// The command line: `--daslang-root`, `--module` (repeatable) and their
/// usage errors.
#[cfg(feature = "cli")]
#[test]
fn the_command_line_takes_a_daslang_root_and_module_prefixes() {
    let repo = support::repo();
    let t = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| support::umbrac(args, &repo);
    let tree = own_tree();
    let src = t.path().join("main.das");
    std::fs::write(&src, "require reg/glow\nrequire pack/tint\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(tint(float3(glow(0.5))), 1.0)\n}\n").unwrap();
    let (a, b) = (t.path().join("a"), t.path().join("b"));
    let root = tree.to_str().unwrap();
    let o = run(&["compile", src.to_str().unwrap(), "--target", "wgsl", "--daslang-root", root, "-o", a.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let reg = format!("reg={}", tree.join("modules/dasReg/lib").display());
    let pack = format!("pack={}", tree.join("modules/dasPack/pack").display());
    let o = run(&["compile", src.to_str().unwrap(), "--target", "wgsl", "--module", &reg, "--module", &pack, "-o", b.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read(a.join("main.wgsl")).unwrap(), std::fs::read(b.join("main.wgsl")).unwrap());
    for (args, want) in [
        (vec!["--module", "reg"], "`reg` is not PREFIX=DIR"),
        (vec!["--module", "=x"], "`=x` is not PREFIX=DIR"),
        (vec!["--daslang-root", "shaders/nowhere"], "is not a directory"),
        (vec!["--daslang-root", "shaders"], "holds neither `daslib/` nor `modules/`"),
    ] {
        let mut all = vec!["check", src.to_str().unwrap()];
        all.extend(args);
        let o = run(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains(want), "{all:?}: {err}");
    }
}

/// Only what shaders reach is compiled: a reached module's host code,
/// `options` lines, generics, macros and its `require`s of host-only
/// modules produce no error, nor does a module in daslang's older (gen1)
/// syntax that no shader reaches.
#[test]
fn host_code_in_required_modules_is_never_an_error() {
    let t = tempfile::tempdir().unwrap();
    let write = |rel: &str, text: &str| {
        let p = t.path().join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    };
    write(
        "lib/mixed.das",
        "options gen2\noptions no_aot = true\nmodule mixed public\nrequire fio\nrequire glfw/glfw_boost\nrequire imgui/imgui_boost\nrequire ./old_style\n\ndef half_of(x : float) : float {\n    return x * 0.5\n}\n\ndef generic_sum(a, b : auto(T)) : T {\n    return a + b\n}\n\n[macro_function]\ndef make_call(var expr : ExpressionPtr) : ExpressionPtr {\n    return <- expr\n}\n\n[export]\ndef main {\n    let files <- [for (x in range(3)); \"{x}.txt\"]\n    print(\"{files}\")\n}\n",
    );
    write("lib/old_style.das", "module old_style\n\ndef old_helper(x:float)\n    let y = x * 2.0\n    return y\n\nstruct Legacy\n    a : int\n");
    write("app/main.das", "options gen2\nrequire ../lib/mixed\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(half_of(0.5))\n}\n");
    let c = compile(&t.path().join("app/main.das"), &Options::default());
    assert!(c.result.is_some() && c.diagnostics.is_empty(), "{}", c.render_diagnostics());
    assert!(read_names(&c).contains(&"old_style.das".to_string()), "{:?}", read_names(&c));
}

/// An error inside a module found through a prefix points into that file
/// with the `require` chain.
#[test]
fn an_error_in_a_prefixed_module_shows_the_require_chain() {
    let t = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(t.path().join("pack")).unwrap();
    std::fs::write(t.path().join("pack/bad.das"), "def broken(x : float) : float {\n    return x + true\n}\n").unwrap();
    let main = t.path().join("main.das");
    std::fs::write(&main, "require p/bad\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(broken(1.0))\n}\n").unwrap();
    let c = compile(&main, &Options { modules: vec![("p".into(), t.path().join("pack"))], ..Default::default() });
    let text = c.render_diagnostics();
    assert!(c.result.is_none() && text.contains("bad.das:2:") && text.contains("required from") && text.contains("main.das:1:"), "{text}");
}

/// daslang's 12 GL tutorials compile to the same outputs with the daslang
/// tree given: their host modules (`opengl/opengl_boost`, `live/live_gc`,
/// `daslib/...`) are then found and read, and none of it is compiled.
#[test]
fn the_gl_tutorials_are_the_same_with_the_daslang_tree() {
    let Some(tree) = daslang_tree() else { return };
    let dir = support::repo().join("../shared/reference/daslang-tutorials");
    let mut tutorials: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "das")).collect();
    tutorials.sort();
    assert_eq!(tutorials.len(), 12, "{tutorials:?}");
    for t in &tutorials {
        let alone = compile(t, &Options::default());
        let with = compile(t, &Options { daslang_root: Some(tree.clone()), ..Default::default() });
        assert_eq!(outputs(&with), outputs(&alone), "{}", t.display());
        assert!(read_names(&with).contains(&"opengl_boost.das".to_string()), "{}: {:?}", t.display(), read_names(&with));
    }
}

/// A `.das_module` decides where a module is: it is in the depfile, and
/// editing it recompiles (the rerun record and the cache key see it).
#[cfg(feature = "cli")]
#[test]
fn an_edited_das_module_recompiles() {
    let t = tempfile::tempdir().unwrap();
    let write = |rel: &str, text: &str| {
        let p = t.path().join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    };
    let descriptor = |file: &str| format!("def initialize(project_path : string) {{\n    register_native_path(\"x\", \"tone\", \"{{project_path}}/{file}\")\n}}\n");
    write("tree/modules/dasX/.das_module", &descriptor("a.das"));
    write("tree/modules/dasX/a.das", "def tone(c : float4) : float4 {\n    return c * 0.5\n}\n");
    write("tree/modules/dasX/b.das", "def tone(c : float4) : float4 {\n    return c * 0.25\n}\n");
    write("m.das", "require x/tone\nvar @uniform u_tint : float4\nvar @out f_color : float4\n[fragment_program]\ndef m_fs {\n    f_color = tone(u_tint)\n}\n");
    let args = ["compile", "m.das", "--target", "wgsl", "--daslang-root", "tree", "-o", "out", "--cache", "cache", "--depfile", "m.d"];
    let run = || {
        let o = support::umbrac(&args, t.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(t.path().join("out/m.wgsl")).unwrap()
    };
    assert!(run().contains("0.5"));
    assert!(std::fs::read_to_string(t.path().join("m.d")).unwrap().contains(".das_module"));
    write("tree/modules/dasX/.das_module", &descriptor("b.das"));
    assert!(run().contains("0.25"), "the edited registration is followed");
}
