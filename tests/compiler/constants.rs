//! Compiler constant handling, the numerical hard cases that need no GPU:
//! - every float literal reaches every target with the same f32 bits (the
//!   emitted text parses back to the value the source literal denotes,
//!   correctly rounded once from decimal to f32);
//! - folding that would overflow, divide by zero or index out of range is a
//!   diagnostic, never a wrong number.

use std::collections::BTreeSet;

use umbrac::{compile_source, Options};

/// Literals chosen to break sloppy printing or rounding: shortest
/// round-trip digits, the f32 extremes, a subnormal, integers past 2^24,
/// and a decimal just above the midpoint between two f32 values, which
/// parsing through f64 first rounds the wrong way (double rounding).
const LITERALS: [&str; 14] = [
    "0.1",
    "0.2",
    "0.33333334",
    "16777217.0",
    "3.4028235e38",
    "1.1754944e-38",
    "1.0e-40",
    "1.00000005960464478",
    "123456.79",
    "6.2831855",
    "0.0009765625",
    "1.0e10",
    "2.5e-7",
    "0.7853982",
];

fn program() -> String {
    let mut terms = String::new();
    for (i, lit) in LITERALS.iter().enumerate() {
        // Multiplied by a uniform so nothing folds the literals together.
        terms.push_str(&format!("    acc += u_x * {lit}\n    let c{i} = {lit}\n    acc += float4(c{i}) * u_x\n"));
    }
    format!(
        "var @uniform u_x : float4\nvar @out f_color : float4\n\n[vertex_program]\ndef vs {{\n    gl_Position = u_x\n}}\n\n[fragment_program]\ndef fs {{\n    var acc = float4(0.0)\n{terms}    f_color = acc\n}}\n"
    )
}

fn expected() -> BTreeSet<u32> {
    LITERALS.iter().map(|l| l.parse::<f32>().unwrap().to_bits()).collect()
}

/// Every decimal or exponent number in GLSL text, as f32 bits.
fn glsl_floats(text: &str) -> BTreeSet<u32> {
    let b = text.as_bytes();
    let mut out = BTreeSet::new();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit() && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
        if !starts {
            i += 1;
            continue;
        }
        let s = i;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
            i += 1;
        }
        if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
            i += 1;
            if i < b.len() && (b[i] == b'-' || b[i] == b'+') {
                i += 1;
            }
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
        }
        if let Ok(v) = text[s..i].parse::<f32>() {
            out.insert(v.to_bits());
        }
        // Skip a suffix (`1.0f`, `0u`).
        while i < b.len() && b[i].is_ascii_alphabetic() {
            i += 1;
        }
    }
    out
}

/// Every f32 literal of a naga module (constants and function bodies).
fn naga_floats(m: &naga::Module) -> BTreeSet<u32> {
    let mut out = BTreeSet::new();
    let mut take = |arena: &naga::Arena<naga::Expression>| {
        for (_, e) in arena.iter() {
            if let naga::Expression::Literal(naga::Literal::F32(v)) = e {
                out.insert(v.to_bits());
            }
        }
    };
    take(&m.global_expressions);
    for (_, f) in m.functions.iter() {
        take(&f.expressions);
    }
    for ep in &m.entry_points {
        take(&ep.function.expressions);
    }
    out
}

/// Every 32-bit float OpConstant of a SPIR-V module.
fn spirv_floats(bytes: &[u8]) -> BTreeSet<u32> {
    let w: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    let mut float_types = BTreeSet::new();
    let mut out = BTreeSet::new();
    let mut i = 5;
    while i < w.len() {
        let (op, len) = (w[i] & 0xffff, (w[i] >> 16) as usize);
        match op {
            22 if w[i + 2] == 32 => {
                float_types.insert(w[i + 1]); // OpTypeFloat %id 32
            }
            43 if float_types.contains(&w[i + 1]) => {
                out.insert(w[i + 3]); // OpConstant %type %id value
            }
            _ => {}
        }
        i += len.max(1);
    }
    out
}

#[test]
fn float_literals_round_trip_through_every_target() {
    let c = compile_source("literals.das", &program(), &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let want = expected();
    let compiled = c.result.as_ref().unwrap();
    let mut checked = 0;
    for a in &compiled.artifacts {
        let got = match a.target {
            Some(umbrac::Target::Wgsl) => {
                let module = naga::front::wgsl::parse_str(&a.text()).expect("naga re-parses the WGSL output");
                naga_floats(&module)
            }
            Some(umbrac::Target::Spirv) => spirv_floats(&a.contents),
            Some(umbrac::Target::Glsl330 | umbrac::Target::Gles300) if a.file_name.ends_with(".frag") => glsl_floats(&a.text()),
            _ => continue,
        };
        let missing: Vec<String> = want.difference(&got).map(|b| format!("{:e} ({b:#010x})", f32::from_bits(*b))).collect();
        assert!(missing.is_empty(), "{}: literals lost or changed: {missing:?}\n{}", a.file_name, a.text());
        checked += 1;
    }
    assert_eq!(checked, 4, "WGSL, SPIR-V and both GLSL fragment outputs");
}

#[test]
fn literal_rounding_is_direct_not_through_f64() {
    // The decimal lies just above the midpoint of 1.0 and the next f32; via
    // f64 it first rounds onto the midpoint, then ties to even: 1.0.
    let direct = "1.00000005960464478".parse::<f32>().unwrap();
    let via_f64 = "1.00000005960464478".parse::<f64>().unwrap() as f32;
    assert_ne!(direct, via_f64);
    assert!(expected().contains(&direct.to_bits()));
}

fn errors_of(body: &str) -> String {
    errors_using(body, "K")
}

/// Compiles `body` with the vertex program using `expr` (only what entry
/// points reach is compiled) and returns the diagnostics.
fn errors_using(body: &str, expr: &str) -> String {
    let src = format!(
        "var @uniform u_x : float4\nvar @out f_color : float4\n{body}\n[vertex_program]\ndef vs {{\n    gl_Position = u_x * {expr}\n}}\n[fragment_program]\ndef fs {{\n    f_color = u_x\n}}\n"
    );
    let c = compile_source("fold.das", &src, &Options::default());
    assert!(c.has_errors(), "expected an error for `{body}`, but it compiled");
    assert!(c.result.is_none());
    c.render_diagnostics()
}

#[test]
fn folding_overflow_is_an_error() {
    let e = errors_of("let K = 3.0e38 * 10.0");
    assert!(e.contains("overflow") || e.contains("infinite"), "{e}");
    let e = errors_of("let K = float(2147483647 + 1)");
    assert!(e.contains("overflow"), "{e}");
    let e = errors_of("let K = 1.0e39");
    assert!(e.contains("out of range"), "{e}");
    let e = errors_of("let K = -3.0e38 - 3.0e38");
    assert!(e.contains("overflow") || e.contains("infinite"), "{e}");
}

#[test]
fn folding_division_by_zero_is_an_error() {
    let e = errors_of("let K = 1.0 / 0.0");
    assert!(e.contains("division by zero"), "{e}");
    let e = errors_of("let K = float(7 / 0)");
    assert!(e.contains("division by zero"), "{e}");
    let e = errors_of("let K = float(7 % 0)");
    assert!(e.contains("division by zero"), "{e}");
    let e = errors_of("let K = 0.0 / 0.0");
    assert!(e.contains("division by zero"), "{e}");
}

#[test]
fn constant_indices_out_of_range_are_errors() {
    let e = errors_using("let V = float3(1.0, 2.0, 3.0)\ndef pick() : float {\n    return V[3]\n}", "pick()");
    assert!(e.contains("out of bounds") || e.contains("out of range"), "{e}");
    let e = errors_using("let I = 4\ndef pick(v : float4) : float {\n    return v[I]\n}", "pick(u_x)");
    assert!(e.contains("out of bounds") || e.contains("out of range"), "{e}");
    let e = errors_using("def pick(v : float4) : float {\n    return v[-1]\n}", "pick(u_x)");
    assert!(e.contains("out of bounds") || e.contains("out of range"), "{e}");
}

#[test]
fn folded_values_are_rounded_to_f32_at_every_step() {
    // 0.1 + 0.2 in f32 arithmetic, rounded after the add, is 0.3 (f32) and
    // equals 0.30000001192...; a chain folded in f64 without rounding can
    // land on a neighbouring f32.
    let src = "var @uniform u_x : float4\nvar @out f_color : float4\nlet K = 0.1 + 0.2\nlet J = 16777216.0 + 1.0 + 1.0\n[vertex_program]\ndef vs {\n    gl_Position = u_x\n}\n[fragment_program]\ndef fs {\n    f_color = u_x * K + u_x * J\n}\n";
    let c = compile_source("fold.das", src, &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let wgsl = c.result.as_ref().unwrap().artifact("fold.wgsl").unwrap().text().into_owned();
    let got = naga_floats(&naga::front::wgsl::parse_str(&wgsl).unwrap());
    assert!(got.contains(&(0.1f32 + 0.2f32).to_bits()), "{wgsl}");
    // f32: 16777216 + 1 rounds back to 16777216 at each step.
    assert!(got.contains(&16777216.0f32.to_bits()), "{wgsl}");
    assert!(!got.contains(&16777218.0f32.to_bits()), "{wgsl}");
}

/// A constructor of a constant integer keeps its value: `int2(2147483647)`
/// was converted through f32 and became 2147483520.
#[test]
fn integer_constructors_keep_every_bit() {
    let src = "var @uniform u_x : float4\nvar @out f_color : float4\nlet K = int2(2147483647)\nlet U = uint3(4294967295u)\n[vertex_program]\ndef vs {\n    gl_Position = u_x\n}\n[fragment_program]\ndef fs {\n    f_color = u_x * float(K.y) * float(U.z)\n}\n";
    let c = compile_source("ints.das", src, &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let wgsl = c.result.as_ref().unwrap().artifact("ints.wgsl").unwrap().text().into_owned();
    assert!(wgsl.contains("2147483647i, 2147483647i") && wgsl.contains("4294967295u"), "{wgsl}");
}

/// Constant subexpressions inside function bodies with a defined value
/// compile, and naga's WGSL front end accepts what umbrac writes for them:
/// the rules reject what is undefined, not everything near an edge.
#[test]
fn defined_constant_subexpressions_compile_and_naga_reads_them_back() {
    let cases = [
        "float(1 << 30)",
        "float(1u << 31u)",
        "float(-1 << 31)",
        "float(-2147483647 / -1)",
        "float(2147483647 % -1)",
        "float(7 >> 31)",
        "clamp(u_x.x, 0.0, 0.0)",
        "clamp(1.0, 0.0, 1.0)",
        "pow(0.0, 2.0)",
        "pow(2.0, -1.0)",
        "sqrt(0.0)",
        "log(1.0)",
        "acos(-1.0) + asin(1.0)",
        "exp(88.0)",
        "smoothstep(0.0, 1.0, 0.5)",
        "atan2(0.0, 1.0)",
        "length(float3(1.0e18))",
        "dot(normalize(float3(1.0, 2.0, 3.0)), float3(1.0))",
        "mod(-1.0, 3.0)",
        "float(abs(-2147483647))",
        "intBitsToFloat(1065353216)",
        "float(sign(-3))",
        "rcp(4.0)",
        "float(u_x.x > 0.0 ? 1 : 2)",
        "float(int(3.0e9))",
        "float((int2(2147483647) - int2(1)).x)",
    ];
    for e in cases {
        let src = format!("var @uniform u_x : float4\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    f_color = u_x * float4({e})\n}}\n");
        let c = compile_source("defined.das", &src, &Options::default());
        assert!(!c.has_errors(), "`{e}`:\n{}", c.render_diagnostics());
        let wgsl = c.result.as_ref().unwrap().artifact("defined.wgsl").unwrap().text().into_owned();
        let m = naga::front::wgsl::parse_str(&wgsl).unwrap_or_else(|err| panic!("`{e}`: naga rejects\n{}\n{wgsl}", err.emit_to_string(&wgsl)));
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
            .validate(&m)
            .unwrap_or_else(|err| panic!("`{e}`: {}", err.emit_to_string(&wgsl)));
    }
}
