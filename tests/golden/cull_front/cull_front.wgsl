diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_light_vp: mat4x4<f32>,
    u_cam_pos: vec3<f32>,
    u_is_floor: f32,
    u_light_dir: vec3<f32>,
}

struct cull_shadow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct cull_shadow_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

struct cull_main_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world_pos: vec3<f32>,
    @location(1) v_world_normal: vec3<f32>,
}

struct cull_main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

const PCF_TAPS: i32 = 4i;
const PCF_OFFSETS: array<vec2<f32>, 4> = array<vec2<f32>, 4>(vec2<f32>(-0.5f, -0.5f), vec2<f32>(0.5f, -0.5f), vec2<f32>(-0.5f, 0.5f), vec2<f32>(0.5f, 0.5f));

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_world_pos_1: vec3<f32>;
var<private> v_world_normal_1: vec3<f32>;
@group(0) @binding(1) 
var shadow_map: texture_depth_2d;
@group(0) @binding(2) 
var shadow_map_sampler: sampler_comparison;

fn shadow_clip() -> vec4<f32> {
    let _e2 = uniforms.u_light_vp;
    let _e4 = uniforms.u_model;
    let _e6 = a_pos;
    return (_e2 * (_e4 * vec4<f32>(_e6, 1f)));
}

fn world_position() -> vec4<f32> {
    let _e2 = uniforms.u_model;
    let _e4 = a_pos;
    return (_e2 * vec4<f32>(_e4, 1f));
}

fn world_normal() -> vec3<f32> {
    let _e2 = uniforms.u_model;
    let _e4 = a_normal;
    return (_e2 * vec4<f32>(_e4, 0f)).xyz;
}

fn to_map(clip: vec4<f32>) -> vec3<f32> {
    return (((clip.xyz / vec3(max(clip.w, 0.0001f))) * 0.5f) + vec3(0.5f));
}

fn pcf_visibility(coord: vec3<f32>, bias: f32) -> f32 {
    var seen: f32;
    var i: i32;

    let _e6 = textureDimensions(shadow_map, 0i);
    let texel = (vec2(1f) / vec2<f32>(vec2<i32>(_e6)));
    seen = 0f;
    i = 0i;
    loop {
        let _e14 = i;
        if !((_e14 < PCF_TAPS)) {
            break;
        }
        let _e19 = i;
        let _e26 = textureSampleCompare(shadow_map, shadow_map_sampler, (coord.xy + (PCF_OFFSETS[_e19] * texel)), (coord.z - bias));
        let _e27 = seen;
        seen = (_e27 + _e26);
        continuing {
            let _e29 = i;
            i = (_e29 + 1i);
        }
    }
    let _e32 = seen;
    return (_e32 / f32(PCF_TAPS));
}

fn surface_gloss() -> f32 {
    let _e2 = uniforms.u_is_floor;
    return select(0.5f, 0.15f, (_e2 > 0.5f));
}

fn checker(p: vec3<f32>) -> vec3<f32> {
    let cell = (floor(((p.x * 0.5f) + 100f)) + floor(((p.z * 0.5f) + 100f)));
    let odd = (cell - (2f * floor((cell * 0.5f))));
    return (vec3(select(0.3f, 0.85f, (odd < 0.5f))) * vec3<f32>(0.8f, 0.82f, 0.88f));
}

fn surface_albedo() -> vec3<f32> {
    let _e2 = uniforms.u_is_floor;
    if (_e2 > 0.5f) {
        let _e6 = v_world_pos_1;
        let _e7 = checker(_e6);
        return _e7;
    }
    return vec3<f32>(0.85f, 0.45f, 0.3f);
}

fn hemisphere(n: vec3<f32>) -> vec3<f32> {
    return mix(vec3<f32>(0.1f, 0.09f, 0.08f), vec3<f32>(0.3f, 0.34f, 0.42f), vec3(((n.y * 0.5f) + 0.5f)));
}

fn sun_shade(visibility: f32) -> vec3<f32> {
    let _e2 = v_world_normal_1;
    let n_1 = normalize(_e2);
    let _e6 = uniforms.u_light_dir;
    let l = normalize(_e6);
    let _e9 = uniforms.u_cam_pos;
    let _e11 = v_world_pos_1;
    let v = normalize((_e9 - _e11));
    let ndotl = max(dot(n_1, l), 0f);
    let lit = select(visibility, 0f, (ndotl < 0.05f));
    let h = normalize((l + v));
    let _e27 = surface_gloss();
    let spec = ((pow(max(dot(n_1, h), 0f), 48f) * lit) * _e27);
    let sun = vec3<f32>(1.3f, 1.15f, 0.9f);
    let _e33 = surface_albedo();
    let _e34 = hemisphere(n_1);
    return ((_e33 * (_e34 + (sun * (ndotl * lit)))) + vec3(spec));
}

@vertex 
fn cull_shadow_vs(@location(0) in_a_pos: vec3<f32>) -> cull_shadow_vs_out {
    var gl_Position: vec4<f32>;

    a_pos = in_a_pos;
    let _e3 = shadow_clip();
    gl_Position = _e3;
    let _e4 = gl_Position;
    return cull_shadow_vs_out(vec4<f32>(_e4.x, -(_e4.y), ((_e4.z + _e4.w) * 0.5f), _e4.w));
}

@fragment 
fn cull_shadow_fs() -> cull_shadow_fs_out {
    var f_FragColor: vec4<f32>;

    f_FragColor = vec4(1f);
    let _e3 = f_FragColor;
    return cull_shadow_fs_out(_e3);
}

@vertex 
fn cull_main_vs(@location(0) in_a_pos_1: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> cull_main_vs_out {
    var v_world_pos: vec3<f32>;
    var v_world_normal: vec3<f32>;
    var gl_Position_1: vec4<f32>;

    a_pos = in_a_pos_1;
    a_normal = in_a_normal;
    let _e4 = world_position();
    v_world_pos = _e4.xyz;
    let _e8 = world_normal();
    v_world_normal = _e8;
    let _e12 = uniforms.u_proj;
    let _e14 = uniforms.u_view;
    gl_Position_1 = (_e12 * (_e14 * _e4));
    let _e17 = gl_Position_1;
    let _e27 = v_world_pos;
    let _e28 = v_world_normal;
    return cull_main_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e27, _e28);
}

@fragment 
fn cull_main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>) -> cull_main_fs_out {
    var f_FragColor_1: vec4<f32>;

    v_world_pos_1 = in_v_world_pos;
    v_world_normal_1 = in_v_world_normal;
    let _e6 = uniforms.u_light_vp;
    let _e7 = v_world_pos_1;
    let _e11 = to_map((_e6 * vec4<f32>(_e7, 1f)));
    let _e14 = pcf_visibility(_e11, 0f);
    let _e15 = sun_shade(_e14);
    f_FragColor_1 = vec4<f32>(_e15, 1f);
    let _e17 = f_FragColor_1;
    return cull_main_fs_out(_e17);
}
