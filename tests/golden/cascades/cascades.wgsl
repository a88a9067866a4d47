diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_light_vp: mat4x4<f32>,
    u_cam_pos: vec3<f32>,
    u_is_floor: f32,
    u_light_dir: vec3<f32>,
    u_cascade_vp: array<mat4x4<f32>, 3>,
}

struct cascades_shadow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct cascades_shadow_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

struct cascades_main_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world_pos: vec3<f32>,
    @location(1) v_world_normal: vec3<f32>,
}

struct cascades_main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

const CASCADES: i32 = 3i;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_world_pos_1: vec3<f32>;
var<private> v_world_normal_1: vec3<f32>;
@group(0) @binding(1) 
var cascade_maps_0_: texture_depth_2d;
@group(0) @binding(2) 
var cascade_maps_0_sampler: sampler_comparison;
@group(0) @binding(3) 
var cascade_maps_1_: texture_depth_2d;
@group(0) @binding(4) 
var cascade_maps_1_sampler: sampler_comparison;
@group(0) @binding(5) 
var cascade_maps_2_: texture_depth_2d;
@group(0) @binding(6) 
var cascade_maps_2_sampler: sampler_comparison;

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

fn pick_cascade(p: vec4<f32>) -> i32 {
    var i: i32;

    let _e4 = textureDimensions(cascade_maps_0_, 0i);
    let margin = (2f / f32(vec2<i32>(_e4).x));
    i = 0i;
    loop {
        let _e13 = i;
        if !((_e13 < (CASCADES - 1i))) {
            break;
        }
        let _e18 = i;
        let _e20 = uniforms.u_cascade_vp[_e18];
        let _e22 = to_map((_e20 * p));
        if (((((_e22.x > margin) && (_e22.y > margin)) && (_e22.x < (1f - margin))) && (_e22.y < (1f - margin))) && (_e22.z < 1f)) {
            let _e40 = i;
            return _e40;
        }
        continuing {
            let _e41 = i;
            i = (_e41 + 1i);
        }
    }
    return (CASCADES - 1i);
}

fn sun_ndotl() -> f32 {
    let _e1 = v_world_normal_1;
    let _e5 = uniforms.u_light_dir;
    return max(dot(normalize(_e1), normalize(_e5)), 0f);
}

fn slope_bias(ndotl: f32) -> f32 {
    return max((0.0025f * (1f - ndotl)), 0.0008f);
}

fn surface_gloss() -> f32 {
    let _e2 = uniforms.u_is_floor;
    return select(0.5f, 0.15f, (_e2 > 0.5f));
}

fn checker(p_1: vec3<f32>) -> vec3<f32> {
    let cell = (floor(((p_1.x * 0.5f) + 100f)) + floor(((p_1.z * 0.5f) + 100f)));
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
    let ndotl_1 = max(dot(n_1, l), 0f);
    let lit = select(visibility, 0f, (ndotl_1 < 0.05f));
    let h = normalize((l + v));
    let _e27 = surface_gloss();
    let spec = ((pow(max(dot(n_1, h), 0f), 48f) * lit) * _e27);
    let sun = vec3<f32>(1.3f, 1.15f, 0.9f);
    let _e33 = surface_albedo();
    let _e34 = hemisphere(n_1);
    return ((_e33 * (_e34 + (sun * (ndotl_1 * lit)))) + vec3(spec));
}

@vertex 
fn cascades_shadow_vs(@location(0) in_a_pos: vec3<f32>) -> cascades_shadow_vs_out {
    var gl_Position: vec4<f32>;

    a_pos = in_a_pos;
    let _e3 = shadow_clip();
    gl_Position = _e3;
    let _e4 = gl_Position;
    return cascades_shadow_vs_out(vec4<f32>(_e4.x, -(_e4.y), ((_e4.z + _e4.w) * 0.5f), _e4.w));
}

@fragment 
fn cascades_shadow_fs() -> cascades_shadow_fs_out {
    var f_FragColor: vec4<f32>;

    f_FragColor = vec4(1f);
    let _e3 = f_FragColor;
    return cascades_shadow_fs_out(_e3);
}

@vertex 
fn cascades_main_vs(@location(0) in_a_pos_1: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> cascades_main_vs_out {
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
    return cascades_main_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e27, _e28);
}

@fragment 
fn cascades_main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>) -> cascades_main_fs_out {
    var f_FragColor_1: vec4<f32>;
    var texel: f32;

    v_world_pos_1 = in_v_world_pos;
    v_world_normal_1 = in_v_world_normal;
    let _e4 = v_world_pos_1;
    let p_2 = vec4<f32>(_e4, 1f);
    let _e7 = pick_cascade(p_2);
    let _e11 = uniforms.u_cascade_vp[_e7];
    let _e13 = to_map((_e11 * p_2));
    let _e14 = sun_ndotl();
    let _e15 = slope_bias(_e14);
    let bias = (_e15 * f32((1i << u32(_e7))));
    let _e21 = _e13.xy;
    let _e23 = (_e13.z - bias);
    switch clamp(_e7, 0i, 2i) {
        case 0: {
            let _e29 = textureSampleCompare(cascade_maps_0_, cascade_maps_0_sampler, _e21, _e23);
            texel = _e29;
        }
        case 1: {
            let _e33 = textureSampleCompare(cascade_maps_1_, cascade_maps_1_sampler, _e21, _e23);
            texel = _e33;
        }
        default: {
            let _e36 = textureSampleCompare(cascade_maps_2_, cascade_maps_2_sampler, _e21, _e23);
            texel = _e36;
        }
    }
    let visibility_1 = texel;
    let _e39 = sun_shade(visibility_1);
    f_FragColor_1 = vec4<f32>(_e39, 1f);
    let _e41 = f_FragColor_1;
    return cascades_main_fs_out(_e41);
}
