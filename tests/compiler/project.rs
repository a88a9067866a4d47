//! The project file (`umbrac.toml`) on the command line: found by walking
//! up from the first input, its settings used, flags winning key by key,
//! its errors located in it, `--no-project`.

use std::path::Path;

use crate::support;

/// A fragment shader that needs `TINT` defined, in `dir/sub/a.das`.
const SHADER: &str = "var @out f_color : float4\n\n[fragment_program]\ndef fs {\n    f_color = float4(TINT)\n}\n";

fn project(toml: &str) -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(d.path().join("sub/inc")).unwrap();
    std::fs::write(d.path().join("sub/a.das"), SHADER).unwrap();
    std::fs::write(d.path().join("umbrac.toml"), toml).unwrap();
    d
}

fn lines(out: &std::process::Output) -> Vec<String> {
    String::from_utf8_lossy(&out.stdout).lines().map(|l| Path::new(l).file_name().unwrap().to_string_lossy().into_owned()).collect()
}

#[test]
fn the_cli_reads_the_project_file_and_flags_win() {
    let d = project("targets = [\"wgsl\"]\ninclude-dirs = [\"sub/inc\"]\n[defines]\nTINT = \"0.5\"\n");
    let sub = d.path().join("sub");
    // Its defines and targets, found from `sub/` up.
    let out = support::umbrac(&["check", "a.das"], &sub);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let out = support::umbrac(&["outputs", "a.das"], &sub);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(lines(&out), ["a.reflect.json", "a.wgsl"]);
    // A flag's target replaces the file's; a flag's define replaces the same name's.
    let out = support::umbrac(&["outputs", "a.das", "--target", "glsl330"], &sub);
    assert_eq!(lines(&out), ["a.reflect.json", "fs.330.frag"]);
    let out = support::umbrac(&["check", "a.das", "-DTINT=nope"], &sub);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nope"), "{}", String::from_utf8_lossy(&out.stderr));
    // Without it, TINT is unknown.
    let out = support::umbrac(&["check", "a.das", "--no-project"], &sub);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("TINT"), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn a_bad_project_file_is_a_located_error_and_nothing_is_written() {
    let d = project("[defines]\nTINT = \"0.5\"\n\n[limits]\nvaryings = \"many\"\n");
    let sub = d.path().join("sub");
    let out = support::umbrac(&["compile", "a.das", "-o", "out"], &sub);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("umbrac.toml:5:12") && err.contains("expected a count") && err.contains('^'), "{err}");
    assert!(!sub.join("out").exists());
}
