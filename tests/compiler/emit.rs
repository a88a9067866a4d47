//! Emitter tests on naga modules built from WGSL shaped like the lowering's
//! output (see tests/support).

use crate::support;

use support::fake_lowered;
use umbrac::{emit, Artifact, Severity, Target};

/// The shadow scene in GL conventions: every `@uniform` its own global, the
/// shadow sampler a depth texture plus a comparison sampler, a PCF loop that
/// samples in non-uniform control flow (allowed by the diagnostic filter).
const SHADOW: &str = r#"
diagnostic(off, derivative_uniformity);

@group(0) @binding(0) var<uniform> u_light_vp: mat4x4<f32>;
@group(0) @binding(1) var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(2) var<uniform> u_view: mat4x4<f32>;
@group(0) @binding(3) var<uniform> u_proj: mat4x4<f32>;
@group(0) @binding(4) var<uniform> u_light_dir: vec3<f32>;
@group(0) @binding(5) var<uniform> u_cam_pos: vec3<f32>;
@group(0) @binding(6) var<uniform> u_is_floor: f32;
@group(0) @binding(7) var shadow_map: texture_depth_2d;
@group(0) @binding(8) var shadow_map_sampler: sampler_comparison;

const SHADOW_MAP_SIZE: f32 = 1024.0;
const PCF_RADIUS: i32 = 1;

struct shadow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

@vertex
fn shadow_vs(@location(0) in_a_pos: vec3<f32>) -> shadow_vs_out {
    var out: shadow_vs_out;
    out.gl_Position = u_light_vp * (u_model * vec4<f32>(in_a_pos, 1.0));
    return out;
}

struct shadow_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

@fragment
fn shadow_fs() -> shadow_fs_out {
    var out: shadow_fs_out;
    out.f_FragColor = vec4<f32>(1.0);
    return out;
}

struct main_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world_pos: vec3<f32>,
    @location(1) v_world_normal: vec3<f32>,
    @location(2) v_light_space: vec4<f32>,
}

@vertex
fn main_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> main_vs_out {
    var out: main_vs_out;
    let world = u_model * vec4<f32>(in_a_pos, 1.0);
    out.v_world_pos = world.xyz;
    out.v_world_normal = (u_model * vec4<f32>(in_a_normal, 0.0)).xyz;
    out.v_light_space = u_light_vp * world;
    out.gl_Position = u_proj * (u_view * world);
    return out;
}

fn sun_visibility(uv: vec2<f32>, depth: f32) -> f32 {
    let step = 1.0 / SHADOW_MAP_SIZE;
    var lit = 0.0;
    var taps = 0.0;
    for (var y = -PCF_RADIUS; y < PCF_RADIUS + 1; y++) {
        for (var x = -PCF_RADIUS; x < PCF_RADIUS + 1; x++) {
            lit += textureSampleCompare(shadow_map, shadow_map_sampler, uv + vec2<f32>(f32(x), f32(y)) * step, depth);
            taps += 1.0;
        }
    }
    return lit / taps;
}

struct main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

@fragment
fn main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>, @location(2) in_v_light_space: vec4<f32>) -> main_fs_out {
    var out: main_fs_out;
    let n = normalize(in_v_world_normal);
    let l = normalize(u_light_dir);
    let v = normalize(u_cam_pos - in_v_world_pos);
    let ndotl = max(dot(n, l), 0.0);
    var albedo = vec3<f32>(0.7, 0.6, 0.5);
    if (u_is_floor > 0.5) {
        albedo = vec3<f32>(0.8, 0.82, 0.88);
    }
    var sun = 0.0;
    if (ndotl > 0.0) {
        let p = in_v_light_space.xyz / in_v_light_space.w * 0.5 + 0.5;
        sun = sun_visibility(p.xy, p.z - 0.002);
    }
    let h = normalize(l + v);
    let spec = pow(max(dot(n, h), 0.0), 32.0) * sun;
    out.f_FragColor = vec4<f32>(albedo * (0.2 + 0.8 * ndotl * sun) + vec3<f32>(spec), 1.0);
    return out;
}
"#;

fn find<'a>(arts: &'a [Artifact], name: &str) -> &'a Artifact {
    arts.iter().find(|a| a.file_name == name).unwrap_or_else(|| panic!("no artifact {name}; have {:?}", arts.iter().map(|a| &a.file_name).collect::<Vec<_>>()))
}

fn text(arts: &[Artifact], name: &str) -> String {
    find(arts, name).text().into_owned()
}

fn emit_all(src: &str) -> (Vec<Artifact>, umbrac::Reflection) {
    let lowered = fake_lowered(src);
    emit::emit(&lowered, "shadow", "shadow.das", &[]).unwrap_or_else(|d| panic!("emit failed: {d:?}"))
}

#[test]
fn emits_every_file() {
    let (arts, _) = emit_all(SHADOW);
    let mut names: Vec<_> = arts.iter().map(|a| a.file_name.as_str()).collect();
    names.sort();
    assert_eq!(
        names,
        [
            "main_fs.300es.frag",
            "main_fs.330.frag",
            "main_vs.300es.vert",
            "main_vs.330.vert",
            "shadow.reflect.json",
            "shadow.spv",
            "shadow.wgsl",
            "shadow_fs.300es.frag",
            "shadow_fs.330.frag",
            "shadow_vs.300es.vert",
            "shadow_vs.330.vert",
        ]
    );
    let spv = &find(&arts, "shadow.spv").contents;
    assert_eq!(spv.len() % 4, 0);
    assert_eq!(&spv[..4], &0x0723_0203u32.to_le_bytes(), "SPIR-V magic, little-endian");
    let json = text(&arts, "shadow.reflect.json");
    assert!(json.ends_with("}\n"));
}

#[test]
fn only_requested_targets() {
    let lowered = fake_lowered(SHADOW);
    let (arts, refl) = emit::emit(&lowered, "shadow", "shadow.das", &[Target::Wgsl]).unwrap();
    let names: Vec<_> = arts.iter().map(|a| a.file_name.as_str()).collect();
    assert_eq!(names, ["shadow.wgsl", "shadow.reflect.json"]);
    // GLSL names are still in the manifest for hosts that compile later.
    assert_eq!(refl.uniform_buffers[0].glsl_block.as_deref(), Some("u_light_vp_ubo"));
    assert_eq!(refl.entry_points[0].files.keys().collect::<Vec<_>>(), ["wgsl"]);
}

#[test]
fn es_precision_preamble() {
    let (arts, _) = emit_all(SHADOW);
    let fs = text(&arts, "main_fs.300es.frag");
    assert!(fs.starts_with("#version 300 es\n"), "{fs}");
    assert!(
        fs.contains("precision highp float;\nprecision highp int;\nprecision highp sampler2DShadow;\n"),
        "the sampler2DShadow precision must follow naga's precision lines:\n{fs}"
    );
    assert!(fs.contains("uniform highp sampler2DShadow shadow_map;"), "{fs}");
    // Stages without such samplers get no extra lines.
    let vs = text(&arts, "main_vs.300es.vert");
    assert!(!vs.contains("sampler2DShadow"), "{vs}");
    // Desktop GLSL has no precision statements at all.
    assert!(!text(&arts, "main_fs.330.frag").contains("precision"));
}

#[test]
fn shadow_vs_declares_only_what_it_uses() {
    let (arts, refl) = emit_all(SHADOW);
    let vs = text(&arts, "shadow_vs.330.vert");
    assert!(vs.starts_with("#version 330 core\n"), "{vs}");
    let uniforms: Vec<&str> = vs.lines().filter(|l| l.contains("uniform")).collect();
    assert_eq!(
        uniforms,
        ["layout(std140) uniform u_light_vp_ubo { mat4x4 u_light_vp; };", "layout(std140) uniform u_model_ubo { mat4x4 u_model; };"],
        "{vs}"
    );
    let ins: Vec<&str> = vs.lines().filter(|l| l.contains(" in ")).collect();
    assert_eq!(ins, ["layout(location = 0) in vec3 a_pos;"], "{vs}");
    for other in ["u_view", "u_proj", "u_light_dir", "u_cam_pos", "u_is_floor", "shadow_map", "a_normal", "main_vs_out", "sun_visibility"] {
        assert!(!vs.contains(other), "{other} in shadow_vs:\n{vs}");
    }
    // No y flip or z rewrite in GL outputs.
    assert!(!vs.contains("gl_Position.yz"), "{vs}");
    let ep = refl.entry_points.iter().find(|e| e.name == "shadow_vs").unwrap();
    assert_eq!(ep.uniform_buffers, ["u_light_vp", "u_model"]);
    assert!(ep.samplers.is_empty());
    assert_eq!(ep.inputs.len(), 1);
    assert_eq!(ep.inputs[0].vertex_format.as_deref(), Some("Float32x3"));
    assert_eq!(ep.inputs[0].size, 12);
    assert_eq!((ep.inputs[0].glsl_name.as_str(), ep.inputs[0].glsl_location), ("a_pos", Some(0)));
    assert_eq!(ep.builtins, ["gl_Position"]);
}

/// Every name the manifest gives a GL host is in the GLSL it points at, and
/// no naga-generated block name is left.
#[test]
fn glsl_names_match_manifest() {
    let (arts, refl) = emit_all(SHADOW);
    for ep in &refl.entry_points {
        for target in ["glsl330", "gles300"] {
            let src = text(&arts, &ep.files[target]);
            assert!(!src.contains("_block_0") && !src.contains("Vertex") && !src.contains("Fragment"), "{src}");
            for b in &ep.uniform_buffers {
                let block = refl.uniform_buffers.iter().find(|u| &u.name == b).unwrap();
                assert!(src.contains(&format!("uniform {} {{", block.glsl_block.as_deref().unwrap())), "{} not in {}:\n{src}", block.glsl_block.as_deref().unwrap(), ep.files[target]);
            }
            for s in &ep.samplers {
                let sampler = refl.samplers.iter().find(|u| &u.name == s).unwrap();
                assert!(src.contains(&format!(" {};", sampler.glsl_name)), "{src}");
            }
            for io in ep.inputs.iter() {
                assert!(src.contains(&format!("in {} {};", glsl_type(&io.ty), io.glsl_name)), "{} in {}:\n{src}", io.glsl_name, ep.files[target]);
            }
            for io in ep.outputs.iter() {
                assert!(src.contains(&format!("out {} {};", glsl_type(&io.ty), io.glsl_name)), "{} in {}:\n{src}", io.glsl_name, ep.files[target]);
            }
        }
    }
    let main_vs = refl.entry_points.iter().find(|e| e.name == "main_vs").unwrap();
    let main_fs = refl.entry_points.iter().find(|e| e.name == "main_fs").unwrap();
    // Varyings link by name between the stages.
    for (o, i) in main_vs.outputs.iter().zip(&main_fs.inputs) {
        assert_eq!(o.glsl_name, i.glsl_name);
        assert_eq!(o.interpolation.as_deref(), Some("perspective"));
    }
    assert_eq!((main_vs.outputs[0].glsl_name.as_str(), main_vs.outputs[0].glsl_location), ("v_world_pos", None));
    assert_eq!((main_fs.outputs[0].glsl_name.as_str(), main_fs.outputs[0].glsl_location), ("f_FragColor", Some(0)));
    assert_eq!(main_fs.outputs[0].interpolation, None);
}

fn glsl_type(dsl: &str) -> String {
    match dsl {
        "float" => "float".into(),
        d if d.starts_with("float") => format!("vec{}", &d[5..]),
        d => d.into(),
    }
}

#[test]
fn block_names_identical_across_stages() {
    let (arts, _) = emit_all(SHADOW);
    let vs = text(&arts, "main_vs.330.vert");
    let fs = text(&arts, "main_fs.330.frag");
    let shadow = text(&arts, "shadow_vs.300es.vert");
    for v in [&vs, &shadow] {
        assert!(v.contains("uniform u_model_ubo { mat4x4 u_model; };") || v.contains("uniform u_model_ubo { highp mat4x4 u_model; };"), "{v}");
    }
    assert!(vs.contains("uniform u_light_vp_ubo {"), "{vs}");
    assert!(fs.contains("uniform u_light_dir_ubo {"), "{fs}");
    assert!(fs.contains("uniform u_is_floor_ubo {"), "{fs}");
    assert!(fs.contains("uniform sampler2DShadow shadow_map;"), "{fs}");
}

#[test]
fn sampler_reflection() {
    let (_, refl) = emit_all(SHADOW);
    assert_eq!(refl.samplers.len(), 1);
    let s = &refl.samplers[0];
    assert_eq!((s.name.as_str(), s.glsl_name.as_str(), s.ty.as_str()), ("shadow_map", "shadow_map", "sampler2DShadow"));
    assert_eq!((s.texture_unit, s.group, s.texture_binding, s.sampler_binding), (0, 0, 7, 8));
    assert_eq!((s.dimension.as_str(), s.sample_type.as_str(), s.comparison), ("2d", "depth", true));
    let fs = refl.entry_points.iter().find(|e| e.name == "main_fs").unwrap();
    assert_eq!(fs.samplers, ["shadow_map"]);
    assert_eq!(fs.uniform_buffers, ["u_light_dir", "u_cam_pos", "u_is_floor"]);
}

#[test]
fn loose_uniform_layouts() {
    let (_, refl) = emit_all(SHADOW);
    let get = |n: &str| refl.uniform_buffers.iter().find(|b| b.name == n).unwrap();
    let m = get("u_model");
    assert_eq!((m.size, m.binding, m.ty.as_str(), m.glsl_block.as_deref().unwrap()), (64, 1, "float4x4", "u_model_ubo"));
    assert_eq!(m.members.len(), 1);
    assert_eq!((m.members[0].name.as_str(), m.members[0].offset, m.members[0].size, m.members[0].matrix_stride), ("u_model", 0, 64, Some(16)));
    let d = get("u_light_dir");
    assert_eq!((d.size, d.members[0].size, d.ty.as_str()), (16, 12, "float3"));
    let f = get("u_is_floor");
    assert_eq!((f.size, f.members[0].size, f.ty.as_str()), (16, 4, "float"));
}

const PACKED: &str = r#"
struct Light {
    dir: vec3<f32>,
    intensity: f32,
    color: vec3<f32>,
    weights: array<vec4<f32>, 3>,
    m: mat3x3<f32>,
    last: f32,
}
@group(0) @binding(0) var<uniform> u_light: Light;
@group(0) @binding(1) var tex: texture_2d<f32>;
@group(0) @binding(2) var tex_sampler: sampler;
@group(0) @binding(3) var arr: texture_depth_2d_array;
@group(0) @binding(4) var arr_sampler: sampler_comparison;
@group(0) @binding(5) var itex: texture_2d<i32>;
@group(0) @binding(6) var itex_sampler: sampler;

struct vs_out { @builtin(position) pos: vec4<f32>, @location(0) @interpolate(flat) id: i32, @location(1) uv: vec2<f32> }

@vertex
fn light_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_id: i32) -> vs_out {
    return vs_out(vec4<f32>(in_a_pos * u_light.intensity, 1.0), in_a_id, in_a_pos.xy);
}

@fragment
fn light_fs(@location(0) @interpolate(flat) in_id: i32, @location(1) in_uv: vec2<f32>) -> @location(0) vec4<f32> {
    let c = textureSample(tex, tex_sampler, in_uv);
    let d = textureSampleCompareLevel(arr, arr_sampler, in_uv, in_id, 0.5);
    let i = textureLoad(itex, vec2<i32>(in_uv * 4.0), 0);
    return vec4<f32>(u_light.color * u_light.weights[in_id].x * d + u_light.m[0] * u_light.last, c.a + f32(i.x));
}
"#;

#[test]
fn struct_uniform_vec3_float_packing() {
    let (arts, refl) = emit_all(PACKED);
    let b = &refl.uniform_buffers[0];
    assert_eq!((b.name.as_str(), b.ty.as_str(), b.glsl_block.as_deref().unwrap()), ("u_light", "Light", "u_light_ubo"));
    let offs: Vec<(&str, u32, u32)> = b.members.iter().map(|m| (m.name.as_str(), m.offset, m.size)).collect();
    // vec3 + float share one 16-byte slot; the next vec3 starts a new one.
    assert_eq!(offs, [("dir", 0, 12), ("intensity", 12, 4), ("color", 16, 12), ("weights", 32, 48), ("m", 80, 48), ("last", 128, 4)]);
    assert_eq!(b.members[3].array_stride, Some(16));
    assert_eq!(b.members[4].matrix_stride, Some(16));
    assert_eq!(b.size, 144);
    let fs = text(&arts, "light_fs.300es.frag");
    assert!(fs.contains("precision highp int;\nprecision highp sampler2DArrayShadow;\nprecision highp isampler2D;\n"), "{fs}");
    assert!(fs.contains("uniform u_light_ubo {"), "{fs}");
    let vs = refl.entry_points.iter().find(|e| e.name == "light_vs").unwrap();
    assert_eq!(vs.inputs[1].vertex_format.as_deref(), Some("Sint32"));
    assert_eq!(vs.outputs[0].interpolation.as_deref(), Some("flat"));
    let kinds: Vec<_> = refl.samplers.iter().map(|s| (s.name.as_str(), s.dimension.as_str(), s.sample_type.as_str(), s.comparison, s.texture_unit)).collect();
    assert_eq!(kinds, [("tex", "2d", "float", false, 0), ("arr", "2d-array", "depth", true, 1), ("itex", "2d", "sint", false, 2)]);
}

/// Struct types nested in uniform blocks (a struct field, the element of a
/// loose array of structs) are described in the manifest's `structs`, once
/// each and after the structs they contain, with the struct's own size (a
/// nested 4-byte struct stays 4 bytes; the block is rounded up to 16).
#[test]
fn nested_struct_layouts_are_in_the_manifest() {
    let src = r#"
struct Inner { a: f32 }
struct Outer { x: vec4<f32>, i: Inner }
struct Pair { k: vec4<f32>, o: array<Outer, 2> }
@group(0) @binding(0) var<uniform> u_pair: Pair;
@group(0) @binding(1) var<uniform> u_outers: array<Outer, 3>;
@group(0) @binding(2) var<uniform> u_inner: Inner;
@fragment fn fs() -> @location(0) vec4<f32> { return u_pair.k + u_outers[2].x + vec4<f32>(u_pair.o[1].i.a + u_inner.a); }
"#;
    let (arts, refl) = emit_all(src);
    // (name, type, offset, size, array stride) of each member.
    type Members<'a> = Vec<(&'a str, &'a str, u32, u32, Option<u32>)>;
    let layout: Vec<(&str, u32, Members)> = refl
        .structs
        .iter()
        .map(|s| (s.name.as_str(), s.size, s.members.iter().map(|m| (m.name.as_str(), m.ty.as_str(), m.offset, m.size, m.array_stride)).collect()))
        .collect();
    assert_eq!(
        layout,
        [
            ("Inner", 4, vec![("a", "float", 0, 4, None)]),
            ("Outer", 32, vec![("x", "float4", 0, 16, None), ("i", "Inner", 16, 4, None)]),
            ("Pair", 80, vec![("k", "float4", 0, 16, None), ("o", "Outer[2]", 16, 64, Some(32))]),
        ]
    );
    let sizes: Vec<(&str, &str, u32)> = refl.uniform_buffers.iter().map(|b| (b.name.as_str(), b.ty.as_str(), b.size)).collect();
    assert_eq!(sizes, [("u_pair", "Pair", 80), ("u_outers", "Outer[3]", 96), ("u_inner", "Inner", 16)]);

    // The JSON carries them and reads back; a manifest written before the
    // field existed still reads, with no structs.
    let json = text(&arts, "shadow.reflect.json");
    let parsed: umbrac::Reflection = serde_json::from_str(&json).unwrap();
    assert_eq!(parsed, refl);
    let mut value: serde_json::Value = serde_json::from_str(&json).unwrap();
    value.as_object_mut().unwrap().remove("structs");
    let old: umbrac::Reflection = serde_json::from_value(value).unwrap();
    assert!(old.structs.is_empty());
    assert_eq!(old.uniform_buffers, refl.uniform_buffers);
}

/// The checker refuses `floatCx2` uniforms (their std140 and WGSL layouts
/// differ), so a lowered module with one is a lowering bug: emission stops
/// with an internal error whatever the targets, never a user error (those
/// belong to the checker, which `fake_lowered` bypasses) and never outputs
/// that disagree about the buffer.
#[test]
fn mat2_uniform_from_the_lowering_is_an_internal_error() {
    let src = r#"
@group(0) @binding(0) var<uniform> u_rot: mat2x2<f32>;
@vertex fn vs(@location(0) p: vec2<f32>) -> @builtin(position) vec4<f32> { return vec4<f32>(u_rot * p, 0.0, 1.0); }
"#;
    let lowered = fake_lowered(src);
    for targets in [&[][..], &[Target::Glsl330], &[Target::Wgsl, Target::Spirv]] {
        let err = emit::emit(&lowered, "rot", "rot.das", targets).unwrap_err();
        assert_eq!(err.severity, Severity::Bug, "{targets:?}: {err:?}");
        assert!(err.message.contains("lowering produced uniform buffer `u_rot`"), "{err:?}");
        assert!(err.message.contains("float2x2: std140 column stride 16, WGSL column stride 8"), "{err:?}");
        assert!(err.notes.is_empty(), "an internal error gives the user no help text: {err:?}");
    }
}

fn validate_wgsl(src: &str) -> Result<(), String> {
    let m = naga::front::wgsl::parse_str(src).map_err(|e| e.emit_to_string(src))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
        .validate(&m)
        .map(|_| ())
        .map_err(|e| e.emit_to_string(src))
}

#[test]
fn wgsl_keeps_the_diagnostic_filter_and_round_trips() {
    let (arts, _) = emit_all(SHADOW);
    let wgsl = text(&arts, "shadow.wgsl");
    assert!(wgsl.starts_with("diagnostic(off, derivative_uniformity);\n"), "{wgsl}");
    validate_wgsl(&wgsl).unwrap();

    // Implicit-LOD sampling under a branch on a varying: invalid WGSL unless
    // the directive survives emission. naga 30 itself does not enforce this
    // rule (its analyzer has `DISABLE_UNIFORMITY_REQ_FOR_FRAGMENT_STAGE`),
    // but Tint (Chrome's WebGPU) does, so the directive must be there.
    let src = r#"
diagnostic(off, derivative_uniformity);
@group(0) @binding(0) var tex: texture_2d<f32>;
@group(0) @binding(1) var tex_sampler: sampler;
@fragment
fn fs(@location(0) uv: vec2<f32>) -> @location(0) vec4<f32> {
    var c = vec4<f32>(0.0);
    if (uv.x > 0.5) {
        c = textureSample(tex, tex_sampler, uv);
    }
    return c;
}
"#;
    let (arts, _) = emit::emit(&fake_lowered(src), "nu", "nu.das", &[Target::Wgsl]).unwrap();
    let wgsl = text(&arts, "nu.wgsl");
    validate_wgsl(&wgsl).unwrap();
    assert!(wgsl.starts_with("diagnostic(off, derivative_uniformity);\n"), "{wgsl}");
    assert_eq!(wgsl.matches("diagnostic(").count(), 1, "{wgsl}");
}

#[test]
fn deterministic() {
    let (a, _) = emit_all(SHADOW);
    let (b, _) = emit_all(SHADOW);
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.contents, y.contents, "{}", x.file_name);
    }
}

#[test]
fn reflection_json_round_trips() {
    let (arts, refl) = emit_all(SHADOW);
    let parsed: umbrac::Reflection = serde_json::from_str(&text(&arts, "shadow.reflect.json")).unwrap();
    assert_eq!(parsed, refl);
    assert_eq!(parsed.conventions, "portable");
    assert_eq!(parsed.source, "shadow.das");
}

#[test]
fn validators_accept_every_output() {
    for (src, stem) in [(SHADOW, "shadow"), (PACKED, "packed")] {
        let lowered = fake_lowered(src);
        let (arts, refl) = emit::emit(&lowered, stem, "x.das", &[]).unwrap();
        let dir = tempfile::tempdir().unwrap();
        support::write_all(dir.path(), &arts);
        let runs = support::validate_dir(dir.path(), &refl);
        eprintln!("{stem}: {runs} validator runs");
    }
}

#[test]
fn block_rename_collision_is_refused() {
    // A global already called `u_model_ubo` makes the rename ambiguous.
    let src = r#"
@group(0) @binding(0) var<uniform> u_model: mat4x4<f32>;
var<private> u_model_ubo: vec4<f32>;
@vertex fn vs(@location(0) p: vec4<f32>) -> @builtin(position) vec4<f32> { u_model_ubo = p; return u_model * u_model_ubo; }
"#;
    let lowered = fake_lowered(src);
    let err = emit::emit(&lowered, "c", "c.das", &[Target::Glsl330]).unwrap_err();
    assert_eq!(err.severity, Severity::Bug);
    assert!(err.message.contains("collide"), "{err:?}");
}

/// What the preamble guards against: an ES sampler2DShadow with neither a
/// default precision nor a qualifier on its declaration is rejected. naga
/// also qualifies the declaration (`uniform highp sampler2DShadow`), so the
/// preamble is what keeps the file valid wherever a sampler type is spelled
/// without one; with the preamble the unqualified form compiles.
#[test]
fn glslang_needs_the_es_precision_line() {
    if !support::require_tool("glslangValidator") {
        return;
    }
    let (arts, _) = emit_all(SHADOW);
    let fs = text(&arts, "main_fs.300es.frag");
    let unqualified = fs.replace("uniform highp sampler2DShadow", "uniform sampler2DShadow");
    let dir = tempfile::tempdir().unwrap();
    let with = dir.path().join("with.frag");
    let without = dir.path().join("without.frag");
    std::fs::write(&with, &unqualified).unwrap();
    std::fs::write(&without, unqualified.replace("precision highp sampler2DShadow;\n", "")).unwrap();
    support::glslang(&with).unwrap();
    let err = support::glslang(&without).unwrap_err();
    assert!(err.contains("precision"), "{err}");
}

/// naga's validators and SPIR-V writer are kept per thread between
/// compilations (their tables' memory is reused): what a thread compiled
/// before must not show in what it compiles next. Each program is compiled
/// on a fresh thread, then all of them again, one after another, on one
/// thread; every output must be the same. `points.das` turns on the
/// writer's point-size flag, and `bind_groups.das` has its own binding map.
#[test]
fn reused_writers_and_validators_leave_nothing_behind() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let files = [dir.join("shadow.das"), dir.join("features/points.das"), dir.join("features/bind_groups.das"), dir.join("features/packing.das")];
    let outputs = |path: &std::path::Path| -> Vec<(String, Vec<u8>)> {
        let c = umbrac::compile_file(path, &umbrac::Options::default());
        assert!(!c.has_errors(), "{}", c.render_diagnostics());
        c.result.unwrap().artifacts.into_iter().map(|a| (a.file_name, a.contents)).collect()
    };
    // Compiler threads run compilations on themselves in every build (a
    // debug build would otherwise start a thread per compilation).
    let on_compiler_thread = |f: &(dyn Fn() -> Vec<Vec<(String, Vec<u8>)>> + Sync)| std::thread::scope(|s| umbrac::spawn_compiler_thread(s, f).unwrap().join().unwrap());
    let fresh: Vec<_> = files.iter().flat_map(|f| on_compiler_thread(&|| vec![outputs(f)])).collect();
    let reused = on_compiler_thread(&|| files.iter().chain(files.iter().rev()).map(|f| outputs(f)).collect());
    let n = files.len();
    for (i, f) in files.iter().enumerate() {
        for again in [&reused[i], &reused[2 * n - 1 - i]] {
            assert_eq!(fresh[i].len(), again.len(), "{}", f.display());
            for (a, b) in fresh[i].iter().zip(again) {
                assert!(a == b, "{}: `{}` differs after other compilations on the thread", f.display(), a.0);
            }
        }
    }
}

/// Struct uniforms are GLSL blocks that declare their members with an
/// instance name (as daslang's generator writes them), at the GL binding
/// points daslang's binder gives them (sorted by name, `@binding` kept);
/// the manifest says the member names a host queries. A whole-struct read
/// is built from the members, in both `--gl-uniforms` modes.
#[test]
fn struct_uniform_blocks_as_daslang_declares_them() {
    let src = "struct Light {\n    color : float4\n}\nstruct Cam {\n    view : float4x4\n    lights : Light[2]\n    key : Light\n}\n\
               var @uniform @binding = 3 z_cam : Cam\nvar @uniform m_cam : Cam\nvar @uniform a_cam : Cam\nvar @uniform u_k : float\n\
               var @in @location = 0 a_pos : float3\nvar @inout v_c : float4\nvar @out f_color : float4\n\
               def lit(c : Cam) : float4 {\n    return c.key.color + c.lights[1].color\n}\n\
               [vertex_program]\ndef vs {\n    let c = m_cam\n    v_c = lit(a_cam) * u_k\n    gl_Position = z_cam.view * c.view * float4(a_pos, 1.0)\n}\n\
               [fragment_program]\ndef fs {\n    f_color = v_c + lit(z_cam)\n}\n";
    for gl_uniforms in [umbrac::GlUniforms::Plain, umbrac::GlUniforms::Blocks] {
        let c = umbrac::compile_source("blocks.das", src, &umbrac::Options { gl_uniforms, ..Default::default() });
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
        let r = &compiled.reflection;
        let point = |name: &str| r.uniform_buffers.iter().find(|b| b.name == name).and_then(|b| b.glsl_binding);
        // a_cam, m_cam by name at 0 and 1; z_cam keeps its @binding.
        assert_eq!([point("a_cam"), point("m_cam"), point("z_cam")], [Some(0), Some(1), Some(3)]);
        let z = r.uniform_buffers.iter().find(|b| b.name == "z_cam").unwrap();
        let names: Vec<_> = z.members.iter().map(|m| m.glsl_name.as_deref().unwrap()).collect();
        assert_eq!(names, ["z_cam_ubo.view", "z_cam_ubo.lights", "z_cam_ubo.key"]);
        let vs = compiled.artifact("vs.330.vert").unwrap().text().into_owned();
        assert!(vs.contains("uniform m_cam_ubo {\n    mat4x4 view;\n    Light lights[2];\n    Light key;\n} m_cam;"), "{vs}");
        assert!(!vs.contains("{ Cam"), "{vs}");
        match gl_uniforms {
            umbrac::GlUniforms::Plain => assert!(vs.contains("uniform float u_k;") && point("uniforms").is_none(), "{vs}"),
            umbrac::GlUniforms::Blocks => {
                // The loose buffer after the struct uniforms' points.
                assert_eq!(point("uniforms"), Some(2));
                assert!(vs.contains("uniform uniforms_ubo {\n    float u_k;\n} uniforms;"), "{vs}");
            }
        }
    }
}
