//! The bad-input corpus: `tests/bad_inputs/*.das`, one case per file, for
//! every diagnostic the compiler has (preprocessor, lexer, item selection,
//! parser, checker, CLI usage). Each file starts with its expectations:
//!
//! ```text
//! // expect: LINE:COL: MESSAGE     the first diagnostic (an error, on stdout's
//!                                  first line): location and message prefix
//!                                  (`-:-` for errors with no location)
//! // expect-file: NAME             the file holding that location (default: the case)
//! // args: ARG...                  extra command-line arguments
//! // input: none                   do not pass the case file itself
//! // exit: N                       expected exit status (default 1)
//! ```
//!
//! Each case runs `umbrac compile CASE -o OUT --message-format json ARGS`
//! in `tests/bad_inputs/`, and must leave `OUT` without a single file.
//! `include/` holds files the cases include. With `UMBRAC_BLESS=1`, a `?:?`
//! location is filled in from the compiler's answer (review the diff).

use std::path::{Path, PathBuf};
use std::process::Command;

struct Case {
    path: PathBuf,
    line: Option<usize>,
    column: Option<usize>,
    message: String,
    file: Option<String>,
    args: Vec<String>,
    input: bool,
    exit: i32,
}

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_inputs")
}

fn parse_case(path: &Path) -> Result<Case, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(&bytes);
    let mut case = Case { path: path.to_path_buf(), line: None, column: None, message: String::new(), file: None, args: vec![], input: true, exit: 1 };
    let mut have_expect = false;
    for l in text.lines().take_while(|l| l.starts_with("// ")) {
        let l = &l[3..];
        if let Some(rest) = l.strip_prefix("expect: ") {
            let mut parts = rest.splitn(3, ':');
            let (line, col, msg) = (parts.next(), parts.next(), parts.next());
            let (Some(line), Some(col), Some(msg)) = (line, col, msg) else { return Err(format!("bad expect line: {l}")) };
            if (line, col) != ("-", "-") && !std::env::var("UMBRAC_BLESS").is_ok_and(|v| v == "1") {
                case.line = Some(line.parse().map_err(|_| format!("bad location in: {l}"))?);
                case.column = Some(col.parse().map_err(|_| format!("bad location in: {l}"))?);
            } else {
                case.line = line.parse().ok();
                case.column = col.parse().ok();
            }
            case.message = msg.trim_start().to_string();
            have_expect = true;
        } else if let Some(f) = l.strip_prefix("expect-file: ") {
            case.file = Some(f.trim().to_string());
        } else if let Some(a) = l.strip_prefix("args: ") {
            case.args = a.split_whitespace().map(String::from).collect();
        } else if l.trim() == "input: none" {
            case.input = false;
        } else if let Some(e) = l.strip_prefix("exit: ") {
            case.exit = e.trim().parse().map_err(|_| format!("bad exit line: {l}"))?;
        }
    }
    if !have_expect {
        return Err("no `// expect:` line".into());
    }
    Ok(case)
}

fn cases() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "das"))
        .collect();
    v.sort();
    v
}

/// Runs one case; `Err` describes the mismatch. Returns the actual
/// `line:col` for blessing.
fn run(case: &Case) -> Result<(), (String, Option<String>)> {
    let tmp = tempfile::tempdir().unwrap();
    let out_dir = tmp.path().join("out");
    std::fs::create_dir(&out_dir).unwrap();
    let name = case.path.file_name().unwrap().to_string_lossy().into_owned();
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_umbrac"));
    cmd.arg("compile").current_dir(dir());
    if case.input {
        cmd.arg(&name);
    }
    cmd.args(&case.args);
    if !case.args.iter().any(|a| a == "-o") {
        cmd.arg("-o").arg(&out_dir);
    }
    cmd.args(["--message-format", "json"]);
    let out = cmd.output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let fail = |m: String| Err((m, None));

    if out.status.code() != Some(case.exit) {
        return fail(format!("exit status {:?}, want {}\nstdout: {stdout}\nstderr: {stderr}", out.status.code(), case.exit));
    }
    let written = std::fs::read_dir(&out_dir).unwrap().count();
    if written != 0 {
        return fail(format!("{written} files written to the output directory"));
    }
    if case.exit == 2 {
        // Usage errors: a plain message on stderr, nothing on stdout.
        if !stdout.is_empty() {
            return fail(format!("usage error printed to stdout: {stdout}"));
        }
        if !stderr.contains(&case.message) {
            return fail(format!("stderr lacks {:?}: {stderr}", case.message));
        }
        return Ok(());
    }
    // The expected error is the first thing reported: stdout's first line.
    let first = stdout.lines().next().and_then(|l| serde_json::from_str::<serde_json::Value>(l).ok());
    let Some(first) = first else { return fail(format!("stdout does not start with a JSON diagnostic; stdout: {stdout}\nstderr: {stderr}")) };
    if first["severity"] != "error" {
        return fail(format!("first diagnostic has severity {}, want error", first["severity"]));
    }
    let message = first["message"].as_str().unwrap_or("");
    let loc = &first["location"];
    let actual = if loc.is_null() {
        "-:-".to_string()
    } else {
        format!("{}:{}", loc["line"].as_u64().unwrap_or(0), loc["column"].as_u64().unwrap_or(0))
    };
    let want = match (case.line, case.column) {
        (Some(l), Some(c)) => format!("{l}:{c}"),
        _ => "-:-".to_string(),
    };
    let file = loc["file"].as_str().map(|f| Path::new(f).file_name().unwrap().to_string_lossy().into_owned());
    let want_file = case.file.clone().unwrap_or(name);
    let mut problems = Vec::new();
    if !message.starts_with(&case.message) {
        problems.push(format!("message {message:?} does not start with {:?}", case.message));
    }
    if !loc.is_null() && file.as_deref() != Some(want_file.as_str()) {
        problems.push(format!("file {file:?}, want {want_file}"));
    }
    if actual != want {
        problems.push(format!("location {actual}, want {want}"));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        let bless = message.starts_with(&case.message).then_some(actual);
        Err((problems.join("; "), bless))
    }
}

#[test]
fn every_bad_input_reports_its_error_and_writes_nothing() {
    let paths = cases();
    assert!(paths.len() >= 60, "only {} cases", paths.len());
    let bless = std::env::var("UMBRAC_BLESS").is_ok_and(|v| v == "1");
    let mut failures = Vec::new();
    for p in &paths {
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        let case = match parse_case(p) {
            Ok(c) => c,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        if let Err((why, actual)) = run(&case) {
            match (bless, actual, case.line) {
                (true, Some(actual), None) => {
                    let bytes = std::fs::read(p).unwrap();
                    let text = String::from_utf8_lossy(&bytes).replacen("// expect: ?:?:", &format!("// expect: {actual}:"), 1);
                    std::fs::write(p, text.as_bytes()).unwrap();
                }
                _ => failures.push(format!("{name}: {why}")),
            }
        }
    }
    assert!(failures.is_empty(), "{} of {} cases failed:\n{}", failures.len(), paths.len(), failures.join("\n"));
}

/// The corpus stays broad: at least 120 distinct messages (compared on
/// their first three words).
#[test]
fn corpus_lists_enough_distinct_messages() {
    let mut seen = std::collections::BTreeSet::new();
    for p in cases() {
        if let Ok(c) = parse_case(&p) {
            seen.insert(c.message.split_whitespace().take(3).collect::<Vec<_>>().join(" "));
        }
    }
    assert!(seen.len() >= 120, "only {} distinct messages", seen.len());
}

// Bad-input checks that cannot be corpus files: the corpus's cases must
// fail, and it checks the first diagnostic only.

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

/// Every uniform layout that GLSL std140 and WGSL disagree on is refused by
/// the checker, located at the uniform's type, as a user error (exit 1),
/// whatever targets are requested: emit's own std140 check only catches
/// lowering bugs. The programs are the layout cases of the bad-input corpus
/// (`tests/bad_inputs/`, which runs them with every target through the CLI);
/// here each is compiled with `compile_source` for each set of targets.
#[test]
fn refused_uniform_layouts_are_located_user_errors_for_every_target_set() {
    use umbrac::{Options, Severity, Target};
    const CASES: &[&str] = &[
        "sema_bool_uniform.das",
        "sema_uniform_bool_vector_field.das",
        "sema_uniform_float2x2.das",
        "sema_uniform_float3x2_field.das",
        "sema_uniform_scalar_array.das",
        "sema_uniform_float2_array.das",
        "sema_uniform_float3_array_field.das",
        "sema_uniform_struct_array_stride.das",
        "sema_uniform_struct_field_offset.das",
        "sema_uniform_after_nested_struct.das",
    ];
    let target_sets: &[&[Target]] = &[&[], &[Target::Glsl330], &[Target::Gles300], &[Target::Wgsl], &[Target::Spirv], &[Target::Wgsl, Target::Spirv]];
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_inputs");
    let mut failures = Vec::new();
    for name in CASES {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        // `// expect: LINE:COL: MESSAGE`, as `parse_case` reads it.
        let expect = text.lines().next().and_then(|l| l.strip_prefix("// expect: ")).unwrap_or_else(|| panic!("{name}: no expect line"));
        let mut parts = expect.splitn(3, ':');
        let (line, col, message) = (parts.next().unwrap(), parts.next().unwrap(), parts.next().unwrap().trim_start());
        let want = (line.parse::<usize>().unwrap(), col.parse::<usize>().unwrap());
        for targets in target_sets {
            let opts = Options { targets: targets.to_vec(), ..Options::default() };
            let c = umbrac::compile_source(name, &text, &opts);
            let what = format!("{name} for {targets:?}");
            if c.result.is_some() {
                failures.push(format!("{what}: compiles"));
                continue;
            }
            if c.diagnostics.iter().any(|d| d.severity == Severity::Bug) {
                failures.push(format!("{what}: internal error:\n{}", c.render_diagnostics()));
                continue;
            }
            let Some(first) = c.diagnostics.iter().find(|d| d.is_error()) else {
                failures.push(format!("{what}: no error"));
                continue;
            };
            let at = first.span.and_then(|s| c.sources.line_col(s)).map(|(_, l, c)| (l, c));
            if first.severity != Severity::Error || !first.message.starts_with(message) || at != Some(want) {
                failures.push(format!("{what}: got {:?} {at:?} {:?}, want an error at {want:?} starting {message:?}", first.severity, first.message));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A wrong type inside a uniform struct is reported once, at the type; the
/// uniform's layout check says nothing about it (it used to add a second
/// error naming an internal `{error}` placeholder).
#[test]
fn an_unknown_type_in_a_uniform_struct_is_reported_once() {
    let text = std::fs::read_to_string(dir().join("sema_uniform_struct_unknown_field_type.das")).unwrap();
    let c = umbrac::compile_source("u.das", &text, &umbrac::Options::default());
    let errors: Vec<&str> = c.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.message.as_str()).collect();
    assert_eq!(errors, ["unknown type `flaot3`"], "{}", c.render_diagnostics());
    assert!(!c.render_diagnostics().contains("{error}"));
}
