//! Several programs in one file: locations and texture units are numbered
//! and checked per program, as daslang does (each program holds only the
//! globals it reaches), not across the file.

use umbrac::{Compilation, Options, Target};

fn compile(name: &str, src: &str, opts: &Options) -> Compilation {
    umbrac::compile_source(name, src, opts)
}

fn ok(c: &Compilation) -> &umbrac::Compiled {
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    c.result.as_ref().unwrap()
}

fn entry<'r>(r: &'r umbrac::Reflection, name: &str) -> &'r umbrac::emit::reflect_types::EntryPoint {
    r.entry_points.iter().find(|e| e.name == name).unwrap_or_else(|| panic!("no entry point `{name}`"))
}

/// A transform-feedback simulation (a vertex program with three `@out`s and
/// a dummy fragment program) and a separate render program, as daslang's
/// particle tutorial has them, plus a second vertex program whose only
/// attribute has a bare `@location`.
const PARTICLES: &str = "
var @in @location = 0 a_pos : float3
var @in @location = 1 a_vel : float3
var @out tf_pos : float3
var @out tf_vel : float3
var @out tf_life : float
var @uniform u_dt : float

[vertex_program]
def sim_vs {
    tf_pos = a_pos + a_vel * u_dt
    tf_vel = a_vel
    tf_life = 1.0
}

var @out f_dummy : float4

[fragment_program]
def sim_fs {
    f_dummy = float4(0.0)
}

var @uniform u_view_proj : float4x4
var @inout r_speed : float
var @out f_color : float4

[vertex_program]
def render_vs {
    gl_Position = u_view_proj * float4(a_pos, 1.0)
    r_speed = length(a_vel)
}

[fragment_program]
def render_fs {
    f_color = float4(r_speed, 0.0, 0.0, 1.0)
}

var @in @location q_pos : float2
var @inout q_uv : float2

[vertex_program]
def quad_vs {
    q_uv = q_pos * 0.5 + float2(0.5)
    gl_Position = float4(q_pos, 0.0, 1.0)
}

[fragment_program]
def quad_fs {
    f_color = float4(q_uv, 0.0, 1.0)
}
";

#[test]
fn locations_are_numbered_per_program() {
    let c = compile("particles.das", PARTICLES, &Options::default());
    let r = &ok(&c).reflection;
    let locations = |e: &str, outputs: bool| -> Vec<(String, u32)> {
        let ep = entry(r, e);
        let list = if outputs { &ep.outputs } else { &ep.inputs };
        list.iter().map(|io| (io.name.clone(), io.location)).collect()
    };
    let pairs = |v: &[(&str, u32)]| v.iter().map(|(n, l)| (n.to_string(), *l)).collect::<Vec<_>>();
    assert_eq!(locations("sim_vs", true), pairs(&[("tf_pos", 0), ("tf_vel", 1), ("tf_life", 2)]));
    // Each fragment program's only output is at location 0, where a host
    // (and WebGL2's default framebuffer) draws.
    for fs in ["sim_fs", "render_fs", "quad_fs"] {
        let outs = locations(fs, true);
        assert_eq!(outs.len(), 1, "{fs}: {outs:?}");
        assert_eq!(outs[0].1, 0, "{fs}: {outs:?}");
    }
    // A bare `@location` is numbered in the program that reads it.
    assert_eq!(locations("quad_vs", false), pairs(&[("q_pos", 0)]));
    assert_eq!(locations("render_vs", true), pairs(&[("r_speed", 0)]));
    assert_eq!(locations("render_fs", false), pairs(&[("r_speed", 0)]));
    assert_eq!(locations("quad_fs", false), pairs(&[("q_uv", 0)]));
}

#[test]
fn every_glsl_fragment_output_of_a_multi_program_file_is_at_location_0() {
    let c = compile("particles.das", PARTICLES, &Options::default());
    let compiled = ok(&c);
    let mut seen = 0;
    for a in compiled.artifacts.iter().filter(|a| a.file_name.ends_with(".frag")) {
        let text = a.text();
        let outs: Vec<&str> = text.lines().filter(|l| l.contains(" out ") || l.starts_with("out ")).collect();
        assert_eq!(outs.len(), 1, "{}: {outs:?}", a.file_name);
        assert!(outs[0].contains("location = 0") || !outs[0].contains("location"), "{}: {}", a.file_name, outs[0]);
        seen += 1;
    }
    assert_eq!(seen, 6, "three fragment programs, two GLSL profiles");
}

/// A deferred renderer: a G-buffer pass, a post pass shared by two
/// fragment programs, each starting its locations and texture units at 0.
const DEFERRED: &str = "
var @in @location = 0 a_pos : float3
var @in @location = 1 a_uv : float2
var @uniform u_mvp : float4x4
var @inout g_uv : float2
var @out @location = 0 g_albedo : float4
var @out @location = 1 g_normal : float4
var @uniform @stage = 0 albedo_tex : sampler2D

[vertex_program]
def gbuffer_vs {
    g_uv = a_uv
    gl_Position = u_mvp * float4(a_pos, 1.0)
}

[fragment_program]
def gbuffer_fs {
    g_albedo = texture(albedo_tex, g_uv)
    g_normal = float4(0.0, 0.0, 1.0, 0.0)
}

var @in @location = 0 q_pos : float2
var @inout l_uv : float2

[vertex_program]
def post_vs {
    l_uv = q_pos * 0.5 + float2(0.5)
    gl_Position = float4(q_pos, 0.0, 1.0)
}

var @uniform @stage = 0 ssao_normal : sampler2D
var @uniform @stage = 1 ssao_depth : sampler2D
var @out ssao_out : float4

[fragment_program]
def ssao_fs {
    ssao_out = texture(ssao_normal, l_uv) * texture(ssao_depth, l_uv).x
}

var @uniform @stage = 0 lit_albedo : sampler2D
var @uniform @stage = 1 lit_ssao : sampler2D
var @uniform lit_env : sampler2D
var @out frag_color : float4

[fragment_program]
def lighting_fs {
    frag_color = texture(lit_albedo, l_uv) * texture(lit_ssao, l_uv).x + texture(lit_env, l_uv)
}
";

#[test]
fn programs_may_reuse_locations_and_texture_units() {
    let c = compile("deferred.das", DEFERRED, &Options::default());
    let r = &ok(&c).reflection;
    let unit = |n: &str| r.samplers.iter().find(|s| s.name == n).unwrap_or_else(|| panic!("no sampler `{n}`")).texture_unit;
    assert_eq!((unit("albedo_tex"), unit("ssao_normal"), unit("ssao_depth"), unit("lit_albedo"), unit("lit_ssao")), (0, 0, 1, 0, 1));
    // The automatic unit is the lowest one free in every program that
    // uses the sampler (post_vs + lighting_fs holds 0 and 1).
    assert_eq!(unit("lit_env"), 2);
    assert_eq!(entry(r, "post_vs").inputs[0].location, 0);
    assert_eq!(entry(r, "gbuffer_vs").inputs[0].location, 0);
    assert_eq!(entry(r, "ssao_fs").outputs[0].location, 0);
    assert_eq!(entry(r, "lighting_fs").outputs[0].location, 0);
}

#[test]
fn one_entry_point_compiles_without_the_other_programs_checks() {
    // Two programs that collide with each other but not inside themselves;
    // with `--entry` only the requested one is compiled and checked.
    let opts = Options { entries: vec!["ssao_fs".into()], targets: vec![Target::Glsl330], ..Options::default() };
    let c = compile("deferred.das", DEFERRED, &opts);
    let compiled = ok(&c);
    assert_eq!(compiled.reflection.entry_points.len(), 1);
}

fn first_error(src: &str) -> String {
    let c = compile("conflict.das", src, &Options::default());
    assert!(c.has_errors(), "compiles:\n{src}");
    c.diagnostics.iter().find(|d| d.is_error()).map(|d| d.message.clone()).unwrap()
}

#[test]
fn conflicts_inside_one_program_are_errors() {
    // Both stages of one program sample on unit 0.
    let units = "
var @in @location = 0 a_pos : float2
var @inout v_uv : float2
var @out f_color : float4
var @uniform @stage = 0 height : sampler2D
var @uniform @stage = 0 albedo : sampler2D
[vertex_program]
def vs {
    v_uv = a_pos
    gl_Position = float4(a_pos, textureLod(height, a_pos, 0.0).x, 1.0)
}
[fragment_program]
def fs {
    f_color = texture(albedo, v_uv)
}
";
    let e = first_error(units);
    assert!(e.contains("texture unit 0") && e.contains("`vs`") && e.contains("`fs`"), "{e}");
    // Two varyings of one program at the same explicit location.
    let varyings = "
var @in @location = 0 a_pos : float2
var @inout @location = 3 v_a : float2
var @inout @location = 3 v_b : float2
var @out f_color : float4
[vertex_program]
def vs {
    v_a = a_pos
    v_b = a_pos * 2.0
    gl_Position = float4(a_pos, 0.0, 1.0)
}
[fragment_program]
def fs {
    f_color = float4(v_a, v_b)
}
";
    let e = first_error(varyings);
    assert!(e.contains("location 3") && e.contains("v_a") && e.contains("v_b"), "{e}");
}

/// A varying whose name naga gives to something of its own in one stage
/// only (`loop_init`, the gate of a `for` loop, here in the fragment
/// program; `gen_gl_Position` in every vertex program) is renamed the same
/// way in both stages: GL links varyings by name.
#[test]
fn a_varying_has_one_glsl_name_in_every_stage() {
    let src = "
var @in @location = 0 a_pos : float2
var @inout loop_init : float2
var @inout gen_gl_Position : float
var @out f_color : float4

[vertex_program]
def edge_vs {
    loop_init = a_pos * 0.5 + 0.5
    gen_gl_Position = a_pos.x
    gl_Position = float4(a_pos, 0.0, 1.0)
}

[fragment_program]
def edge_fs {
    var acc = 0.0
    for (k in range(0, 4)) {
        acc += loop_init.x * float(k)
    }
    f_color = float4(acc, loop_init.y, gen_gl_Position, 1.0)
}
";
    let c = compile("edge.das", src, &Options::default());
    let r = ok(&c);
    let (vs, fs) = (entry(&r.reflection, "edge_vs"), entry(&r.reflection, "edge_fs"));
    assert_eq!(vs.outputs.len(), 2);
    for out in &vs.outputs {
        let input = fs.inputs.iter().find(|i| i.name == out.name).unwrap();
        assert_eq!(out.glsl_name, input.glsl_name, "`{}` must have one GLSL name in both stages", out.name);
        assert_ne!(out.glsl_name, out.name, "`{}` is also a name of naga's: renamed", out.name);
        for (file, decl) in [("edge_vs.330.vert", "out"), ("edge_vs.300es.vert", "out"), ("edge_fs.330.frag", "in"), ("edge_fs.300es.frag", "in")] {
            let text = std::str::from_utf8(&r.artifact(file).unwrap().contents).unwrap();
            assert!(text.lines().any(|l| l.ends_with(&format!("{decl} {} {};", out.ty.replace("float2", "vec2"), out.glsl_name))), "{file} declares no `{decl} ... {};`:\n{text}", out.glsl_name);
        }
    }
}

/// A vertex and a fragment program linked though they share no varying
/// (each is the only one of its stage) may hold different varyings at
/// one location: the GLSL names of the two ends are compared per varying,
/// not per location (the fuzzer found this).
#[test]
fn programs_sharing_no_varying_compile() {
    let src = "
var @in @location = 0 a_pos : float3
var @inout v_wpos : float3
var @inout v_dir : float3
var @out f_color : float4

[vertex_program]
def only_vs {
    v_wpos = a_pos
    gl_Position = float4(a_pos, 1.0)
}

[fragment_program]
def only_fs {
    f_color = float4(v_dir, 1.0)
}
";
    let c = compile("apart.das", src, &Options::default());
    let r = ok(&c);
    let (vs, fs) = (entry(&r.reflection, "only_vs"), entry(&r.reflection, "only_fs"));
    assert_eq!((vs.outputs[0].glsl_name.as_str(), fs.inputs[0].glsl_name.as_str()), ("v_wpos", "v_dir"));
}
