//! Limits: inputs built to exhaust the stack, memory or time must end in a
//! diagnostic naming the limit (or compile fine), never in a crash. Each
//! compile runs on a thread with a 2 MiB stack, the test harness's default,
//! in whatever profile the tests are built with: in debug builds umbrac
//! moves the work to a large-stack thread of its own, in release builds it
//! compiles on the 2 MiB thread itself (`cargo test --release
//! --no-default-features --test compiler limits::`, docs/robustness.md).

use umbrac::{compile_source, Compilation, Options};

const STACK: usize = 2 << 20;

/// Compiles on a fresh 2 MiB thread. A stack overflow aborts the whole
/// test binary (every compiler test), which fails the run.
fn compile_small_stack(src: String) -> Compilation {
    std::thread::Builder::new()
        .stack_size(STACK)
        .spawn(move || compile_source("limits.das", &src, &Options::default()))
        .expect("spawn")
        .join()
        .expect("the compiler panicked")
}

fn fs(body: &str) -> String {
    format!("var @out f_color : float4\n[fragment_program]\ndef fs {{\n    var a = 1.0\n    var v = float4(1.0)\n{body}\n    f_color = float4(a)\n}}\n")
}

fn messages(c: &Compilation) -> Vec<String> {
    c.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.message.clone()).collect()
}

#[track_caller]
fn assert_limit(c: &Compilation, needle: &str) {
    let m = messages(c);
    assert!(c.result.is_none(), "compiled, but a limit error was expected");
    assert!(!m.is_empty() && m.len() <= 3, "want one limit error, got {} errors: {:?}", m.len(), &m[..m.len().min(5)]);
    assert!(m[0].contains(needle), "{:?} does not mention {needle:?}", m[0]);
    assert!(c.diagnostics.iter().all(|d| d.severity != umbrac::Severity::Bug), "{}", c.render_diagnostics());
}

const N: usize = 100_000;

#[test]
fn nested_parentheses() {
    let c = compile_small_stack(fs(&format!("    a = {}a{}", "(".repeat(N), ")".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn unclosed_parentheses() {
    let c = compile_small_stack(fs(&format!("    a = {}a", "(".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn nested_blocks() {
    let c = compile_small_stack(fs(&format!("{}{}", "{\n".repeat(N), "}\n".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn nested_ifs() {
    let c = compile_small_stack(fs(&format!("{}{}", "if a > 0.0 {\n".repeat(N), "}\n".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn long_binary_chain() {
    let c = compile_small_stack(fs(&format!("    a = a{}", " + a".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn long_elif_chain() {
    let c = compile_small_stack(fs(&format!("    if a > 0.0 {{\n    }}{}", " elif a > 1.0 {\n    }".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn long_swizzle_chain() {
    let c = compile_small_stack(fs(&format!("    v = v{}", ".xyzw".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn long_index_chain() {
    let c = compile_small_stack(fs(&format!("    a = v{}", "[0]".repeat(N))));
    assert!(c.result.is_none());
}

#[test]
fn long_postfix_chain() {
    let c = compile_small_stack(fs(&format!("    a{}", "++".repeat(N))));
    assert!(c.result.is_none());
}

#[test]
fn long_unary_chain() {
    let c = compile_small_stack(fs(&format!("    a = {}a", "- ".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn long_ternary_chain() {
    let c = compile_small_stack(fs(&format!("    a = {}a", "a > 0.0 ? a : ".repeat(N))));
    assert_limit(&c, "limit");
}

#[test]
fn deep_array_type() {
    let c = compile_small_stack(fs(&format!("    var t : float{}", "[1]".repeat(N))));
    assert!(c.result.is_none());
}

#[test]
fn long_call_chain() {
    let n = 20_000;
    let mut src = String::from("var @out f_color : float4\n");
    for i in 0..n {
        src.push_str(&format!("def f{i}(x : float) : float {{\n    return f{}(x) + 1.0\n}}\n", i + 1));
    }
    src.push_str(&format!("def f{n}(x : float) : float {{\n    return x\n}}\n[fragment_program]\ndef fs {{\n    f_color = float4(f0(1.0))\n}}\n"));
    let c = compile_small_stack(src);
    assert!(c.result.is_none());
}

#[test]
fn long_constant_chain() {
    let n = 20_000;
    let mut src = String::from("var @out f_color : float4\nlet c0 = 1.0\n");
    for i in 1..=n {
        src.push_str(&format!("let c{i} = c{} + 1.0\n", i - 1));
    }
    src.push_str(&format!("[fragment_program]\ndef fs {{\n    f_color = float4(c{n})\n}}\n"));
    let c = compile_small_stack(src);
    assert!(c.result.is_none());
}

#[test]
fn long_struct_chain() {
    let n = 20_000;
    let mut src = String::from("var @out f_color : float4\nstruct S0 {\n    x : float\n}\n");
    for i in 1..=n {
        src.push_str(&format!("struct S{i} {{\n    s : S{}\n}}\n", i - 1));
    }
    src.push_str(&format!("[fragment_program]\ndef fs {{\n    var s : S{n}\n    f_color = float4(1.0)\n}}\n"));
    let c = compile_small_stack(src);
    assert!(c.result.is_none());
}

// ---- just inside the limits: these compile, all the way through naga and
// every backend, on the same 2 MiB stack.

#[track_caller]
fn assert_compiles(c: &Compilation) {
    assert!(!c.has_errors(), "{}", c.render_diagnostics().chars().take(2000).collect::<String>());
}

#[test]
fn deepest_accepted_expressions_compile() {
    let n = 120;
    assert_compiles(&compile_small_stack(fs(&format!("    a = {}a{}", "(".repeat(n), ")".repeat(n)))));
    assert_compiles(&compile_small_stack(fs(&format!("    a = a{}", " + a".repeat(n)))));
    // A unary operator counts two levels (its operand is written in
    // parentheses): 60 of them, not 120.
    assert_compiles(&compile_small_stack(fs(&format!("    a = {}a", "- ".repeat(n / 2)))));
    assert!(compile_small_stack(fs(&format!("    a = {}a", "- ".repeat(65)))).has_errors(), "65 unary operators are 130 levels");
    assert_compiles(&compile_small_stack(fs(&format!("    a = {}a", "a > 0.0 ? a : ".repeat(n / 2)))));
    assert_compiles(&compile_small_stack(fs(&format!("    a = {}a{}", "sin(".repeat(n), ")".repeat(n)))));
    assert_compiles(&compile_small_stack(fs(&format!("    v = v{}", ".wzyx".repeat(n)))));
    // WGSL nests each `elif` two levels deeper (tests/bad_inputs/limit_wgsl_nesting_elif.das).
    assert_compiles(&compile_small_stack(fs(&format!("    if a > 0.0 {{\n        a = 1.0\n    }}{}", " elif a > 1.0 {\n        a = 2.0\n    }".repeat(n / 2)))));
}

#[test]
fn deepest_accepted_blocks_compile() {
    let n = 60;
    // Blocks, each with an expression as deep as the remaining budget allows.
    let open = "if a > 0.0 {\n".repeat(n);
    let close = "}\n".repeat(n);
    let deep = format!("a = {}a{}\n", "(".repeat(50), ")".repeat(50));
    assert_compiles(&compile_small_stack(fs(&format!("{open}{deep}{close}"))));
    let loops = "for i in range(3) {\n".repeat(n);
    assert_compiles(&compile_small_stack(fs(&format!("{loops}a += float(i)\n{close}"))));
}

#[test]
fn deepest_expressions_compile_on_a_compiler_thread() {
    // umbrac's own workers (CLI, build) compile on their thread directly,
    // in every build: its 32 MiB must hold the deepest program unoptimised.
    let n = 120;
    let src = fs(&format!("    a = {}a{}", "sin(".repeat(n), ")".repeat(n)));
    let c = std::thread::scope(|s| umbrac::spawn_compiler_thread(s, || compile_source("limits.das", &src, &Options::default())).unwrap().join());
    assert_compiles(&c.expect("the compiler panicked"));
}

#[test]
fn deepest_accepted_call_chain_compiles() {
    // Each helper calls the next inside an expression a few levels deep.
    let n = 24;
    let mut src = String::from("var @out f_color : float4\n");
    for i in 0..n {
        src.push_str(&format!("def f{i}(x : float) : float {{\n    return ((f{}(x) * 0.5 + 1.0))\n}}\n", i + 1));
    }
    src.push_str(&format!("def f{n}(x : float) : float {{\n    return x\n}}\n[fragment_program]\ndef fs {{\n    f_color = float4(f0(1.0))\n}}\n"));
    assert_compiles(&compile_small_stack(src));
}

// ---- the other limits, one test each

#[test]
fn source_size_limit() {
    let limit = umbrac::syntax::MAX_FILE_SIZE;
    let mut big = fs("    a = 1.0");
    big.push_str("//");
    big.push_str(&"x".repeat(limit + 1 - big.len()));
    let c = compile_small_stack(big.clone());
    assert_limit(&c, &format!("limit {limit} bytes"));
    // From disk: refused before it is read.
    let d = tempfile::tempdir().unwrap();
    let p = d.path().join("big.das");
    std::fs::write(&p, &big).unwrap();
    let c = umbrac::compile_file(&p, &Options::default());
    assert_limit(&c, "is too large");
}

#[test]
fn include_count_limit() {
    // One small file included more often than the limit allows.
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("inc.das"), "\n").unwrap();
    let n = umbrac::syntax::preprocess::MAX_INCLUDES + 1;
    let src = "#include \"inc.das\"\n".repeat(n) + &fs("    a = 1.0");
    let p = d.path().join("main.das");
    std::fs::write(&p, src).unwrap();
    let c = umbrac::compile_file(&p, &Options::default());
    assert_limit(&c, &format!("too many `#include`s (limit {})", n - 1));
}

#[test]
fn include_depth_limit() {
    // Distinct files, each including the next.
    let d = tempfile::tempdir().unwrap();
    let n = umbrac::syntax::MAX_INCLUDE_DEPTH + 4;
    for i in 0..n {
        std::fs::write(d.path().join(format!("f{i}.das")), format!("#include \"f{}.das\"\n", i + 1)).unwrap();
    }
    std::fs::write(d.path().join(format!("f{n}.das")), "").unwrap();
    let p = d.path().join("main.das");
    std::fs::write(&p, "#include \"f0.das\"\n".to_owned() + &fs("    a = 1.0")).unwrap();
    let c = umbrac::compile_file(&p, &Options::default());
    assert_limit(&c, &format!("`#include` nested too deeply (limit {})", umbrac::syntax::MAX_INCLUDE_DEPTH));
}

#[test]
fn macro_expansion_limits() {
    // Each macro expands to two copies of the previous one: 2^40 tokens.
    let mut src = String::from("#define M0 a\n");
    for i in 1..=40 {
        src.push_str(&format!("#define M{i} M{} + M{}\n", i - 1, i - 1));
    }
    let start = std::time::Instant::now();
    let c = compile_small_stack(src + &fs("    a = M40"));
    assert_limit(&c, &format!("limit {} tokens", umbrac::syntax::preprocess::MAX_TOKENS));
    eprintln!("expansion bomb stopped in {:?}", start.elapsed());
    // A chain of macros, each naming the next.
    let mut src = String::new();
    for i in 1..100 {
        src.push_str(&format!("#define N{i} N{}\n", i - 1));
    }
    let c = compile_small_stack(src + "#define N0 1.0\n" + &fs("    a = N99"));
    assert_limit(&c, "macro expansion nested too deeply (limit 64)");
}

#[test]
fn array_size_limits() {
    let max = umbrac::sema::MAX_ARRAY_LEN;
    assert_compiles(&compile_small_stack(fs(&format!("    var t : float[{max}]\n    t[3] = a\n    a = t[3]"))));
    for len in [format!("{}", max + 1), "0".into(), "-1".into(), "4294967297".into(), "99999999999999999999".into()] {
        let c = compile_small_stack(fs(&format!("    var t : float[{len}]")));
        assert!(c.result.is_none() && !messages(&c).is_empty(), "{len}");
        assert!(c.diagnostics.iter().all(|d| d.severity != umbrac::Severity::Bug));
    }
    let c = compile_small_stack(fs(&format!("    var t : float[{}]", max + 1)));
    assert_limit(&c, &format!("at most {max}"));
    // An array literal longer than the limit.
    let items = vec!["1.0"; max as usize + 1].join(", ");
    let c = compile_small_stack(fs(&format!("    var t = [{items}]")));
    assert_limit(&c, &format!("an array needs 1 to {max} elements"));
}

/// Loops are never unrolled: a loop with a billion iterations compiles to a
/// loop, quickly, with output the size of the source.
#[test]
fn loops_are_not_unrolled() {
    let start = std::time::Instant::now();
    let c = compile_small_stack(fs("    for i in range(1000000000) {\n        for j in range(1000000000) {\n            a += float(i + j)\n        }\n    }"));
    assert_compiles(&c);
    let r = c.result.unwrap();
    let wgsl = r.artifact("limits.wgsl").unwrap().text().into_owned();
    assert!(wgsl.matches("loop").count() >= 2 && wgsl.len() < 20_000, "{wgsl}");
    assert!(start.elapsed() < std::time::Duration::from_secs(30));
}

/// 100 000 independent errors: 50 reported, the rest counted, quickly.
#[test]
fn error_count_limit() {
    let body: String = (0..100_000).map(|i| format!("    var v{i} : int = 1.0\n")).collect();
    let start = std::time::Instant::now();
    let c = compile_small_stack(fs(&body));
    assert_eq!(messages(&c).len(), umbrac::Diagnostics::MAX_ERRORS);
    assert_eq!(c.suppressed_errors, 100_000 - umbrac::Diagnostics::MAX_ERRORS);
    eprintln!("100 000 errors in {:?}", start.elapsed());
}
