//! The minimum limits of each target's devices (`emit::limits`): a program
//! over one is an error on that target that names the resource, the count
//! and the limit, at the declaration that goes over; one within them
//! compiles; `--limit NAME=N` (`Options::limits`) compiles for more.

use umbrac::{compile_source, Compilation, Limit, Options, Target};

fn compile(src: &str, targets: &[Target], limits: &[(Limit, u64)]) -> Compilation {
    let opts = Options { targets: targets.to_vec(), limits: limits.to_vec(), ..Options::default() };
    compile_source("limits.das", src, &opts)
}

/// The error messages of a compilation (none when it compiled).
fn errors(c: &Compilation) -> Vec<String> {
    c.diagnostics.iter().filter(|d| d.severity == umbrac::Severity::Error).map(|d| d.message.clone()).collect()
}

/// A fragment program that reads `decls`' uniforms in `body`.
fn frag(decls: &str, body: &str) -> String {
    format!("{decls}\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n    var s = 0.0\n{body}\n    f_color = float4(s)\n}}\n")
}

const ALL: &[Target] = &[Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Spirv];

fn each_target() -> impl Iterator<Item = Target> {
    ALL.iter().copied()
}

/// `n` struct uniforms, each its own block / buffer, all read.
fn struct_uniforms(n: usize) -> String {
    let decls: String = (0..n).map(|i| format!("var @uniform u_s{i} : S\n")).collect();
    let body: String = (0..n).map(|i| format!("    s += u_s{i}.v.x\n")).collect();
    frag(&format!("struct S {{\n    v : float4\n}}\n{decls}"), &body)
}

#[test]
fn many_loose_uniforms_fit_every_target() {
    // daslang's glTF tutorial has 22 loose uniforms; one buffer holds them.
    let decls: String = (0..22).map(|i| format!("var @uniform u_f{i} : float\n")).collect();
    let body: String = (0..22).map(|i| format!("    s += u_f{i}\n")).collect();
    for t in each_target() {
        let c = compile(&frag(&decls, &body), &[t], &[]);
        assert!(c.result.is_some(), "{t:?}:\n{}", c.render_diagnostics());
    }
}

#[test]
fn thirteen_uniform_blocks_are_over_the_limit_everywhere() {
    let src = struct_uniforms(13);
    for t in each_target() {
        let c = compile(&src, &[t], &[]);
        let e = errors(&c);
        let (what, limit, api) = match t {
            Target::Glsl330 | Target::Gles300 => ("13 uniform blocks", "12", "GL_MAX_FRAGMENT_UNIFORM_BLOCKS"),
            _ => ("13 uniform buffers", "12", "max_uniform_buffers_per_shader_stage"),
        };
        assert!(c.result.is_none() && e.len() == 1, "{t:?}: {e:?}");
        assert!(e[0].starts_with(&format!("fragment entry point `fs` uses {what} in ")) && e[0].contains(&format!("over the {limit} that")) && e[0].contains(api), "{t:?}: {e:?}");
        // The error points at the thirteenth, with the option that raises it.
        let d = &c.diagnostics[0];
        let span = d.span.expect("located");
        assert_eq!(&src[span.start as usize..span.end as usize], "u_s12", "{t:?}");
        let name = if matches!(t, Target::Glsl330 | Target::Gles300) { "uniform-blocks" } else { "uniform-buffers" };
        assert!(d.notes.iter().any(|n| n.contains(&format!("--limit {name}=N"))), "{t:?}: {:?}", d.notes);
        // Stated higher, it compiles.
        let raised = [(Limit::from_name(name).unwrap(), 16)];
        let c = compile(&src, &[t], &raised);
        assert!(c.result.is_some(), "{t:?} with {name}=16:\n{}", c.render_diagnostics());
    }
    assert!(compile(&struct_uniforms(12), ALL, &[]).result.is_some());
}

#[test]
fn uniform_vectors_are_counted_per_stage_against_es_fragment_minimum() {
    // 230 float4 loose uniforms: over ES 3.00's 224 fragment vectors, within
    // GL 3.3's 256; one buffer on WGSL/SPIR-V.
    let decls = "var @uniform u_big : float4[230]\nvar @uniform u_i : int";
    let src = frag(decls, "    s += u_big[u_i].x");
    let es = compile(&src, &[Target::Gles300], &[]);
    let e = errors(&es);
    assert!(e.len() == 1 && e[0].contains("uses 231 uniform vectors in GLSL ES 3.00, over the 224 that GLES 3.0 and WebGL2 guarantee (GL_MAX_FRAGMENT_UNIFORM_VECTORS)"), "{e:?}");
    for t in [Target::Glsl330, Target::Wgsl, Target::Spirv] {
        let c = compile(&src, &[t], &[]);
        assert!(c.result.is_some(), "{t:?}:\n{}", c.render_diagnostics());
    }
    // In blocks, the same uniforms count as one block, not as vectors.
    let opts = Options { targets: vec![Target::Gles300], gl_uniforms: umbrac::GlUniforms::Blocks, ..Options::default() };
    let c = compile_source("limits.das", &src, &opts);
    assert!(c.result.is_some(), "{}", c.render_diagnostics());
}

#[test]
fn attributes_varyings_textures_and_outputs() {
    // 17 vertex attributes.
    let attrs: String = (0..17).map(|i| format!("var @in a_{i}x : float\n")).collect();
    let sum: String = (0..17).map(|i| format!(" + a_{i}x")).collect();
    let vs = format!("{attrs}[vertex_program]\ndef vs {{\n    gl_Position = float4(0.0{sum})\n}}\n");
    for t in each_target() {
        let e = errors(&compile(&vs, &[t], &[]));
        assert!(e.len() == 1 && e[0].contains("uses 17 vertex attribute locations") && e[0].contains("over the 16"), "{t:?}: {e:?}");
    }
    // 17 samplers in one stage: texture units on GL, textures and samplers on wgpu.
    let decls: String = (0..17).map(|i| format!("var @uniform t{i}x : sampler2D\n")).collect();
    let body: String = (0..17).map(|i| format!("    s += texture(t{i}x, float2(0.5)).x\n")).collect();
    let src = frag(&decls, &body);
    let gl = errors(&compile(&src, &[Target::Glsl330], &[]));
    assert!(gl.len() == 1 && gl[0].contains("uses 17 texture units in GLSL 330, over the 16") && gl[0].contains("GL_MAX_TEXTURE_IMAGE_UNITS"), "{gl:?}");
    let gpu = errors(&compile(&src, &[Target::Wgsl], &[]));
    assert!(gpu.len() == 2 && gpu[0].contains("17 sampled textures") && gpu[1].contains("17 samplers"), "{gpu:?}");
    // 5 colour outputs: over ES 3.00's 4 draw buffers, within GL 3.3's 8.
    let outs: String = (0..5).map(|i| format!("var @out @location = {i} o_{i}x : float4\n")).collect();
    let writes: String = (0..5).map(|i| format!("    o_{i}x = float4(1.0)\n")).collect();
    let mrt = format!("{outs}[fragment_program]\ndef fs {{\n{writes}}}\n");
    let es = errors(&compile(&mrt, &[Target::Gles300], &[]));
    assert!(es.len() == 1 && es[0].contains("uses 5 colour outputs in GLSL ES 3.00, over the 4") && es[0].contains("GL_MAX_DRAW_BUFFERS"), "{es:?}");
    assert!(compile(&mrt, &[Target::Glsl330, Target::Wgsl], &[]).result.is_some());
}

#[test]
fn bind_groups_and_buffer_size() {
    let src = frag("var @uniform @set = 4 u_far : float", "    s += u_far");
    let e = errors(&compile(&src, &[Target::Wgsl], &[]));
    assert!(e.len() == 1 && e[0].contains("uses 5 bind groups in WGSL/SPIR-V, over the 4") && e[0].contains("max_bind_groups"), "{e:?}");
    assert!(compile(&src, &[Target::Glsl330, Target::Gles300], &[]).result.is_some(), "GL has no bind groups");
    // A loose buffer of 20 KiB: over GL's 16 KiB block only in blocks form.
    let big = frag("var @uniform u_big : float4[1280]\nvar @uniform u_i : int", "    s += u_big[u_i].x");
    let opts = Options { targets: vec![Target::Glsl330], gl_uniforms: umbrac::GlUniforms::Blocks, limits: vec![(Limit::UniformVectors, 2000)], ..Options::default() };
    let e = errors(&compile_source("limits.das", &big, &opts));
    assert!(e.len() == 1 && e[0].contains("bytes in one uniform block in GLSL 330, over the 16384"), "{e:?}");
}

#[test]
fn a_program_over_the_combined_blocks_points_at_the_block_past_the_limit() {
    // 13 blocks in the vertex stage and 12 in the fragment stage: each
    // within a stated limit of 16, together over the 24 GL guarantees.
    let vs_decls: String = (0..13).map(|i| format!("var @uniform v_s{i} : S\n")).collect();
    let fs_decls: String = (0..12).map(|i| format!("var @uniform f_s{i} : S\n")).collect();
    let vs_sum: String = (0..13).map(|i| format!(" + v_s{i}.v")).collect();
    let fs_sum: String = (0..12).map(|i| format!(" + f_s{i}.v")).collect();
    let src = format!(
        "struct S {{\n    v : float4\n}}\n{vs_decls}{fs_decls}var @inout v_c : float4\nvar @out f_color : float4\n\
         [vertex_program]\ndef vs {{\n    v_c = float4(0.0){vs_sum}\n    gl_Position = v_c\n}}\n\
         [fragment_program]\ndef fs {{\n    f_color = v_c{fs_sum}\n}}\n"
    );
    let raised = [(Limit::UniformBlocks, 16)];
    for t in [Target::Glsl330, Target::Gles300] {
        let c = compile(&src, &[t], &raised);
        let e = errors(&c);
        assert!(e.len() == 1 && e[0].starts_with("the program of `vs` and `fs` uses 25 uniform blocks in its two stages") && e[0].contains("over the 24"), "{t:?}: {e:?}");
        let span = c.diagnostics.iter().find(|d| d.severity == umbrac::Severity::Error).and_then(|d| d.span).expect("located");
        assert_eq!(&src[span.start as usize..span.end as usize], "f_s11", "{t:?}");
    }
    assert!(compile(&src, &[Target::Glsl330], &[(Limit::UniformBlocks, 16), (Limit::CombinedUniformBlocks, 25)]).result.is_some());
}

#[test]
fn a_location_past_the_limit_is_over_it_however_few_are_used() {
    // One vertex attribute, at location 16: locations 0..15 exist.
    let attribute = "var @in @location = 16 q : float4\n[vertex_program]\ndef vs { gl_Position = q }\n";
    // One colour output at location 5: GLES 3.0 has draw buffers 0..3.
    let output = "var @out @location = 5 c : float4\n[fragment_program]\ndef fs { c = float4(1.0) }\n";
    // A varying at location 20: GL matches it by name, WebGPU has 0..15.
    let varying = "var @inout @location = 20 v : float4\nvar @out f : float4\n[vertex_program]\ndef vs { v = float4(1.0); gl_Position = v }\n[fragment_program]\ndef fs { f = v }\n";
    for t in each_target() {
        let e = errors(&compile(attribute, &[t], &[]));
        assert!(e.len() == 1 && e[0].starts_with("vertex entry point `vs` uses 17 vertex attribute locations in "), "{t:?}: {e:?}");
        let e = errors(&compile(output, &[t], &[]));
        match t {
            Target::Gles300 => assert!(e.len() == 1 && e[0].starts_with("fragment entry point `fs` uses 6 colour outputs in GLSL ES 3.00"), "{t:?}: {e:?}"),
            _ => assert!(e.is_empty(), "{t:?}: {e:?}"),
        }
        let e = errors(&compile(varying, &[t], &[]));
        match t {
            Target::Wgsl | Target::Spirv => assert!(e.len() == 2 && e.iter().all(|m| m.contains("uses 21 varying vectors in WGSL/SPIR-V")), "{t:?}: {e:?}"),
            _ => assert!(e.is_empty(), "{t:?}: {e:?}"),
        }
    }
    // The note says why so few are too many; a stated limit allows it.
    let c = compile(attribute, &[Target::Glsl330], &[]);
    assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("locations count from 0: with 16, the last is 15")), "{:?}", c.diagnostics[0].notes);
    assert!(compile(attribute, &[Target::Glsl330], &[(Limit::VertexAttributes, 17)]).result.is_some());
    // The last location of each compiles everywhere.
    let last = "var @in @location = 15 q : float4\n[vertex_program]\ndef vs { gl_Position = q }\n";
    for t in each_target() {
        assert!(compile(last, &[t], &[]).result.is_some(), "{t:?}");
    }
}

/// A vertex program with a 64-joint skinning palette: 268 uniform vectors,
/// over the 256 GL 3.3 and GLES 3.0 guarantee.
const SKINNING: &str = include_str!("../support/skinning_palette.das");

fn warnings(c: &Compilation) -> Vec<&umbrac::Diagnostic> {
    c.diagnostics.iter().filter(|d| d.severity == umbrac::Severity::Warning).collect()
}

#[test]
fn a_skinning_palette_over_the_gl_guarantee_is_a_warning_unless_strict() {
    // GL 3.3 drivers in use all report at least 1024 vectors: a located
    // warning naming the guarantee, and the outputs.
    let c = compile(SKINNING, &[Target::Glsl330], &[]);
    assert!(c.result.is_some() && errors(&c).is_empty(), "{}", c.render_diagnostics());
    let w = warnings(&c);
    assert_eq!(w.len(), 1, "{}", c.render_diagnostics());
    assert!(w[0].message.starts_with("vertex entry point `skin_vs` uses 268 uniform vectors in GLSL 330, over the 256 that GL 3.3 core guarantees"), "{}", w[0].message);
    let span = w[0].span.expect("located");
    assert_eq!(&SKINNING[span.start as usize..span.end as usize], "u_view_proj", "the first uniform past 256");
    assert!(w[0].notes.iter().any(|n| n.contains("1024 components cannot run it")), "{:?}", w[0].notes);
    assert!(w[0].notes.iter().any(|n| n.contains("--strict-limits")), "{:?}", w[0].notes);
    // Strict: the same count, an error, nothing compiled.
    let strict = Options { targets: vec![Target::Glsl330], strict_limits: true, ..Options::default() };
    let c = compile_source("limits.das", SKINNING, &strict);
    let e = errors(&c);
    assert!(c.result.is_none() && e.len() == 1 && warnings(&c).is_empty(), "{}", c.render_diagnostics());
    assert!(e[0].starts_with("vertex entry point `skin_vs` uses 268 uniform vectors in GLSL 330, over the 256 that GL 3.3 core guarantees (GL_MAX_VERTEX_UNIFORM_COMPONENTS / 4)"), "{e:?}");
    assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("because of `--strict-limits`")), "{:?}", c.diagnostics[0].notes);
    // A stated limit replaces both: no warning, strict or not.
    for strict_limits in [false, true] {
        let stated = Options { targets: vec![Target::Glsl330], limits: vec![(Limit::UniformVectors, 268)], strict_limits, ..Options::default() };
        let c = compile_source("limits.das", SKINNING, &stated);
        assert!(c.result.is_some() && c.diagnostics.is_empty(), "strict {strict_limits}: {}", c.render_diagnostics());
    }
    // WGSL/SPIR-V hold the loose uniforms in a buffer: nothing to say.
    let c = compile(SKINNING, &[Target::Wgsl, Target::Spirv], &[]);
    assert!(c.result.is_some() && c.diagnostics.is_empty(), "{}", c.render_diagnostics());
}

#[test]
fn the_skinning_palette_is_refused_on_gles_where_adreno_reports_only_256() {
    // GLES 3.0 / WebGL2: Adreno GPUs report exactly the guarantee, so it
    // stays an error, with or without strict.
    for strict_limits in [false, true] {
        for targets in [vec![Target::Gles300], vec![]] {
            let opts = Options { targets: targets.clone(), strict_limits, ..Options::default() };
            let c = compile_source("limits.das", SKINNING, &opts);
            // (By default GLSL 330 is also requested: a warning there, an
            // error too when strict.)
            let e: Vec<String> = errors(&c).into_iter().filter(|m| m.contains("GLSL ES 3.00")).collect();
            assert!(c.result.is_none() && e.len() == 1, "{targets:?} strict {strict_limits}: {}", c.render_diagnostics());
            assert!(e[0].contains("uses 268 uniform vectors in GLSL ES 3.00, over the 256 that GLES 3.0 and WebGL2 guarantee (GL_MAX_VERTEX_UNIFORM_VECTORS)"), "{e:?}");
            let d = c.diagnostics.iter().find(|d| d.is_error() && d.message.contains("GLSL ES 3.00")).unwrap();
            assert!(d.notes.iter().any(|n| n.contains("Adreno")), "{:?}", d.notes);
        }
    }
    let c = compile(SKINNING, &[Target::Gles300], &[(Limit::UniformVectors, 1024)]);
    assert!(c.result.is_some() && c.diagnostics.is_empty(), "{}", c.render_diagnostics());
}

#[test]
fn over_what_gl_drivers_report_is_an_error_by_default() {
    // 1031 vectors in a vertex and in a fragment program: over the 1024
    // the GL 3.3 drivers in use report, an error at the uniform past it.
    let decls = "var @uniform u_big : float4[1030]\nvar @uniform u_i : int";
    let vs = format!("{decls}\n[vertex_program]\ndef vs {{\n    gl_Position = u_big[u_i]\n}}\n");
    let fs = frag(decls, "    s += u_big[u_i].x");
    for (src, stage) in [(vs.as_str(), "vertex entry point `vs`"), (fs.as_str(), "fragment entry point `fs`")] {
        for t in [Target::Glsl330, Target::Glsl430] {
            let c = compile(src, &[t], &[]);
            let e = errors(&c);
            let name = if t == Target::Glsl330 { "GLSL 330" } else { "GLSL 430" };
            assert!(c.result.is_none() && e.len() == 1 && warnings(&c).is_empty(), "{t:?}: {}", c.render_diagnostics());
            assert!(e[0].starts_with(&format!("{stage} uses 1031 uniform vectors in {name}, over the 1024 that GL 3.3 drivers in use report")), "{e:?}");
            let span = c.diagnostics[0].span.expect("located");
            assert_eq!(&src[span.start as usize..span.end as usize], "u_big", "{t:?}");
            assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("--limit uniform-vectors=N")), "{:?}", c.diagnostics[0].notes);
        }
        assert!(compile(src, &[Target::Glsl330], &[(Limit::UniformVectors, 1031)]).result.is_some());
    }
}

#[test]
fn hard_limits_stay_errors_without_strict() {
    // Limits some device in use has only the guarantee of: errors by
    // default, the same as strict, with no warning before them.
    let src = struct_uniforms(13);
    for strict_limits in [false, true] {
        for t in each_target() {
            let opts = Options { targets: vec![t], strict_limits, ..Options::default() };
            let c = compile_source("limits.das", &src, &opts);
            assert!(c.result.is_none() && errors(&c).len() == 1 && warnings(&c).is_empty(), "{t:?}: {}", c.render_diagnostics());
        }
    }
    // WebGPU's defaults are what a default device enforces: the note says
    // the host must ask for more.
    let c = compile(&src, &[Target::Wgsl], &[]);
    assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("`required_limits`")), "{:?}", c.diagnostics[0].notes);
}

#[test]
fn the_manifest_lists_the_webgpu_limits_a_stated_program_needs() {
    // 13 uniform buffers: WebGPU's default device has 12. Stated, it
    // compiles, and the manifest says what the host must request.
    let src = struct_uniforms(13);
    let c = compile(&src, &[Target::Wgsl, Target::Spirv], &[(Limit::UniformBuffers, 16)]);
    let r = &c.result.as_ref().expect("compiles for the stated limit").reflection;
    let needs = r.required_limits.as_ref().expect("required_limits");
    assert_eq!(needs.iter().map(|(k, v)| (k.as_str(), *v)).collect::<Vec<_>>(), [("maxUniformBuffersPerShaderStage", 13)]);
    let json = c.result.as_ref().unwrap().artifact("limits.reflect.json").unwrap().text().into_owned();
    assert!(json.contains("\"required_limits\": {\n    \"maxUniformBuffersPerShaderStage\": 13\n  }"), "{json}");
    // Within the defaults, or with no WebGPU target, the field is left out.
    for (src, targets) in [(struct_uniforms(12), &[Target::Wgsl][..]), (src.clone(), &[Target::Glsl330][..])] {
        let limits = [(Limit::UniformBlocks, 16)];
        let c = compile(&src, targets, &limits);
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
        assert!(compiled.reflection.required_limits.is_none(), "{targets:?}");
        assert!(!compiled.artifact("limits.reflect.json").unwrap().text().contains("required_limits"), "{targets:?}");
    }
}

#[test]
fn strict_limits_are_part_of_the_cache_key() {
    let d = tempfile::tempdir().unwrap();
    let path = d.path().join("skin.das");
    std::fs::write(&path, SKINNING).unwrap();
    let pre = umbrac::preprocess_file(&path, &Options::default());
    let plain = umbrac::cache::Key::of(&pre, &Options::default(), "");
    let strict = umbrac::cache::Key::of(&pre, &Options { strict_limits: true, ..Options::default() }, "");
    assert!(plain != strict, "a strict compile must not be served a lenient one's outputs");
}
