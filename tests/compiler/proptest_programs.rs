//! Property test: generated well-typed programs compile, validate in naga
//! (which the compiler does on every compile), and pass glslangValidator
//! (GLSL 330 and ES 300, each file and each vertex+fragment pair linked)
//! and spirv-val.
//!
//! The generator builds expressions over float, float2, float3 and float4
//! from uniforms, vertex inputs, varyings, locals, parameters, literals,
//! arithmetic, swizzles, constructors, comparisons in `?:`, math builtins
//! and calls of helper functions; statements are locals, assignments,
//! `op=`, `if`/`else` and `for` loops.
//!
//! 64 cases by default (CI budget); more with `PROPTEST_CASES=1000`.
//! A failure prints the shrunk program; proptest records its seed under
//! `proptest-regressions/`.

use crate::support;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum T {
    F1,
    F2,
    F3,
    F4,
}

const TYPES: [T; 4] = [T::F1, T::F2, T::F3, T::F4];

impl T {
    fn name(self) -> &'static str {
        match self {
            T::F1 => "float",
            T::F2 => "float2",
            T::F3 => "float3",
            T::F4 => "float4",
        }
    }
    fn width(self) -> usize {
        self as usize + 1
    }
    fn of_width(n: usize) -> T {
        TYPES[n - 1]
    }
    fn idx(self) -> usize {
        self as usize
    }
}

/// Names in scope, by type, and the helpers that may be called.
#[derive(Clone, Default)]
struct Env {
    vars: [Vec<&'static str>; 4],
    helpers: bool,
}

fn env(vars: &[(&'static str, T)], helpers: bool) -> Env {
    let mut e = Env { helpers, ..Env::default() };
    for &(n, t) in vars {
        e.vars[t.idx()].push(n);
    }
    e
}

const UNIFORMS: [(&str, T); 4] = [("u_time", T::F1), ("u_offset", T::F2), ("u_tint", T::F3), ("u_params", T::F4)];

fn literal() -> BoxedStrategy<String> {
    (0u32..64).prop_map(|k| format!("{}.{}", k / 8, (k % 8) * 125)).boxed()
}

/// Strategies for expressions of each type, `depth` levels deep at most.
fn exprs(env: &Env, depth: u32) -> [BoxedStrategy<String>; 4] {
    let leaves: Vec<BoxedStrategy<String>> = TYPES
        .iter()
        .map(|&t| {
            let mut options: Vec<BoxedStrategy<String>> = Vec::new();
            let lit = literal();
            options.push(if t == T::F1 { lit } else { lit.prop_map(move |l| format!("{}({l})", t.name())).boxed() });
            let names: Vec<String> = env.vars[t.idx()].iter().map(|s| s.to_string()).collect();
            if !names.is_empty() {
                options.push(proptest::sample::select(names).boxed());
            }
            proptest::strategy::Union::new(options).boxed()
        })
        .collect();
    let mut level: Vec<BoxedStrategy<String>> = leaves.clone();
    for _ in 0..depth {
        let prev = level.clone();
        let f1 = prev[0].clone();
        level = TYPES
            .iter()
            .map(|&t| {
                let e = prev[t.idx()].clone();
                let mut o: Vec<BoxedStrategy<String>> = vec![
                    leaves[t.idx()].clone(),
                    (e.clone(), e.clone(), prop::sample::select(vec!["+", "-", "*"])).prop_map(|(a, b, op)| format!("({a} {op} {b})")).boxed(),
                    e.clone().prop_map(|a| format!("(-{a})")).boxed(),
                    (e.clone(), prop::sample::select(vec!["sin", "cos", "abs", "fract", "floor", "saturate"]))
                        .prop_map(|(a, f)| format!("{f}({a})"))
                        .boxed(),
                    // Bounded: `exp2` of a constant above 128 is infinite, a
                    // compile error since constants must be finite.
                    e.clone().prop_map(|a| format!("exp2(sin({a}) * 8.0)")).boxed(),
                    (e.clone(), e.clone(), prop::sample::select(vec!["min", "max", "step"])).prop_map(|(a, b, f)| format!("{f}({a}, {b})")).boxed(),
                    (e.clone(), e.clone(), f1.clone()).prop_map(|(a, b, s)| format!("lerp({a}, {b}, saturate({s}))")).boxed(),
                    e.clone().prop_map(|a| format!("sqrt(abs({a}) + 1.0)")).boxed(),
                    (f1.clone(), f1.clone(), e.clone(), e.clone(), prop::sample::select(vec!["<", ">", "<=", "==", "!="]))
                        .prop_map(|(x, y, a, b, c)| format!("({x} {c} {y} ? {a} : {b})"))
                        .boxed(),
                ];
                if t != T::F1 {
                    // vector * scalar, and swizzles / constructors from other widths
                    o.push((e.clone(), f1.clone()).prop_map(|(a, s)| format!("({a} * {s})")).boxed());
                    let wide = prev[3].clone();
                    o.push((wide, prop::sample::select(vec!["x", "y", "z", "w"]), 0usize..4).prop_map(move |(v, _c, r)| {
                        let comps = ["x", "y", "z", "w", "r", "g", "b", "a"];
                        let sw: String = (0..t.width()).map(|i| comps[(i + r) % 4 + if r % 2 == 0 { 0 } else { 4 }]).collect();
                        format!("({v}).{sw}")
                    }).boxed());
                    if t.width() >= 2 {
                        let lo = prev[T::of_width(t.width() - 1).idx()].clone();
                        o.push((lo, f1.clone()).prop_map(move |(a, s)| format!("{}({a}, {s})", t.name())).boxed());
                    }
                } else {
                    for v in [T::F2, T::F3, T::F4] {
                        let ev = prev[v.idx()].clone();
                        o.push((ev.clone(), ev.clone()).prop_map(|(a, b)| format!("dot({a}, {b})")).boxed());
                        o.push(ev.clone().prop_map(|a| format!("length({a})")).boxed());
                        o.push(ev.prop_map(|a| format!("({a}).y")).boxed());
                    }
                }
                if t == T::F3 {
                    let e3 = prev[2].clone();
                    o.push((e3.clone(), e3).prop_map(|(a, b)| format!("cross({a}, {b})")).boxed());
                }
                if env.helpers {
                    match t {
                        T::F3 => o.push((prev[2].clone(), f1.clone()).prop_map(|(a, s)| format!("shade({a}, {s})")).boxed()),
                        T::F1 => o.push(f1.clone().prop_map(|a| format!("wave({a})")).boxed()),
                        T::F2 => o.push(prev[3].clone().prop_map(|a| format!("fold({a})")).boxed()),
                        T::F4 => {}
                    }
                }
                proptest::strategy::Union::new(o).boxed()
            })
            .collect();
    }
    [level[0].clone(), level[1].clone(), level[2].clone(), level[3].clone()]
}

/// Statements over the locals `t3 : float3` and `t1 : float` (declared
/// before them), as text, indented by four spaces.
fn stmts(env: &Env) -> BoxedStrategy<String> {
    let e = exprs(env, 2);
    let (e1, e3) = (e[0].clone(), e[2].clone());
    let cond = (e1.clone(), e1.clone(), prop::sample::select(vec!["<", ">", ">="])).prop_map(|(a, b, c)| format!("{a} {c} {b}"));
    let one = prop_oneof![
        e3.clone().prop_map(|x| format!("    t3 = {x}\n")),
        e3.clone().prop_map(|x| format!("    t3 += {x}\n")),
        e1.clone().prop_map(|x| format!("    t1 *= {x}\n")),
        (cond, e3.clone(), e1.clone()).prop_map(|(c, a, b)| format!("    if ({c}) {{\n        t3 = {a}\n    }} else {{\n        t1 = {b}\n    }}\n")),
        (1i32..5, e1.clone()).prop_map(|(n, x)| format!("    for i in range({n}) {{\n        t1 += float(i) * {x}\n    }}\n")),
        e3.prop_map(|x| format!("    let k = {x}\n    t3 = k * 0.5\n")),
    ];
    prop::collection::vec(one, 0..4).prop_map(|v| v.into_iter().map(|s| if s.contains("let k") { format!("    {{\n{s}    }}\n") } else { s }).collect()).boxed()
}

fn program() -> impl Strategy<Value = String> {
    let helper_env = |params: &[(&'static str, T)]| {
        let mut v: Vec<(&'static str, T)> = UNIFORMS.to_vec();
        v.extend_from_slice(params);
        env(&v, false)
    };
    let shade = exprs(&helper_env(&[("x", T::F3), ("s", T::F1)]), 2)[2].clone();
    let wave = exprs(&helper_env(&[("x", T::F1)]), 2)[0].clone();
    let fold = exprs(&helper_env(&[("v", T::F4)]), 2)[1].clone();

    let mut vs_vars: Vec<(&'static str, T)> = UNIFORMS.to_vec();
    vs_vars.extend([("a_pos", T::F3), ("a_uv", T::F2), ("t3", T::F3), ("t1", T::F1)]);
    let vs_env = env(&vs_vars, true);
    let mut fs_vars: Vec<(&'static str, T)> = UNIFORMS.to_vec();
    fs_vars.extend([("v_color", T::F3), ("v_fade", T::F1), ("v_uv", T::F2), ("t3", T::F3), ("t1", T::F1)]);
    let fs_env = env(&fs_vars, true);
    let vs = exprs(&vs_env, 3);
    let fs = exprs(&fs_env, 3);
    // The locals' initialisers cannot use the locals.
    let without_locals = |vars: &[(&'static str, T)]| env(&vars[..vars.len() - 2], true);
    let vs_init = exprs(&without_locals(&vs_vars), 3);
    let fs_init = exprs(&without_locals(&fs_vars), 3);

    (
        (shade, wave, fold),
        (vs_init[2].clone(), vs_init[0].clone(), stmts(&vs_env), vs[2].clone(), vs[0].clone(), vs[1].clone()),
        (fs_init[2].clone(), fs_init[0].clone(), stmts(&fs_env), fs[2].clone(), fs[0].clone()),
    )
        .prop_map(|((shade, wave, fold), (v3, v1, vstmts, vpos, vfade, vuv), (f3, f1, fstmts, fcol, falpha))| {
            format!(
                "var @uniform u_time : float\nvar @uniform u_offset : float2\nvar @uniform u_tint : float3\nvar @uniform u_params : float4\n\
                 var @in @location = 0 a_pos : float3\nvar @in @location = 1 a_uv : float2\n\
                 var @inout v_color : float3\nvar @inout v_fade : float\nvar @inout v_uv : float2\n\
                 var @out f_color : float4\n\n\
                 def shade(x : float3; s : float) : float3 {{\n    return {shade}\n}}\n\n\
                 def wave(x : float) : float {{\n    let w = {wave}\n    return w * 0.5\n}}\n\n\
                 def fold(v : float4) : float2 {{\n    return {fold}\n}}\n\n\
                 [vertex_program]\ndef vs {{\n    var t3 = {v3}\n    var t1 = {v1}\n{vstmts}    v_color = t3\n    v_fade = t1\n    v_uv = {vuv}\n    gl_Position = float4({vpos}, 1.0) + float4(0.0, 0.0, 0.0, {vfade})\n}}\n\n\
                 [fragment_program]\ndef fs {{\n    var t3 = {f3}\n    var t1 = {f1}\n{fstmts}    f_color = float4({fcol}, saturate({falpha}))\n}}\n"
            )
        })
}

#[test]
fn generated_programs_compile_and_validate() {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(64);
    let tools = support::require_tool("glslangValidator") && support::require_tool("spirv-val");
    let mut runner = TestRunner::new(Config { cases, failure_persistence: None, ..Config::default() });
    let validator_runs = std::cell::Cell::new(0);
    let result = runner.run(&program(), |src| {
        let c = umbrac::compile_source("gen.das", &src, &umbrac::Options::default());
        prop_assert!(!c.has_errors(), "does not compile:\n{}\n{src}", c.render_diagnostics());
        let Some(r) = c.result else { return Err(TestCaseError::fail("no result")) };
        if tools {
            let d = tempfile::tempdir().unwrap();
            support::write_all(d.path(), &r.artifacts);
            let runs = std::panic::catch_unwind(|| support::validate_dir(d.path(), &r.reflection));
            match runs {
                Ok(n) => validator_runs.set(validator_runs.get() + n),
                Err(e) => {
                    let msg = e.downcast_ref::<String>().cloned().unwrap_or_default();
                    return Err(TestCaseError::fail(format!("{msg}\n{src}")));
                }
            }
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    eprintln!("{cases} generated programs compiled; {} validator runs passed", validator_runs.get());
}
