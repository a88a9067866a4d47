//! Compile time of pathological program shapes against the scene program,
//! per megabyte of source: whatever a file holds, compiling it (or refusing
//! it) costs time in proportion to its size. Each shape must stay within
//! 10x the scene program's time per MB; the run exits 1 if one does not.
//!
//!     cargo bench --bench pathological
//!
//! Prints a markdown table (docs/performance.md has the one on record) and
//! writes it to target/perf/pathological.md. Times are process CPU time of
//! `compile_source` with every target, medians.

#[path = "support/mod.rs"]
mod support;

use std::fmt::Write as _;

use support::*;

/// How many times the scene program's time per MB a shape may take.
const BOUND: f64 = 10.0;

/// One expression of 10 MB on one line (`u + u + ... `): refused at the
/// nesting and token limits, with diagnostics on that line.
fn huge_line() -> String {
    let terms = 10_000_000 / 4;
    format!("var @uniform u : float\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    f_color = float4({}u)\n}}\n", "u + ".repeat(terms))
}

/// 200 000 uniforms, every one read: refused past the binding limit.
fn uniforms_used() -> String {
    let n = 200_000;
    let mut s: String = (0..n).map(|i| format!("var @uniform u{i} : float4\n")).collect();
    s.push_str("var @out f_color : float4\n[fragment_program]\ndef fs {\n");
    s.extend((0..n).map(|i| format!("    f_color += u{i}\n")));
    s.push_str("}\n");
    s
}

/// A struct with 200 000 fields, a local of the fragment program: compiles
/// (as a uniform it would be a 3.2 MB block, past the 64 KiB limit).
fn struct_fields() -> String {
    let n = 200_000;
    let mut s = String::from("struct Big {\n");
    s.extend((0..n).map(|i| format!("    f{i} : float4\n")));
    s.push_str("}\nvar @uniform u : float4\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    var big : Big\n    big.f199999 = u\n    f_color = big.f0 + big.f199999\n}\n");
    s
}

/// 100 000 one-line helper functions, each called once in a chain.
fn tiny_functions() -> String {
    let n = 100_000;
    let mut s: String = (0..n).map(|i| format!("def f{i}(x : float) : float {{\n    return x + 1.0\n}}\n")).collect();
    s.push_str("var @out f_color : float4\n[fragment_program]\ndef fs {\n    var a = 0.0\n");
    s.extend((0..n).map(|i| format!("    a = f{i}(a)\n")));
    s.push_str("    f_color = float4(a)\n}\n");
    s
}

/// A file of the size limit (16 MiB): the scene program after host code
/// (functions the shaders do not reach, split but never parsed), with a
/// comment in each so the file stays under the token limit (4 Mi tokens
/// after preprocessing, host code included).
fn file_at_the_limit() -> String {
    let limit = umbrac::syntax::MAX_FILE_SIZE;
    let mut s = String::with_capacity(limit);
    let mut k = 0;
    let host = |k: usize| format!("// host function {k}: what a daslang program runs on the CPU; umbrac skips it whole\ndef host_{k}(a : int; b : float) : float {{\n    var t = float(a) * b\n    for (i in range(a)) {{\n        t += sin(float(i))\n    }}\n    return t\n}}\n");
    while s.len() + host(k).len() + SHADOW_DAS.len() < limit {
        s.push_str(&host(k));
        k += 1;
    }
    s.push_str(SHADOW_DAS);
    s
}

fn main() {
    type Shape = (&'static str, fn() -> String);
    let shapes: [Shape; 5] = [
        ("one 10 MB line", huge_line),
        ("200 000 uniforms used", uniforms_used),
        ("a 200 000-field struct", struct_fields),
        ("100 000 tiny functions", tiny_functions),
        ("a 16 MiB file (host code + scene)", file_at_the_limit),
    ];
    let compile = |src: &str| umbrac::compile_source("shape.das", src, &umbrac::Options::default());
    let base = time(5, 40, 1, || compile(SHADOW_DAS));
    let mb = |s: &str| s.len() as f64 / (1 << 20) as f64;
    let base_per_mb = base.median() / mb(SHADOW_DAS);
    let mut md = String::new();
    writeln!(md, "### Pathological shapes, compile time per MB\n\nMachine: {}.\n", machine()).unwrap();
    writeln!(md, "| shape | size MB | result | s (p10-p90) | s/MB | x scene |").unwrap();
    writeln!(md, "|---|---|---|---|---|---|").unwrap();
    writeln!(
        md,
        "| scene program (`shaders/shadow.das`) | {:.4} | compiles | {:.4} ({:.4}-{:.4}) | {:.3} | 1.0 |",
        mb(SHADOW_DAS),
        base.median(),
        base.p10(),
        base.p90(),
        base_per_mb
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for (name, make) in shapes {
        let src = make();
        let outcome = {
            let c = compile(&src);
            match (&c.result, c.diagnostics.iter().find(|d| d.is_error())) {
                (Some(_), _) => "compiles".to_string(),
                (None, Some(d)) => format!("refused: {}", d.message.split(" (").next().unwrap_or("")),
                (None, None) => "failed without a diagnostic".into(),
            }
        };
        let t = time(1, 3, 1, || compile(&src));
        let per_mb = t.median() / mb(&src);
        let ratio = per_mb / base_per_mb;
        worst = worst.max(ratio);
        eprintln!("{name}: {:.1} MB, {:.3} s, {per_mb:.3} s/MB, {ratio:.2}x", mb(&src), t.median());
        writeln!(md, "| {name} | {:.1} | {outcome} | {:.3} ({:.3}-{:.3}) | {per_mb:.3} | {ratio:.2} |", mb(&src), t.median(), t.p10(), t.p90()).unwrap();
    }
    writeln!(md, "\nWorst: {worst:.2}x the scene program's time per MB (bound: {BOUND}x).").unwrap();
    println!("{md}");
    std::fs::create_dir_all("target/perf").unwrap();
    std::fs::write("target/perf/pathological.md", &md).unwrap();
    if worst > BOUND {
        eprintln!("a shape takes {worst:.2}x the scene program's time per MB, more than {BOUND}x");
        std::process::exit(1);
    }
}

/// The machine and its load (timings on a shared machine mean little
/// without it).
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("model name")).map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string()))
        .unwrap_or_default();
    let load = std::fs::read_to_string("/proc/loadavg").map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" ")).unwrap_or_default();
    format!("{} cores ({cpu}), load average {load} at the start", std::thread::available_parallelism().map_or(0, |n| n.get()))
}
