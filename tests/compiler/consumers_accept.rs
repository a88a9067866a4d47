//! Programs umbrac accepts whose outputs a consumer once refused: each is
//! compiled for every target, and every output goes through the consumers'
//! own checks: naga's WGSL front end reading the WGSL text back (what wgpu
//! runs), glslangValidator on each GLSL file and linked pair, spirv-val.

use crate::support;

use umbrac::{compile_source, Options};

/// Compiles `src`, then checks every output with every consumer.
fn accepted_everywhere(name: &str, src: &str) -> umbrac::Compiled {
    let c = compile_source(&format!("{name}.das"), src, &Options::default());
    let compiled = c.result.unwrap_or_else(|| panic!("{name} does not compile:\n{}", umbrac_diags(&c.diagnostics, &c.sources)));
    for a in compiled.artifacts.iter().filter(|a| a.target == Some(umbrac::Target::Wgsl)) {
        let text = a.text();
        let m = naga::front::wgsl::parse_str(&text).unwrap_or_else(|e| panic!("{name}: naga rejects the WGSL:\n{}", e.emit_to_string(&text)));
        // What wgpu grants: f16 packing everywhere, f16 with `shader-f16`.
        let mut caps = naga::valid::Capabilities::default() | naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32;
        if text.contains("enable f16;") {
            caps |= naga::valid::Capabilities::SHADER_FLOAT16;
        }
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), caps)
            .validate(&m)
            .unwrap_or_else(|e| panic!("{name}: the WGSL does not validate:\n{}", e.emit_to_string(&text)));
    }
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &compiled.artifacts);
    support::validate_dir(dir.path(), &compiled.reflection);
    compiled
}

fn umbrac_diags(d: &[umbrac::Diagnostic], map: &umbrac::SourceMap) -> String {
    d.iter().map(|d| d.render(map)).collect()
}

/// Code after a `return`, `break`, `continue` or `discard()` is checked but
/// never run. After an entry point's `return` naga's GLSL writer declared
/// `_tmp_return` twice in one scope (glslang: redefinition).
#[test]
fn code_after_a_return_is_not_emitted() {
    let src = "var @uniform u_x : float4\nvar @out f_color : float4\n\
        def helper(v : float4) : float4 {\n    return v\n    return v * 2.0\n}\n\
        [vertex_program]\ndef vs {\n    gl_Position = u_x\n    return\n    gl_Position = u_x * 2.0\n}\n\
        [fragment_program]\ndef fs {\n    f_color = helper(u_x)\n    for (i in range(4)) {\n        if (u_x.x > 0.5) {\n            break\n            f_color = u_x\n        }\n        continue\n        f_color = u_x * 3.0\n    }\n    if (u_x.y > 0.5) {\n        discard()\n        f_color = u_x\n    }\n    return\n    f_color = float4(0.5)\n    return\n}\n";
    let c = accepted_everywhere("dead_code", src);
    let fs = c.artifact("fs.330.frag").unwrap().text().into_owned();
    assert!(!fs.contains("vec4(0.5)"), "dead code was emitted:\n{fs}");
}

/// Names at the length limit, and a helper specialised for many samplers
/// with such names (its copy's name would join them all), give outputs
/// every consumer takes: GLSL allows names of 1024 characters.
#[test]
fn the_longest_names_fit_every_target() {
    let n = umbrac::syntax::MAX_IDENT_LEN;
    let long = |c: char| std::iter::repeat_n(c, n).collect::<String>();
    let (u, f) = (long('u'), long('f'));
    let samplers: Vec<String> = (0..6).map(|i| format!("{}{i}", "s".repeat(n - 1))).collect();
    let mut src = format!("var @uniform {u} : float4\nvar @out f_color : float4\nvar @inout {} : float2\n", long('v'));
    for s in &samplers {
        src.push_str(&format!("var @uniform {s} : sampler2D\n"));
    }
    let params: Vec<String> = (0..6).map(|i| format!("t{i} : sampler2D")).collect();
    let reads: Vec<String> = (0..6).map(|i| format!("texture(t{i}, uv)")).collect();
    src.push_str(&format!("def {f}({}; uv : float2) : float4 {{\n    return {}\n}}\n", params.join("; "), reads.join(" + ")));
    src.push_str(&format!("[vertex_program]\ndef vs {{\n    gl_Position = {u}\n    {} = {u}.xy\n}}\n", long('v')));
    src.push_str(&format!("[fragment_program]\ndef fs {{\n    f_color = {f}({}, {}) * {u}\n}}\n", samplers.join(", "), long('v')));
    accepted_everywhere("long_names", &src);
}

/// The WGSL/SPIR-V module holds only the globals its entry points reach,
/// like each GLSL file: 70 000 uniforms of which one is read made a SPIR-V
/// module that spirv-val refuses (at most 65 535 module-scope variables).
#[test]
fn unreached_globals_are_left_out_of_every_module() {
    let mut src: String = (0..70_000).map(|i| format!("var @uniform u{i} : float4\n")).collect();
    src.push_str("var @uniform s0 : sampler2D\nvar @uniform s1 : sampler2D\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = u69999 * texture(s1, float2(0.5))\n}\n");
    let c = accepted_everywhere("many_uniforms", &src);
    let wgsl = c.artifact("many_uniforms.wgsl").unwrap().text().into_owned();
    assert_eq!(wgsl.matches("var<uniform>").count(), 1, "{wgsl}");
    assert!(!wgsl.contains("s0"), "{wgsl}");
    let names: Vec<&str> = c.reflection.uniforms.iter().map(|u| u.name.as_str()).collect();
    assert_eq!(names, ["u69999"]);
    assert_eq!(c.reflection.uniform_buffers.len(), 1);
}

/// A program that needs more bindings than one WebGPU bind group has is a
/// located error, not a module a consumer refuses. (Loose uniforms share
/// their group's buffer: 1001 struct uniforms take a binding each.)
#[test]
fn more_bindings_than_a_bind_group_holds_is_a_located_error() {
    let n = 1000;
    let mut src: String = "struct S {\n    v : float4\n}\n".to_string();
    src.extend((0..=n).map(|i| format!("var @uniform u{i} : S\n")));
    let sum: String = (0..=n).map(|i| format!("    f_color += u{i}.v\n")).collect();
    src.push_str(&format!("var @out f_color : float4\n[fragment_program]\ndef fs {{\n{sum}}}\n"));
    let c = compile_source("bindings.das", &src, &Options::default());
    assert!(c.result.is_none());
    let text = umbrac_diags(&c.diagnostics, &c.sources);
    assert!(text.contains("no 1 free bindings left in group 0 (at most 1000)") && text.contains(&format!("bindings.das:{}:", n + 4)), "{text}");
    assert_eq!(c.diagnostics.len(), 1, "one mistake, one error:\n{text}");
}

/// The deepest programs the nesting limits accept (tests/compiler/limits.rs)
/// give outputs every consumer reads: naga's WGSL parser, glslang and
/// spirv-val have nesting limits of their own.
#[test]
fn the_deepest_accepted_programs_fit_every_consumer() {
    let fs = |body: &str| format!("var @uniform u : float\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    var a = u\n    var v = float4(u)\n{body}\n    f_color = float4(a) + v\n}}\n");
    let n = 120;
    let bodies = [
        format!("    a = {}a{}", "(".repeat(n), ")".repeat(n)),
        format!("    a = a{}", " + a".repeat(n)),
        format!("    a = {}a", "- ".repeat(n)),
        format!("    a = {}a", "a > 0.0 ? a : ".repeat(n / 2)),
        format!("    a = {}a{}", "sin(".repeat(n), ")".repeat(n)),
        format!("    v = v{}", ".wzyx".repeat(n)),
        format!("    if (a > 0.0) {{\n        a = 1.0\n    }}{}", " elif (a > 1.0) {\n        a = 2.0\n    }".repeat(n)),
        format!("{}    a = {}a{}\n{}", "if (a > 0.0) {\n".repeat(60), "(".repeat(50), ")".repeat(50), "}\n".repeat(60)),
        format!("{}    a += float(i)\n{}", "for (i in range(3)) {\n".repeat(60), "}\n".repeat(60)),
    ];
    for (i, body) in bodies.iter().enumerate() {
        accepted_everywhere(&format!("deep{i}"), &fs(body));
    }
}

/// The packing builtins of shaders/features/packing.das: naga's WGSL front
/// end (the fuzz campaign's check of every output) refused umbrac's WGSL.
#[test]
fn packing_builtins_read_back() {
    let src = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/features/packing.das")).unwrap();
    accepted_everywhere("packing", &src);
}
