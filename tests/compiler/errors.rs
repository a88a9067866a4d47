//! Bad input: one case per class of error. Each asserts the exact message,
//! file, line and column (through `--message-format json`), exit status 1,
//! and that the output directory is left without a single file.

use std::path::Path;
use std::process::Command;

struct Case {
    name: &'static str,
    /// Files to create: (relative path, contents). The first is compiled.
    files: &'static [(&'static str, &'static str)],
    /// Expected (file, line, column, message) of the first diagnostic.
    file: &'static str,
    line: usize,
    column: usize,
    message: &'static str,
}


const CASES: &[Case] = &[
    Case {
        name: "syntax error",
        files: &[("main.das", "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0, 2.0\n}\n")],
        file: "main.das",
        line: 5,
        column: 1,
        message: "expected ',' or ')', found '}'",
    },
    Case {
        name: "unknown name",
        files: &[("main.das", "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(colr)\n}\n")],
        file: "main.das",
        line: 4,
        column: 22,
        message: "unknown name `colr`",
    },
    Case {
        name: "unknown function with a suggestion",
        files: &[("main.das", "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(nrmalize(float3(1.0)), 1.0)\n}\n")],
        file: "main.das",
        line: 4,
        column: 22,
        message: "unknown function `nrmalize`",
    },
    Case {
        name: "type mismatch",
        files: &[("main.das", "var @out f_color : float4\n[fragment_program]\ndef fs {\n    let x : float = 2\n    f_color = float4(x)\n}\n")],
        file: "main.das",
        line: 4,
        column: 21,
        message: "type mismatch: `x` is declared `float` but initialised with `int`",
    },
    Case {
        name: "wrong argument count",
        files: &[(
            "main.das",
            "var @out f_color : float4\ndef tint(c : float3; k : float) : float3 {\n    return c * k\n}\n[fragment_program]\ndef fs {\n    f_color = float4(tint(float3(1.0)), 1.0)\n}\n",
        )],
        file: "main.das",
        line: 7,
        column: 22,
        message: "wrong number of arguments: `tint` takes 2 but 1 were given",
    },
    Case {
        name: "assignment to a let",
        files: &[("main.das", "var @out f_color : float4\n[fragment_program]\ndef fs {\n    let k = 1.0\n    k = 2.0\n    f_color = float4(k)\n}\n")],
        file: "main.das",
        line: 5,
        column: 5,
        message: "cannot assign to `k`: it is declared with `let`",
    },
    Case {
        name: "missing include",
        files: &[("main.das", "#include \"nope.das\"\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n")],
        file: "main.das",
        line: 1,
        column: 10,
        message: "cannot find include file `nope.das`",
    },
    Case {
        name: "include cycle",
        files: &[
            ("main.das", "#include \"b.das\"\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n"),
            ("b.das", "#include \"main.das\"\n"),
        ],
        file: "b.das",
        line: 1,
        column: 10,
        message: "include cycle",
    },
    Case {
        name: "unterminated #ifdef",
        files: &[("main.das", "#ifdef FOO\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n")],
        file: "main.das",
        line: 1,
        column: 1,
        message: "unterminated `#ifdef`",
    },
    Case {
        name: "duplicate location",
        files: &[(
            "main.das",
            "var @in @location = 0 a_pos : float3\nvar @in @location = 0 a_normal : float3\n[vertex_program]\ndef vs {\n    gl_Position = float4(a_pos + a_normal, 1.0)\n}\n",
        )],
        file: "main.das",
        line: 2,
        column: 9,
        message: "duplicate location 0 for `@in` variables",
    },
    Case {
        name: "textureCompare on a non-shadow sampler",
        files: &[(
            "main.das",
            "var @uniform tex : sampler2D\nvar @inout v_uv : float2\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(textureCompare(tex, v_uv, 0.5))\n}\n",
        )],
        file: "main.das",
        line: 6,
        column: 37,
        message: "`textureCompare` needs a shadow sampler, but `tex` is a `sampler2D`",
    },
    Case {
        name: "error inside an included file",
        files: &[
            ("main.das", "#include \"lib.das\"\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(half(1.0))\n}\n"),
            ("lib.das", "def half(x : float) : float {\n    return x * 0.5 + undefined_thing\n}\n"),
        ],
        file: "lib.das",
        line: 2,
        column: 22,
        message: "unknown name `undefined_thing`",
    },
];

#[test]
fn each_bad_input_class_is_located_and_writes_nothing() {
    let mut failures = Vec::new();
    for case in CASES {
        let dir = tempfile::tempdir().unwrap();
        for (name, text) in case.files {
            std::fs::write(dir.path().join(name), text).unwrap();
        }
        let out_dir = dir.path().join("out");
        std::fs::create_dir(&out_dir).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .arg("compile")
            .arg(dir.path().join(case.files[0].0))
            .arg("-o")
            .arg(&out_dir)
            .args(["--message-format", "json"])
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        let first: serde_json::Value = match stdout.lines().next().map(serde_json::from_str) {
            Some(Ok(v)) => v,
            _ => {
                failures.push(format!("{}: no JSON diagnostic; stdout: {stdout}", case.name));
                continue;
            }
        };
        let loc = &first["location"];
        let file = loc["file"].as_str().unwrap_or("");
        let got = (
            Path::new(file).file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default(),
            loc["line"].as_u64().unwrap_or(0) as usize,
            loc["column"].as_u64().unwrap_or(0) as usize,
        );
        let want = (case.file.to_string(), case.line, case.column);
        let message = first["message"].as_str().unwrap_or("");
        if got != want || !message.starts_with(case.message) {
            failures.push(format!("{}: got {got:?} {message:?}, want {want:?} {:?}", case.name, case.message));
        }
        if out.status.code() != Some(1) {
            failures.push(format!("{}: exit status {:?}, want 1", case.name, out.status.code()));
        }
        let written: Vec<_> = std::fs::read_dir(&out_dir).unwrap().collect();
        if !written.is_empty() {
            failures.push(format!("{}: {} files written to the output directory", case.name, written.len()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// An error in host code that no shader reaches is not reported.
#[test]
fn errors_in_skipped_host_code_are_not_reported() {
    let src = "options gen2\nrequire opengl/opengl_boost\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n[export]\ndef host {\n    let x = = broken ( syntax $ here\n}\n";
    let c = umbrac::compile_source("host.das", src, &umbrac::Options::default());
    assert!(c.result.is_some(), "{}", c.render_diagnostics());
    assert!(c.diagnostics.is_empty(), "{}", c.render_diagnostics());
}

/// Independent errors are all reported in one run.
#[test]
fn independent_errors_are_reported_together() {
    let src = "var @out f_color : float4\n[fragment_program]\ndef fs {\n    let a = unknown_one\n    let b : int = 1.0\n    f_color = float4(unknown_two)\n}\n";
    let c = umbrac::compile_source("multi.das", src, &umbrac::Options::default());
    let msgs: Vec<&str> = c.diagnostics.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(msgs.len(), 3, "{msgs:?}");
    assert!(msgs[0].contains("unknown_one") && msgs[1].contains("type mismatch") && msgs[2].contains("unknown_two"), "{msgs:?}");
}
