//! Programs umbrac accepts whose outputs a consumer once refused: each is
//! compiled for every target, and every output goes through the consumers'
//! own checks: naga's WGSL front end reading the WGSL text back (what wgpu
//! runs), glslangValidator on each GLSL file and linked pair, spirv-val,
//! tint (what Chrome runs).

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
        // A unary operator is two levels (tint: `-(` counts twice).
        format!("    a = {}a", "- ".repeat(n / 2)),
        format!("    a = {}a", "-sin(".repeat(n / 3)) + &")".repeat(n / 3),
        format!("    a = {}a", "a > 0.0 ? a : ".repeat(n / 2)),
        format!("    a = {}a{}", "sin(".repeat(n), ")".repeat(n)),
        format!("    v = v{}", ".wzyx".repeat(n)),
        // WGSL allows 127 levels of statements; an `elif` is two.
        format!("    if (a > 0.0) {{\n        a = 1.0\n    }}{}", " elif (a > 1.0) {\n        a = 2.0\n    }".repeat(61)),
        format!("{}    a += 1.0\n{}", "if (a > 0.0) {\n".repeat(62), "}\n".repeat(62)),
        format!("{}    a += 1.0\n{}", "while (a < 0.0) {\n".repeat(61), "}\n".repeat(61)),
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

/// Loose uniforms whose names naga's GLSL namer changes (a final `_`, a
/// double `_`, a name an input holder or a stand-in already has, one
/// starting as naga's own) were "cannot find the declaration of uniform"
/// internal errors. Each gets one GLSL name in both stages, the one the
/// manifest records, and both files declare it.
#[test]
fn uniforms_naga_would_rename_get_one_name_in_every_stage() {
    for name in ["a_", "x_", "__x", "fs_out", "vs_out", "in_a", "out_f_color", "gen_gl_Position", "u1", "_group_q", "const_k", "input"] {
        let src = format!(
            "var @uniform {name} : float4\nvar @in a : float4\nvar @out f_color : float4\n[vertex_program]\ndef vs {{\n    gl_Position = a * {name}\n}}\n[fragment_program]\ndef fs {{\n    f_color = {name}\n}}\n"
        );
        let c = accepted_everywhere("renamed", &src);
        let u = c.reflection.uniforms.iter().find(|u| u.name == name).unwrap_or_else(|| panic!("{name} is not in the manifest"));
        let glsl = u.glsl_name.as_deref().unwrap_or_else(|| panic!("{name} has no GLSL name"));
        for file in ["vs.330.vert", "fs.330.frag", "vs.300es.vert", "fs.300es.frag"] {
            let text = c.artifact(file).unwrap().text().into_owned();
            assert!(text.contains(&format!("uniform vec4 {glsl};")), "{name}: {file} does not declare `{glsl}`:\n{text}");
        }
    }
}

/// A stage input or output named as naga's GLSL writer names its own
/// globals (`_group_0_binding_1_fs`) made the search for a free GLSL name
/// run forever, whatever the targets.
#[test]
fn varyings_named_as_naga_names_its_own_end() {
    for name in ["_group_x", "_group_0_binding_0_vs", "const_v", "_immediates_binding_v"] {
        let src = format!(
            "var @in {name} : float4\nvar @inout v_{name} : float4\nvar @out f_color : float4\n[vertex_program]\ndef vs {{\n    gl_Position = {name}\n    v_{name} = {name}\n}}\n[fragment_program]\ndef fs {{\n    f_color = v_{name}\n}}\n"
        );
        accepted_everywhere("group_names", &src);
    }
}

/// The GLSL name of a stage input or output was chosen against naga's
/// names only, from initials the caller listed: it could be a name the
/// fix-ups after naga give (a uniform block `light_ubo`: a debug
/// assertion, an invalid shader in a release build), or the name chosen
/// for another input or output (`input` and `input_` both `input_`; a
/// Vulkan-dialect attribute `vk_location1` and the varying at location 1
/// both `vk_location1`): glslang, "redefinition". The name picker now
/// gathers every such name itself.
#[test]
fn varyings_keep_off_every_name_the_gl_text_holds() {
    let block = "struct Light {\n    dir : float3\n}\nvar @uniform light : Light\nvar @in a_pos : float3\nvar @inout light_ubo : float3\nvar @out f_color : float4\n\
        [vertex_program]\ndef vs {\n    light_ubo = a_pos\n    gl_Position = float4(a_pos, 1.0)\n}\n\
        [fragment_program]\ndef fs {\n    f_color = float4(light_ubo * light.dir, 1.0)\n}\n";
    let underscored = "var @in a_pos : float3\nvar @inout input : float3\nvar @inout input_ : float3\nvar @out f_color : float4\n\
        [vertex_program]\ndef vs {\n    input = a_pos\n    input_ = a_pos * 2.0\n    gl_Position = float4(a_pos, 1.0)\n}\n\
        [fragment_program]\ndef fs {\n    f_color = float4(input + input_, 1.0)\n}\n";
    let located = "var @in @location = 1 vk_location1 : float2\nvar @out @location = 1 n_out : float2\n\
        [vertex_shader]\ndef vs {\n    n_out = vk_location1\n    gl_Position = float4(vk_location1, 0.0, 1.0)\n}\n\
        var @in @location = 1 f_n : float2\nvar @out @location = 0 o_color : float4\n\
        [fragment_shader]\ndef fs {\n    o_color = float4(f_n, 0.0, 1.0)\n}\n";
    for (name, src, want) in [("block", block, &["a_pos", "light_ubo_"][..]), ("underscored", underscored, &["a_pos", "input_", "input_1"]), ("located", located, &["vk_location1_", "vk_location1"])] {
        let c = accepted_everywhere(name, src);
        let vs = c.reflection.entry_points.iter().find(|e| e.name == "vs").unwrap();
        let names: Vec<&str> = vs.inputs.iter().chain(&vs.outputs).map(|io| io.glsl_name.as_str()).collect();
        // Apart from each other and from the block, as the rule names them.
        let blocks: Vec<&str> = c.reflection.uniform_buffers.iter().filter_map(|u| u.glsl_block.as_deref()).collect();
        for (i, n) in names.iter().enumerate() {
            assert!(!names[..i].contains(n) && !blocks.contains(n), "{name}: `{n}` twice in {names:?} / {blocks:?}");
        }
        assert_eq!(names, want, "{name}");
    }
}

/// GLSL ES reserves every identifier holding `__`, and WebGL2 (ANGLE)
/// refuses a shader with one ("identifiers containing two consecutive
/// underscores are reserved"), though glslang only warns. The name picker
/// made `input__` for a varying `input_` beside `input`, and a source name
/// holding `__` (a uniform, a varying) was written as it is. No GL output
/// may hold one; the manifest gives the names the GL host binds by.
#[test]
fn no_gl_name_holds_a_double_underscore() {
    let src = "var @uniform my__u : float\nvar @in a__pos : float3\nvar @inout input : float3\nvar @inout input_ : float3\nvar @inout v__n : float3\nvar @out f_color : float4\n\
        [vertex_program]\ndef vs {\n    input = a__pos\n    input_ = a__pos * my__u\n    v__n = a__pos\n    gl_Position = float4(a__pos, 1.0)\n}\n\
        [fragment_program]\ndef fs {\n    f_color = float4(input + input_ + v__n * my__u, 1.0)\n}\n";
    let c = accepted_everywhere("double_underscore", src);
    for a in c.artifacts.iter().filter(|a| a.target.is_some_and(|t| t.is_glsl())) {
        assert!(!a.text().contains("__"), "{} holds `__`:\n{}", a.file_name, a.text());
    }
    let vs = c.reflection.entry_points.iter().find(|e| e.name == "vs").unwrap();
    let names: Vec<&str> = vs.inputs.iter().chain(&vs.outputs).map(|io| io.glsl_name.as_str()).collect();
    assert_eq!(names, ["a_pos", "input_", "input_1", "v_n"]);
    let json = String::from_utf8(c.artifacts.iter().find(|a| a.target.is_none()).unwrap().contents.clone()).unwrap();
    assert!(json.contains("\"glsl_name\": \"my_u\""), "the manifest names the uniform's GL name:\n{json}");
}

/// A vertex and a compute entry point without a fragment one were linked
/// as a program ("does not link a vertex and a fragment entry point"): a
/// compute entry point is a program alone, next to any vertex/fragment.
#[test]
fn compute_entry_points_are_never_linked_with_a_vertex_one() {
    let vc = "var @in a : float4\n[vertex_program]\ndef vs {\n    gl_Position = a\n}\n[compute_program(local_size_x = 1)]\ndef cs {\n    let x = 1\n}\n";
    let c = accepted_everywhere("vertex_compute", vc);
    assert!(c.reflection.programs.is_empty(), "{:?}", c.reflection.programs.len());
    let vfc = "var @in a : float4\nvar @out f_color : float4\n[vertex_program]\ndef vs {\n    gl_Position = a\n}\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n[compute_program(local_size_x = 1)]\ndef cs {\n    let x = 1\n}\n";
    let c = accepted_everywhere("vertex_fragment_compute", vfc);
    let pairs: Vec<(&str, &str)> = c.reflection.programs.iter().map(|p| (p.vertex.as_str(), p.fragment.as_str())).collect();
    assert_eq!(pairs, [("vs", "fs")]);
}

/// FLT_MAX, which naga writes as a decimal above FLT_MAX (tint: "cannot be
/// represented as 'f32'"), and the largest finite values near it.
#[test]
fn the_largest_floats_are_written_within_range() {
    let src = "var @uniform u : float\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(u * 3.4028235e38, u * -3.4028235e38, u * 3.4028233e38, min(u, 340282346638528859811704183484516925440.0))\n}\n";
    let c = accepted_everywhere("flt_max", src);
    let wgsl = c.artifact("flt_max.wgsl").unwrap().text().into_owned();
    assert!(wgsl.contains("0x1.fffffep+127f"), "{wgsl}");
}

/// naga's WGSL writer renamed entry points (`vs1` to `vs1_`, `x__y` to
/// `x_y`, `p_` to `p`) while the SPIR-V, the GLSL file names and the
/// manifest kept the source name: a WebGPU host asking for the manifest's
/// name found nothing. Every output now names them as the source does.
#[test]
fn entry_points_keep_their_names_in_every_output() {
    let src = "var @in a : float4\nvar @out f_color : float4\n[vertex_program]\ndef vs1 {\n    gl_Position = a\n}\n[fragment_program]\ndef x__y {\n    f_color = float4(1.0)\n}\n[fragment_program]\ndef p_ {\n    f_color = float4(0.5)\n}\n";
    let c = accepted_everywhere("entry_names", src);
    let wgsl = c.artifact("entry_names.wgsl").unwrap().text().into_owned();
    let spv = &c.artifact("entry_names.spv").unwrap().contents;
    let words: Vec<u32> = spv.chunks_exact(4).map(|b| u32::from_le_bytes(b.try_into().unwrap())).collect();
    // OpEntryPoint (15): model, id, then the name, NUL-terminated.
    let mut spv_names = Vec::new();
    let mut at = 5;
    while at < words.len() {
        let (count, op) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        if op == 15 {
            let bytes: Vec<u8> = words[at + 3..at + count].iter().flat_map(|w| w.to_le_bytes()).collect();
            spv_names.push(String::from_utf8_lossy(&bytes[..bytes.iter().position(|&b| b == 0).unwrap()]).into_owned());
        }
        at += count.max(1);
    }
    let from_wgsl = naga::front::wgsl::parse_str(&wgsl).unwrap();
    for ep in &c.reflection.entry_points {
        assert!(from_wgsl.entry_points.iter().any(|e| e.name == ep.name), "the WGSL has no entry point `{}`:\n{wgsl}", ep.name);
        assert!(spv_names.contains(&ep.name), "the SPIR-V has no entry point `{}`: {spv_names:?}", ep.name);
    }
    assert_eq!(c.reflection.entry_points.len(), 3);
}

/// The longest array (tint refuses a count of 65536: "must be less than
/// 65536") and 255 parameters, WGSL's and SPIR-V's most, in every output.
#[test]
fn the_longest_array_and_the_most_parameters_fit_every_target() {
    let max = umbrac::sema::MAX_ARRAY_LEN;
    let src = format!("var @uniform u : float\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    var t : float[{max}]\n    t[3] = u\n    f_color = float4(t[3])\n}}\n");
    accepted_everywhere("long_array", &src);
    let params: Vec<String> = (0..255).map(|i| format!("p{i} : float")).collect();
    let args: Vec<String> = (0..255).map(|i| format!("u * {i}.0")).collect();
    let src = format!("var @uniform u : float\nvar @out f_color : float4\ndef h({}) : float {{\n    return p0 + p254\n}}\n[fragment_program]\ndef fs {{\n    f_color = float4(h({}))\n}}\n", params.join("; "), args.join(", "));
    accepted_everywhere("many_params", &src);
}

/// `discard()` then `return v` in a helper: the return was dropped as
/// dead code, and glslang and tint refuse a function that does not return
/// a value (WGSL's `discard` does not end the invocation). A helper whose
/// paths all end in `discard()` returns a zero value. Locals named as
/// naga's own (`_tmp_return`: glslang saw a redefinition) are renamed.
#[test]
fn helpers_that_discard_still_return_and_locals_keep_clear_of_naga_names() {
    let src = "var @uniform u : float\nvar @out f_color : float4\n\
        def g(x : float) : float {\n    if (x > 0.0) {\n        discard()\n        return x\n    } else {\n        discard()\n    }\n}\n\
        def k(x : float) : float {\n    discard()\n}\n\
        def h(_tmp_return : float) : float {\n    let _e1 = _tmp_return * 2.0\n    var const_float = _e1\n    return const_float\n}\n\
        [vertex_program]\ndef vs {\n    var _tmp_return = float4(u)\n    gl_Position = _tmp_return\n    return\n}\n\
        [fragment_program]\ndef fs {\n    var _tmp_return = float4(g(u) + k(u) + h(u))\n    f_color = _tmp_return\n    return\n}\n";
    let c = accepted_everywhere("discarding", src);
    let wgsl = c.artifact("discarding.wgsl").unwrap().text().into_owned();
    assert!(wgsl.contains("return x"), "the `return` after `discard()` was dropped:\n{wgsl}");
}

/// The largest constant index into a run-time-sized array, `int`'s; one
/// above (2^31) was written, and glslang ("index out of range") and tint
/// (not an `i32`) refused it (tests/bad_inputs/sema_runtime_index_too_large.das).
#[test]
fn the_largest_constant_index_into_a_runtime_array_fits() {
    let src = "struct Values {\n    count : uint\n    data : uint[]\n}\nvar @ssbo output : Values\n[compute_program(local_size_x = 1)]\ndef cs {\n    output.data[2147483647] = 1u\n    output.data[int(2147483647u)] = 2u\n}\n";
    accepted_everywhere("runtime_index", src);
}

/// `half` used only inside expressions (a conversion) gave WGSL without
/// `enable f16` and SPIR-V with 16-bit capabilities but no extension: tint,
/// naga and spirv-val refused them. `half(65504.0)`, its largest value, fits.
#[test]
fn half_used_only_in_expressions_is_announced() {
    let src = "var @uniform u : float\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(u) * float4(float(half(u) * half(2.0)), float(half(65504.0)), 1.0, 1.0)\n}\n";
    let c = compile_source("half_expr.das", src, &Options { targets: vec![umbrac::Target::Wgsl, umbrac::Target::Spirv], ..Options::default() });
    let compiled = c.result.unwrap_or_else(|| panic!("does not compile:\n{}", umbrac_diags(&c.diagnostics, &c.sources)));
    assert!(compiled.artifact("half_expr.wgsl").unwrap().text().contains("enable f16;"));
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &compiled.artifacts);
    support::validate_dir(dir.path(), &compiled.reflection);
}
