//! Differential test: for constant-foldable expressions, the value sema's
//! constant folder computes (emitted as a literal constant) equals what the
//! emitted shader computes at run time on a real device.
//!
//! One program holds every case twice: as a top-level `let` (folded at
//! compile time) and as the same expression whose operands are made opaque
//! to every compiler on the way (`x + z` with `z = int(gl_FragCoord.y)`,
//! which is 0 in a one-pixel-high target). A fragment shader writes both
//! bit patterns into pixel `i` of an `Rgba32Uint` target; the test reads
//! them back and compares. It runs the WGSL output through wgpu (Vulkan;
//! lavapipe on a machine without a GPU) and the SPIR-V output unchanged
//! where the device takes it (`PASSTHROUGH_SHADERS`).
//!
//! A second test runs `inverse` (lowered to the same closed-form helper on
//! every target) on matrices a renderer builds, against glam's f64 inverse.
//!
//! No adapter: the test is skipped, unless `CI=true` (then it fails).

use crate::support;

/// Result type of a case: how its bits are written.
#[derive(Clone, Copy)]
enum R {
    Int,
    Uint,
    Float,
    Bool,
}

/// Operands in braces: `{-7} % {3}`. An operand with `.` or `e` is a float,
/// one ending in `u` a uint, else an int.
const CASES: &[(&str, R)] = &[
    // `%` on ints: the truncated remainder (sign of the dividend).
    ("{-7} % {3}", R::Int),
    ("{7} % {-3}", R::Int),
    ("{-7} % {-3}", R::Int),
    ("{-2147483647} % {10}", R::Int),
    ("{13u} % {5u}", R::Uint),
    ("{4294967295u} % {7u}", R::Uint),
    // Integer division rounds toward zero.
    ("{-7} / {2}", R::Int),
    ("{7} / {-2}", R::Int),
    ("{-1} / {3}", R::Int),
    ("{-2147483648} / {2}", R::Int),
    ("{4294967295u} / {3u}", R::Uint),
    // `%` on floats is GLSL mod: x - y * floor(x / y).
    ("{-7.5} % {2.0}", R::Float),
    ("{7.5} % {-2.0}", R::Float),
    ("{-0.25} % {1.0}", R::Float),
    ("{5.3} % {0.7}", R::Float),
    // f32 arithmetic, one rounding per operation.
    ("{0.1} + {0.2}", R::Float),
    ("{1.0} / {3.0}", R::Float),
    ("{16777216.0} + {1.0}", R::Float),
    ("{-0.0} * {1.0}", R::Float),
    ("{3.0e38} * {0.5}", R::Float),
    ("{1.0e-30} * {1.0e-8}", R::Float),
    // Shifts: arithmetic on int, logical on uint; int or uint amounts.
    ("{-1} >> {1}", R::Int),
    ("{-8} >> {2u}", R::Int),
    ("{-1} << {31}", R::Int),
    ("{1} << {30}", R::Int),
    ("{4294967295u} >> {4u}", R::Uint),
    ("{3u} << {30}", R::Uint),
    // Bitwise operators on negative ints.
    ("{5} & {-3}", R::Int),
    ("{5} | {-3}", R::Int),
    ("{5} ^ {-3}", R::Int),
    // Conversions: int <-> uint keep the bits; float -> int truncates
    // toward zero; int -> float rounds to nearest.
    ("uint({-1})", R::Uint),
    ("int({4294967295u})", R::Int),
    ("int({2147483648u})", R::Int),
    ("float({16777217})", R::Float),
    ("float({-2147483647})", R::Float),
    ("float({4294967295u})", R::Float),
    ("int({-2.75})", R::Int),
    ("int({2.75})", R::Int),
    ("int({-0.5})", R::Int),
    ("uint({3.99})", R::Uint),
    ("int({2147483520.0})", R::Int),
    ("uint({-1.0})", R::Uint),
    ("int({3.0e9})", R::Int),
    ("int({-3.0e9})", R::Int),
    ("uint({5.0e9})", R::Uint),
    // Comparisons, including signed zero.
    ("{-0.0} == {0.0}", R::Bool),
    ("{-1} < {1}", R::Bool),
    ("{4294967295u} > {1u}", R::Bool),
    ("{0.1} + {0.2} == {0.3}", R::Bool),
];

/// Expressions the constant folder must refuse (they have no portable
/// value, or no value WGSL accepts as a constant), with part of the error.
const REFUSED: &[(&str, &str)] = &[
    ("1.0 / 0.0", "division by zero"),
    ("0.0 / 0.0", "division by zero"),
    ("3.0e38 * 10.0", "infinite"),
    ("1 / 0", "division by zero"),
    ("7 % 0", "division by zero"),
    ("2147483647 + 1", "overflow"),
    ("-2147483648 / -1", "overflow"),
    ("0u - 1u", "overflow"),
    ("1 << 32", "overflow"),
    // A `<<` that shifts out bits (the sign bit of an int included): WGSL
    // refuses it as a constant expression.
    ("1 << 31", "overflows"),
    ("3u << 31u", "overflows"),
];

fn operand(raw: &str, runtime: bool) -> String {
    if !runtime {
        return raw.to_string();
    }
    if raw.contains('.') || raw.contains('e') {
        format!("({raw} * f1)")
    } else if raw.ends_with('u') {
        format!("({raw} + uz)")
    } else {
        format!("({raw} + z)")
    }
}

/// The case with its operands as written, or made opaque.
fn instantiate(template: &str, runtime: bool) -> String {
    let mut out = String::new();
    let mut rest = template;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let close = open + rest[open..].find('}').expect("balanced braces");
        out.push_str(&operand(&rest[open + 1..close], runtime));
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    out
}

fn bits(e: &str, r: R) -> String {
    match r {
        R::Int => format!("uint({e})"),
        R::Uint => e.to_string(),
        R::Float => format!("floatBitsToUint({e})"),
        R::Bool => format!("(({e}) ? 1u : 0u)"),
    }
}

/// One triangle covering the target: every pixel runs `diff_fs`.
const VERTEX_ENTRY: &str =
    "[vertex_program]\ndef diff_vs {\n    let c = float2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2))\n    gl_Position = float4(c * 2.0 - float2(1.0), 0.0, 1.0)\n}\n\n";

fn program() -> String {
    let mut s = String::from("// generated by tests/gpu/differential.rs\nvar @out f_out : uint4\n\n");
    for (i, (t, _)) in CASES.iter().enumerate() {
        s.push_str(&format!("let K{i} = {}\n", instantiate(t, false)));
    }
    s.push('\n');
    s.push_str(VERTEX_ENTRY);
    s.push_str("[fragment_program]\ndef diff_fs {\n    let z = int(gl_FragCoord.y)\n    let uz = uint(z)\n    let f1 = 1.0 + float(z)\n    let x = int(gl_FragCoord.x)\n    var r = uint4(0u)\n");
    for (i, (t, ty)) in CASES.iter().enumerate() {
        let kw = if i == 0 { "if" } else { "elif" };
        let k = bits(&format!("K{i}"), *ty);
        let v = bits(&instantiate(t, true), *ty);
        s.push_str(&format!("    {kw} (x == {i}) {{\n        r = uint4({k}, {v}, 0u, 1u)\n    }}\n"));
    }
    s.push_str("    f_out = r\n}\n");
    s
}

fn compile(src: &str) -> umbrac::Compilation {
    umbrac::compile_source("differential.das", src, &umbrac::Options::default())
}

/// The program's words at each pixel, drawn as a self-checking frame plan
/// (`diff_vs` / `diff_fs` into a `width` x 1 integer target) from the WGSL
/// output, and from the SPIR-V output unchanged where the device allows
/// (`PASSTHROUGH_SHADERS`). No Vulkan device: empty (after `support::skip`).
fn results(compiled: &umbrac::Compiled, width: u32) -> Vec<(&'static str, Vec<[u32; 4]>)> {
    use umbrac::render::{plan, Executor, ShaderSet};
    let Some(gpu) = support::gpu::vulkan() else { return Vec::new() };
    let plan = plan::checks::plan("diff_vs", "diff_fs", width);
    let mut forms = vec![("WGSL", umbrac::Target::Wgsl)];
    if gpu.supports_passthrough() {
        forms.push(("SPIR-V", umbrac::Target::Spirv));
    } else {
        support::skip(format!("{} lacks PASSTHROUGH_SHADERS: SPIR-V not run, WGSL only", gpu.adapter_name()));
    }
    forms
        .into_iter()
        .map(|(label, target)| {
            let set = ShaderSet::from_compiled(label, compiled, target).unwrap();
            let prepared = gpu.prepare(&set, &plan).unwrap_or_else(|e| panic!("wgpu rejected the {label} program: {e}"));
            let readback = gpu.run(&prepared, &plan).unwrap_or_else(|e| panic!("the {label} program failed to draw: {e}"));
            (label, readback.words().expect("an integer target"))
        })
        .collect()
}

fn show(v: u32, r: R) -> String {
    match r {
        R::Int => format!("{}", v as i32),
        R::Uint => format!("{v}u"),
        R::Float => format!("{:?} (0x{v:08x})", f32::from_bits(v)),
        R::Bool => format!("{}", v != 0),
    }
}

/// Differences the language documents as not portable (docs/language.md,
/// "Integer and float semantics"): run-time float arithmetic may lose the
/// sign of zero and flush subnormal results to zero (Vulkan and GL do not
/// require either to be preserved); constants keep both.
fn tolerated(folded: u32, computed: u32, r: R) -> bool {
    if !matches!(r, R::Float) {
        return false;
    }
    let (a, b) = (f32::from_bits(folded), f32::from_bits(computed));
    let flushed = |x: f32, y: f32| x.is_subnormal() && y == 0.0;
    (a == 0.0 && b == 0.0) || flushed(a, b) || flushed(b, a)
}

fn check(label: &str, results: &[[u32; 4]]) {
    let mut failures = Vec::new();
    for (i, ((t, r), &[folded, computed, _, written])) in CASES.iter().zip(results).enumerate() {
        if written != 1 {
            failures.push(format!("case {i} `{t}`: pixel not written"));
        } else if folded != computed && tolerated(folded, computed, *r) {
            eprintln!("{label}: case {i} `{t}`: folded {} and computed {}: a documented non-portable difference", show(folded, *r), show(computed, *r));
        } else if folded != computed {
            failures.push(format!("case {i} `{t}`: folded {} but the {label} shader computed {}", show(folded, *r), show(computed, *r)));
        }
    }
    assert!(failures.is_empty(), "{label}: {} of {} cases differ:\n{}", failures.len(), CASES.len(), failures.join("\n"));
}

#[test]
fn constant_folding_matches_the_gpu() {
    let src = program();
    let c = compile(&src);
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("the differential program does not compile:\n{}\n{src}", c.render_diagnostics()));

    for (label, words) in results(compiled, CASES.len() as u32) {
        check(label, &words);
    }
}

#[test]
fn non_portable_constants_are_refused() {
    for (expr, needle) in REFUSED {
        let src = format!("let K = {expr}\nvar @out f : float4\n[fragment_program]\ndef fs {{\n    let k = K\n    f = float4(0.0)\n}}\n");
        let c = compile(&src);
        assert!(c.result.is_none(), "`{expr}` compiled");
        let text = c.render_diagnostics();
        assert!(text.contains(needle), "`{expr}`: expected an error mentioning `{needle}`, got:\n{text}");
        assert!(!text.contains("bug"), "`{expr}` is an internal error:\n{text}");
    }
}

/// Matrices whose inverse the shader computes (`inverse` is lowered to the
/// same closed-form helper on every target), column-major, with a name.
fn inverse_cases() -> Vec<(&'static str, usize, Vec<f64>)> {
    use glam::dcamera::rh::{proj::opengl, view::look_at_mat4};
    use glam::{DMat3, DMat4, DVec3};
    let rotation = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.52);
    let view = look_at_mat4(DVec3::new(3.0, 4.0, 5.0), DVec3::ZERO, DVec3::Y);
    let light = opengl::orthographic(-4.0, 4.0, -4.0, 4.0, 0.1, 20.0) * look_at_mat4(DVec3::new(5.0, 8.0, 3.0), DVec3::ZERO, DVec3::Y);
    let far_away = DMat4::from_translation(DVec3::new(1.0e4, -2.0e3, 5.0e3)) * DMat4::from_mat3(rotation);
    let stretched = DMat4::from_mat3(rotation * DMat3::from_diagonal(DVec3::new(1.0e3, 1.0, 1.0e-3)));
    vec![
        ("2x2", 2, vec![2.0, 1.0, 1.0, 3.0]),
        ("rotation * scale (a normal matrix)", 3, (rotation * DMat3::from_diagonal(DVec3::new(2.0, 0.5, 1.0))).to_cols_array().to_vec()),
        ("GL perspective projection", 4, opengl::perspective(1.047, 4.0 / 3.0, 0.1, 100.0).to_cols_array().to_vec()),
        ("look-at view", 4, view.to_cols_array().to_vec()),
        ("light view-projection", 4, light.to_cols_array().to_vec()),
        ("rotation at a large translation", 4, far_away.to_cols_array().to_vec()),
        ("scales 1e3 and 1e-3", 4, stretched.to_cols_array().to_vec()),
    ]
}

/// The f64 inverse of an n x n column-major matrix.
fn inverse_f64(n: usize, m: &[f64]) -> Vec<f64> {
    match n {
        2 => glam::DMat2::from_cols_slice(m).inverse().to_cols_array().to_vec(),
        3 => glam::DMat3::from_cols_slice(m).inverse().to_cols_array().to_vec(),
        _ => glam::DMat4::from_cols_slice(m).inverse().to_cols_array().to_vec(),
    }
}

#[test]
fn matrix_inverse_matches_f64_on_the_gpu() {
    // Each column of each case's inverse goes to its own pixel; the
    // entries are multiplied by 1.0 known only at run time, so no compiler
    // folds the inverse.
    let cases = inverse_cases();
    let mut src = String::from("// generated by tests/gpu/differential.rs\nvar @out f_out : uint4\n\n");
    src.push_str(VERTEX_ENTRY);
    src.push_str("[fragment_program]\ndef diff_fs {\n    let f1 = 1.0 + float(int(gl_FragCoord.y))\n    let x = int(gl_FragCoord.x)\n    var r = uint4(0u)\n");
    // Per pixel: (case, column); the entries as the shader's f32 literals.
    let mut pixels = Vec::new();
    let mut inputs = Vec::new();
    let mut chain = String::new();
    for (k, (_, n, m)) in cases.iter().enumerate() {
        let literals: Vec<String> = m.iter().map(|v| format!("{:?}", *v as f32)).collect();
        inputs.push(literals.iter().map(|l| l.parse::<f64>().unwrap() as f32 as f64).collect::<Vec<f64>>());
        let entries: Vec<String> = literals.iter().map(|l| format!("{l} * f1")).collect();
        src.push_str(&format!("    let m{k} = inverse(float{n}x{n}({}))\n", entries.join(", ")));
        for j in 0..*n {
            let pad = ["", "", ", 0.0, 0.0", ", 0.0", ""][*n];
            let kw = if pixels.is_empty() { "if" } else { "elif" };
            chain.push_str(&format!("    {kw} (x == {}) {{\n        r = floatBitsToUint(float4(m{k}[{j}]{pad}))\n    }}\n", pixels.len()));
            pixels.push((k, j));
        }
    }
    src.push_str(&chain);
    src.push_str("    f_out = r\n}\n");
    let c = compile(&src);
    let compiled = c.result.as_ref().unwrap_or_else(|| panic!("the inverse program does not compile:\n{}\n{src}", c.render_diagnostics()));

    for (label, results) in results(compiled, pixels.len() as u32) {
        let mut failures = Vec::new();
        for (k, (name, n, _)) in cases.iter().enumerate() {
            let want = inverse_f64(*n, &inputs[k]);
            // f32 arithmetic: errors in proportion to the inverse's largest
            // entry (the closed form's sums of products round once each).
            // Measured on lavapipe: at most 7.4e-8 of it (about half an f32
            // epsilon); allowed: 1e-6.
            let scale = want.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let mut worst = 0.0f64;
            for (p, _) in pixels.iter().enumerate().filter(|(_, (pk, _))| *pk == k) {
                let j = pixels[p].1;
                for i in 0..*n {
                    let got = f32::from_bits(results[p][i]) as f64;
                    worst = worst.max((got - want[j * n + i]).abs() / scale);
                }
            }
            eprintln!("{label} inverse of {name}: worst error {worst:.2e} of the largest entry ({scale:.3e})");
            if worst.is_nan() || worst > 1.0e-6 {
                failures.push(format!("{name}: worst error {worst:.2e} of the largest entry"));
            }
        }
        assert!(failures.is_empty(), "{label}: inverse differs from f64:\n{}", failures.join("\n"));
    }
}
