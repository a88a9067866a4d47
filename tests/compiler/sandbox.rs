//! umbrac inside a sandbox of symbolic links, as Bazel stages an action's
//! inputs: real directories holding one link per declared file, each
//! pointing into the source tree. The directory the user named is the
//! boundary for `#include` and `require`, not where the links point; a
//! file the sandbox does not hold (an undeclared dependency) is not found.
//! Depfiles name the files by normalised paths relative to the working
//! directory.

use std::path::Path;

use crate::support::umbrac;

/// The source tree: a program that includes through `..` and requires a
/// module found by `-I`.
const FILES: [(&str, &str); 4] = [
    ("shaders/main.das", "#include \"inc/lib/../palette.das\"\nrequire tone\nvar @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = tone(PALETTE)\n}\n"),
    ("shaders/inc/palette.das", "#include \"lib/scale.das\"\nlet PALETTE = float4(SCALE)\n"),
    ("shaders/inc/lib/scale.das", "let SCALE = 0.5\n"),
    ("modules/tone.das", "def tone(c : float4) : float4 {\n    return c * 0.5\n}\n"),
];

/// The source tree under `src`, and a sandbox under `sandbox` linking
/// every file but those in `leave_out`.
fn farm(root: &Path, leave_out: &[&str]) {
    for (rel, text) in FILES {
        let real = root.join("src").join(rel);
        std::fs::create_dir_all(real.parent().unwrap()).unwrap();
        std::fs::write(&real, text).unwrap();
        let link = root.join("sandbox").join(rel);
        std::fs::create_dir_all(link.parent().unwrap()).unwrap();
        if !leave_out.contains(&rel) {
            std::os::unix::fs::symlink(&real, &link).unwrap();
        }
    }
}

const ARGS: [&str; 11] = ["compile", "shaders/main.das", "-I", "modules", "-o", "out", "--target", "wgsl", "--no-cache", "--depfile", "out/main.d"];

#[test]
fn includes_and_requires_are_allowed_by_the_path_given() {
    let t = tempfile::tempdir().unwrap();
    farm(t.path(), &[]);
    let sandbox = t.path().join("sandbox");
    let o = umbrac(&ARGS, &sandbox);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let d = std::fs::read_to_string(sandbox.join("out/main.d")).unwrap();
    let expect = "out/main.reflect.json \\\nout/main.wgsl: \\\n  modules/tone.das \\\n  shaders/inc/lib/scale.das \\\n  shaders/inc/palette.das \\\n  shaders/main.das\n\n\
                  modules/tone.das:\n\nshaders/inc/lib/scale.das:\n\nshaders/inc/palette.das:\n\nshaders/main.das:\n";
    assert_eq!(d, expect, "normalised, relative to the working directory");
    // The same from outside the sandbox by absolute paths: absolute, but
    // still without `..`.
    let main = sandbox.join("shaders/main.das");
    let (m, modules, out) = (main.to_str().unwrap(), sandbox.join("modules"), sandbox.join("abs"));
    let o = umbrac(&["compile", m, "-I", modules.to_str().unwrap(), "-o", out.to_str().unwrap(), "--target", "wgsl", "--no-cache", "--depfile", "abs.d"], t.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let d = std::fs::read_to_string(t.path().join("abs.d")).unwrap();
    assert!(d.contains(&format!("  {}/shaders/inc/palette.das", sandbox.display())) && !d.contains(".."), "{d}");
}

#[test]
fn an_undeclared_include_or_module_is_not_found_in_the_sandbox() {
    for (missing, message) in [("shaders/inc/lib/scale.das", "cannot find include file `lib/scale.das`"), ("modules/tone.das", "tone")] {
        let t = tempfile::tempdir().unwrap();
        farm(t.path(), &[missing]);
        let o = umbrac(&ARGS, &t.path().join("sandbox"));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{missing} left out, yet: {err}");
        assert!(err.contains(message) && !err.contains("reaches outside"), "{missing}: {err}");
        assert!(!t.path().join("sandbox/out").exists(), "nothing written");
    }
}

/// A `..` that leaves the named directory is refused in the sandbox as
/// outside it.
#[test]
fn a_dotdot_out_of_the_sandbox_directory_is_still_refused() {
    let t = tempfile::tempdir().unwrap();
    farm(t.path(), &[]);
    let sandbox = t.path().join("sandbox");
    std::fs::write(sandbox.join("secret.das"), "let SCALE = 9.0\n").unwrap();
    std::fs::write(sandbox.join("shaders/escape.das"), "#include \"../secret.das\"\nvar @out f_color : float4\n[fragment_program]\ndef e_fs {\n    f_color = float4(SCALE)\n}\n").unwrap();
    let o = umbrac(&["compile", "shaders/escape.das", "-o", "out", "--target", "wgsl", "--no-cache"], &sandbox);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("reaches outside the input's directory"), "{err}");
}

/// `umbrac outputs` (what a Bazel rule declares) lists exactly the files
/// `umbrac compile` with the same arguments writes, and writes nothing.
#[test]
fn outputs_lists_exactly_what_compile_writes() {
    let repo = crate::support::repo();
    let shaders = repo.join("shaders");
    let variants = ["--variants", &*shaders.join("programs/shadow_variants.toml").to_string_lossy()].map(String::from);
    let runs: [(&str, Vec<String>); 3] = [
        ("shadow.das", vec![]),
        ("features/preprocessor.das", ["--target", "wgsl", "--target", "glsl330", "--target", "spirv"].map(String::from).to_vec()),
        ("programs/shadow_variants.das", variants.to_vec()),
    ];
    for (i, (input, extra)) in runs.iter().enumerate() {
        let t = tempfile::tempdir().unwrap();
        let input = shaders.join(input);
        let out = format!("out{i}/sub");
        let mut args: Vec<&str> = vec![input.to_str().unwrap(), "-o", &out, "--no-cache"];
        args.extend(extra.iter().map(String::as_str));
        let listed = umbrac(&[&["outputs"], &args[..]].concat(), t.path());
        assert!(listed.status.success(), "{}", String::from_utf8_lossy(&listed.stderr));
        assert!(!t.path().join(format!("out{i}")).exists(), "`outputs` writes nothing");
        let o = umbrac(&[&["compile"], &args[..]].concat(), t.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let mut written = Vec::new();
        walk(t.path(), &t.path().join(&out), &mut written);
        written.sort();
        let listed: Vec<String> = String::from_utf8(listed.stdout).unwrap().lines().map(String::from).collect();
        assert!(listed.len() > 3, "{listed:?}");
        assert_eq!(listed, written, "{}", input.display());
    }
}

fn walk(base: &Path, dir: &Path, out: &mut Vec<String>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        if e.file_type().unwrap().is_dir() {
            walk(base, &e.path(), out);
        } else {
            out.push(e.path().strip_prefix(base).unwrap().to_string_lossy().into_owned());
        }
    }
}
