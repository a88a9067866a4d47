//! Tests of the `umbrac` binary: exit codes, `-o -`, JSON diagnostics and
//! atomic outputs.
//!
//! Tests of successful compiles use the project's own programs.

use crate::support::{self, repo, umbrac};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Output;

fn code(o: &Output) -> i32 {
    o.status.code().expect("exited normally (no signal, no panic abort)")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Every file under `dir` with its bytes.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut m = BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            m.insert(p.clone(), b"<dir>".to_vec());
            m.extend(snapshot(&p));
        } else {
            m.insert(p.clone(), std::fs::read(&p).unwrap());
        }
    }
    m
}

const BAD: &str = "[vertex_program]\ndef vs {\n    gl_Position = float4(1.0, 2.0\n}\n";

#[test]
fn usage_errors_exit_2() {
    let d = tempfile::tempdir().unwrap();
    for args in [
        &["compile"][..],
        &["compile", "a.das", "--target", "hlsl"],
        &["compile", "a.das", "--conventions", "sideways"],
        &["compile", "a.das", "-D", "1abc"],
        &["compile", "a.das", "b.das", "-o", "-"],
        &["compile", "a.das", "--target", "spirv", "-o", "-"],
        &["compile", "a.das", "-o", "-"],
        &["frobnicate"],
        &["reflect"],
        &["outputs"],
        &["outputs", "a.das", "-o", "-"],
        &["outputs", "a.das", "--depfile", "a.d"],
        &["outputs", "a.das", "--watch"],
    ] {
        let o = umbrac(args, d.path());
        assert_eq!(code(&o), 2, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("error"), "{args:?}: {}", stderr(&o));
    }
    assert!(snapshot(d.path()).is_empty(), "usage errors write nothing");
}

#[test]
fn help_and_version_exit_0() {
    let d = tempfile::tempdir().unwrap();
    for args in [&["--help"][..], &["--version"], &["compile", "--help"]] {
        assert_eq!(code(&umbrac(args, d.path())), 0, "{args:?}");
    }
    let help = stdout(&umbrac(&["compile", "--help"], d.path()));
    for flag in ["--target", "-o", "-D", "-I", "--entry", "--conventions", "--allow-outside-includes", "--message-format"] {
        assert!(help.contains(flag), "{flag} missing from help:\n{help}");
    }
}

#[test]
fn missing_input_is_a_compile_error() {
    let d = tempfile::tempdir().unwrap();
    let o = umbrac(&["compile", "nope.das", "-o", "out"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(stderr(&o).contains("nope.das"), "{}", stderr(&o));
    assert!(!d.path().join("out").exists(), "no output directory for a failed compile");
    let o = umbrac(&["reflect", "nope.das"], d.path());
    assert_eq!(code(&o), 1);
    assert!(o.stdout.is_empty());
    let o = umbrac(&["check", "nope.das"], d.path());
    assert_eq!(code(&o), 1);
}

#[test]
fn json_diagnostics_shape() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("bad.das"), BAD).unwrap();
    let o = umbrac(&["check", "nope.das", "bad.das", "--message-format", "json"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    let lines: Vec<&str> = std::str::from_utf8(&o.stdout).unwrap().lines().collect();
    assert!(lines.len() >= 2, "one JSON object per diagnostic per line: {lines:?}");
    for line in lines {
        let v: serde_json::Value = serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"));
        let obj = v.as_object().unwrap();
        for key in ["severity", "message", "location", "label", "related", "notes", "include_chain", "rendered"] {
            assert!(obj.contains_key(key), "{key} missing: {line}");
        }
        assert!(["error", "warning", "bug"].contains(&obj["severity"].as_str().unwrap()), "{line}");
        assert!(obj["rendered"].as_str().unwrap().contains(obj["message"].as_str().unwrap()));
        if let Some(loc) = obj["location"].as_object() {
            for key in ["file", "line", "column", "end_line", "end_column", "byte_start", "byte_end"] {
                assert!(loc.contains_key(key), "{key} missing: {line}");
            }
        }
    }
    // Human output goes to stderr instead, and stdout stays empty.
    let o = umbrac(&["check", "nope.das"], d.path());
    assert!(o.stdout.is_empty());
    assert!(stderr(&o).contains("error"), "{}", stderr(&o));
}

/// A failing compile leaves existing outputs byte-identical and creates no
/// files.
#[test]
fn failed_compile_changes_nothing() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    std::fs::create_dir(&out).unwrap();
    for (name, text) in [("bad.wgsl", "old wgsl"), ("bad.reflect.json", "{}\n"), ("vs.330.vert", "old glsl")] {
        std::fs::write(out.join(name), text).unwrap();
    }
    std::fs::write(d.path().join("bad.das"), BAD).unwrap();
    let before = snapshot(d.path());
    let o = umbrac(&["compile", "bad.das", "-o", "out"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert_eq!(snapshot(d.path()), before);
}

/// A write that fails part-way (a directory where an output file must go)
/// leaves every previous output as it was and no temporary files behind.
/// Uses real emitter outputs through the library.
#[test]
fn write_failure_keeps_old_outputs() {
    let lowered = support::fake_lowered(
        r#"
@group(0) @binding(0) var<uniform> u_model: mat4x4<f32>;
@vertex fn vs(@location(0) p: vec4<f32>) -> @builtin(position) vec4<f32> { return u_model * p; }
@fragment fn fs() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
"#,
    );
    let (arts, _) = umbrac::emit::emit(&lowered, "s", "s.das", &[]).unwrap();
    let d = tempfile::tempdir().unwrap();
    for a in &arts {
        std::fs::write(d.path().join(&a.file_name), format!("old {}", a.file_name)).unwrap();
    }
    // The SPIR-V output's path is taken by a directory.
    std::fs::remove_file(d.path().join("s.spv")).unwrap();
    std::fs::create_dir(d.path().join("s.spv")).unwrap();
    let before = snapshot(d.path());
    let e = umbrac::output::write_artifacts(d.path(), &arts).unwrap_err();
    assert!(e.to_string().contains("s.spv"), "{e}");
    assert_eq!(snapshot(d.path()), before);

    // With the obstacle gone the same write succeeds and replaces everything.
    std::fs::remove_dir(d.path().join("s.spv")).unwrap();
    umbrac::output::write_artifacts(d.path(), &arts).unwrap();
    for a in &arts {
        assert_eq!(std::fs::read(d.path().join(&a.file_name)).unwrap(), a.contents, "{}", a.file_name);
    }
    assert_eq!(snapshot(d.path()).len(), arts.len(), "no temporaries left");
}

#[test]
fn unwritable_output_directory_is_a_clear_error() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("file"), "").unwrap();
    let lowered = support::fake_lowered("@fragment fn fs() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }");
    let (arts, _) = umbrac::emit::emit(&lowered, "s", "s.das", &[]).unwrap();
    let e = umbrac::output::write_artifacts(&d.path().join("file"), &arts).unwrap_err();
    assert!(e.to_string().contains("not a directory"), "{e}");
    let e = umbrac::output::write_artifacts(&d.path().join("file/sub"), &arts).unwrap_err();
    assert!(e.to_string().contains("cannot create the output directory"), "{e}");
}

// ---- needs a working front end ----

fn shadow_das() -> PathBuf {
    repo().join("shaders/shadow.das")
}

#[test]
fn compile_writes_every_output() {
    let d = tempfile::tempdir().unwrap();
    let o = umbrac(&["compile", shadow_das().to_str().unwrap(), "-o", "out"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let out = d.path().join("out");
    for ep in ["shadow_vs", "main_vs"] {
        assert!(out.join(format!("{ep}.330.vert")).exists());
        assert!(out.join(format!("{ep}.300es.vert")).exists());
    }
    for ep in ["shadow_fs", "main_fs"] {
        assert!(out.join(format!("{ep}.330.frag")).exists());
        assert!(out.join(format!("{ep}.300es.frag")).exists());
    }
    for f in ["shadow.wgsl", "shadow.spv", "shadow.reflect.json"] {
        assert!(out.join(f).exists(), "{f}");
    }
    let refl: umbrac::Reflection = serde_json::from_slice(&std::fs::read(out.join("shadow.reflect.json")).unwrap()).unwrap();
    support::validate_dir(&out, &refl);
}

#[test]
fn default_output_directory_is_the_current_one() {
    let d = tempfile::tempdir().unwrap();
    let o = umbrac(&["compile", shadow_das().to_str().unwrap(), "--target", "wgsl"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let mut names: Vec<_> = snapshot(d.path()).into_keys().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["shadow.reflect.json", "shadow.wgsl"]);
}

#[test]
fn stdout_output() {
    let d = tempfile::tempdir().unwrap();
    let das = shadow_das();
    let das = das.to_str().unwrap();
    let o = umbrac(&["compile", das, "--target", "wgsl", "-o", "-"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).contains("@vertex"), "{}", stdout(&o));
    let o = umbrac(&["compile", das, "--target", "gles300", "--entry", "main_fs", "-o", "-"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).starts_with("#version 300 es\n"));
    // Four GLSL files cannot go to one stdout.
    let o = umbrac(&["compile", das, "--target", "glsl330", "-o", "-"], d.path());
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert!(snapshot(d.path()).is_empty(), "-o - writes no files");
}

#[test]
fn check_and_reflect_write_nothing() {
    let d = tempfile::tempdir().unwrap();
    let das = shadow_das();
    let o = umbrac(&["check", das.to_str().unwrap()], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = umbrac(&["reflect", das.to_str().unwrap()], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let refl: umbrac::Reflection = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(refl.entry_points.len(), 4);
    assert!(snapshot(d.path()).is_empty());
}

#[test]
fn cli_write_failure_keeps_old_outputs() {
    let d = tempfile::tempdir().unwrap();
    let das = shadow_das();
    let o = umbrac(&["compile", das.to_str().unwrap(), "-o", "out"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let out = d.path().join("out");
    std::fs::remove_file(out.join("shadow.spv")).unwrap();
    std::fs::create_dir(out.join("shadow.spv")).unwrap();
    std::fs::write(out.join("main_fs.330.frag"), "previous").unwrap();
    let before = snapshot(d.path());
    let o = umbrac(&["compile", das.to_str().unwrap(), "-o", "out"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(stderr(&o).contains("shadow.spv"), "{}", stderr(&o));
    assert_eq!(snapshot(d.path()), before);
}

#[test]
fn parallel_files_failed_one_writes_nothing() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("bad.das"), BAD).unwrap();
    let das = shadow_das();
    let o = umbrac(&["compile", das.to_str().unwrap(), "bad.das", "-o", "out", "--target", "wgsl"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    // All or nothing: the good file's outputs are not written either.
    let out = d.path().join("out");
    assert!(!out.join("shadow.wgsl").exists());
    assert!(!out.join("bad.wgsl").exists() && !out.join("bad.reflect.json").exists());
}

#[test]
fn syntax_error_json_has_a_location() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("bad.das"), BAD).unwrap();
    let o = umbrac(&["check", "bad.das", "--message-format", "json"], d.path());
    assert_eq!(code(&o), 1);
    let first: serde_json::Value = serde_json::from_str(stdout(&o).lines().next().unwrap()).unwrap();
    assert_eq!(first["severity"], "error");
    assert_eq!(first["location"]["file"], "bad.das");
    assert_eq!(first["location"]["line"], 4, "reported at the token that ends the unclosed call");
}

#[test]
fn reference_tutorial_compiles_and_validates() {
    let reference = repo().join("../shared/reference/08_shadow.das");
    if !reference.exists() {
        eprintln!("skipping: {} not found", reference.display());
        return;
    }
    let d = tempfile::tempdir().unwrap();
    let o = umbrac(&["compile", reference.to_str().unwrap(), "-o", "out"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let out = d.path().join("out");
    let refl: umbrac::Reflection = serde_json::from_slice(&std::fs::read(out.join("08_shadow.reflect.json")).unwrap()).unwrap();
    let mut names: Vec<_> = refl.entry_points.iter().map(|e| e.name.as_str()).collect();
    names.sort();
    assert_eq!(names, ["main_fs", "main_vs", "shadow_fs", "shadow_vs"]);
    support::validate_dir(&out, &refl);
}

/// `umbrac compile DIR`: every `.das` under it (not `include/`), compiled in
/// parallel, outputs mirrored into the same subdirectories of `-o`; the
/// golden outputs are exactly what lands there.
#[test]
fn compile_a_directory() {
    // A tree of the project's programs (entry point names are unique per
    // output directory; see the clash below).
    fn copy_tree(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).unwrap();
        for e in std::fs::read_dir(from).unwrap() {
            let p = e.unwrap().path();
            let dest = to.join(p.file_name().unwrap());
            if p.is_dir() {
                copy_tree(&p, &dest);
            } else {
                std::fs::copy(&p, &dest).unwrap();
            }
        }
    }
    let src = tempfile::tempdir().unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), src.path().join("shadow.das")).unwrap();
    copy_tree(&repo().join("shaders/features"), &src.path().join("features"));
    copy_tree(&repo().join("shaders/programs"), &src.path().join("programs"));
    let tmp = tempfile::tempdir().unwrap();
    let o = umbrac(&["compile", src.path().to_str().unwrap(), "-o", tmp.path().to_str().unwrap()], tmp.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    for (sub, stem) in [("", "shadow"), ("features", "points"), ("programs", "bloom")] {
        let golden = repo().join("tests/golden").join(stem);
        for e in std::fs::read_dir(&golden).unwrap() {
            let g = e.unwrap().path();
            let out = tmp.path().join(sub).join(g.file_name().unwrap());
            assert!(out.exists(), "{} was not written", out.display());
            // The manifest records the source path as given; the rest is byte-identical.
            if g.extension().is_some_and(|x| x != "json") {
                assert!(std::fs::read(&out).unwrap() == std::fs::read(&g).unwrap(), "{} differs from {}", out.display(), g.display());
            }
        }
    }
    assert!(!tmp.path().join("features/include").exists(), "include/ is compiled");
    assert!(!tmp.path().join("features/lighting.reflect.json").exists(), "include/lighting.das is compiled");
    // `check` takes directories too; an empty one is a usage error.
    let o = umbrac(&["check", repo().join("shaders/programs").to_str().unwrap()], tmp.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let empty = tmp.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    let o = umbrac(&["compile", empty.to_str().unwrap()], tmp.path());
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    assert!(stderr(&o).contains("no `.das` files"), "{}", stderr(&o));
    // Two files with the same entry point names cannot share an output
    // directory: the clash is named and nothing of either is written.
    let twins = tmp.path().join("twins");
    std::fs::create_dir(&twins).unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), twins.join("a.das")).unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), twins.join("b.das")).unwrap();
    let clash = tmp.path().join("clash");
    let o = umbrac(&["compile", twins.to_str().unwrap(), "-o", clash.to_str().unwrap()], tmp.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(stderr(&o).contains("is an output of both"), "{}", stderr(&o));
    // Located in both inputs, at the entry point that names the file.
    let e = stderr(&o);
    let at = |f: &str| regex_free_location(&e, f);
    assert!(at("b.das").is_some() && at("a.das").is_some() && e.contains('^'), "{e}");
    assert!(!clash.exists() || std::fs::read_dir(&clash).unwrap().next().is_none(), "nothing is written");
}

/// Several inputs where one fails: exit 1 and nothing is written, the good
/// inputs' outputs included (a run is all or nothing, as the README says;
/// issue 37 found the good files' outputs written).
#[test]
fn one_failing_input_writes_nothing_for_the_others() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path().join("many");
    std::fs::create_dir(&dir).unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), dir.join("good.das")).unwrap();
    std::fs::write(dir.join("bad.das"), "options gen2\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = nope\n}\n").unwrap();
    for args in [vec!["compile", "many", "-o", "out"], vec!["compile", "many/good.das", "many/bad.das", "-o", "out"]] {
        let o = umbrac(&args, d.path());
        assert_eq!(code(&o), 1, "{}", stderr(&o));
        assert!(stderr(&o).contains("bad.das:5:"), "{}", stderr(&o));
        assert!(!d.path().join("out").exists() || std::fs::read_dir(d.path().join("out")).unwrap().next().is_none(), "{args:?} wrote outputs");
    }
    // The good input alone compiles.
    let o = umbrac(&["compile", "many/good.das", "-o", "out"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(d.path().join("out/main_fs.330.frag").exists());
}

/// A program over a guarantee that every device in use exceeds compiles
/// with a located warning (on stderr, or a JSON line on stdout) and exit
/// status 0, every time (a cache never hides it); with `--strict-limits`
/// it is an error, exit 1, nothing written.
#[test]
fn a_device_limit_warning_is_shown_and_fails_only_when_strict() {
    let d = tempfile::tempdir().unwrap();
    std::fs::copy(repo().join("tests/support/skinning_palette.das"), d.path().join("skin.das")).unwrap();
    let message = "vertex entry point `skin_vs` uses 268 uniform vectors in GLSL 330, over the 256 that GL 3.3 core guarantees";
    for _ in 0..2 {
        let o = umbrac(&["compile", "skin.das", "--target", "glsl330", "-o", "out"], d.path());
        assert_eq!(code(&o), 0, "{}", stderr(&o));
        assert!(stderr(&o).contains(&format!("warning: {message}")) && stderr(&o).contains("skin.das:9:14"), "{}", stderr(&o));
    }
    assert!(d.path().join("out/skin_vs.330.vert").exists());
    let o = umbrac(&["compile", "skin.das", "--target", "glsl330", "-o", "json", "--message-format", "json"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 1, "{}", stdout(&o));
    assert_eq!(lines[0]["severity"], "warning");
    assert!(lines[0]["message"].as_str().unwrap().starts_with(message), "{}", lines[0]);
    assert_eq!((lines[0]["location"]["line"].as_u64(), lines[0]["location"]["column"].as_u64()), (Some(9), Some(14)));
    assert!(d.path().join("json/skin_vs.330.vert").exists());
    let o = umbrac(&["compile", "skin.das", "--target", "glsl330", "--strict-limits", "-o", "strict"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(stderr(&o).contains(&format!("error: {message}")), "{}", stderr(&o));
    assert!(!d.path().join("strict").exists() || snapshot(&d.path().join("strict")).is_empty(), "a refused compile writes nothing");
}

/// An input, or a file it includes, named like one of its own outputs in
/// the output directory is never replaced by that output: the run is
/// refused whole, exit 1, naming both, and nothing is written (issue 37:
/// `umbrac compile self/x.wgsl -o self` replaced its source).
#[test]
fn an_output_never_replaces_a_file_the_compile_reads() {
    let d = tempfile::tempdir().unwrap();
    let source = std::fs::read(repo().join("shaders/shadow.das")).unwrap();
    let own = d.path().join("self");
    std::fs::create_dir(&own).unwrap();
    std::fs::write(own.join("shadow.wgsl"), &source).unwrap();
    for out in ["self", "./self/../self"] {
        let o = umbrac(&["compile", "self/shadow.wgsl", "-o", out], d.path());
        assert_eq!(code(&o), 1, "{}", stderr(&o));
        assert!(stderr(&o).contains("would replace `self/shadow.wgsl`, which this compile reads; nothing was written"), "{}", stderr(&o));
        assert_eq!(std::fs::read(own.join("shadow.wgsl")).unwrap(), source, "the source is intact");
        let names: Vec<_> = std::fs::read_dir(&own).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1, "nothing else written: {names:?}");
    }
    // An included file named like an output of the program that includes it.
    let inc = d.path().join("inc");
    std::fs::create_dir(&inc).unwrap();
    let body = "options gen2\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n";
    std::fs::write(inc.join("fs.330.frag"), body).unwrap();
    std::fs::write(inc.join("main.das"), "#include \"fs.330.frag\"\n").unwrap();
    let o = umbrac(&["compile", "inc/main.das", "-o", "inc"], d.path());
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(stderr(&o).contains("fs.330.frag"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(inc.join("fs.330.frag")).unwrap(), body);
    // Elsewhere the same inputs compile.
    let o = umbrac(&["compile", "inc/main.das", "-o", "out"], d.path());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(d.path().join("out/fs.330.frag").exists());
}

/// The `LINE:COL` after `FILE:` in a rendered diagnostic, if any.
fn regex_free_location(text: &str, file: &str) -> Option<(usize, usize)> {
    let i = text.find(&format!("{file}:"))? + file.len() + 1;
    let mut parts = text[i..].splitn(3, ':');
    let line = parts.next()?.parse().ok()?;
    let col = parts.next()?.split(|c: char| !c.is_ascii_digit()).next()?.parse().ok()?;
    Some((line, col))
}
