diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_light_vp: mat4x4<f32>,
    u_cam_pos: vec3<f32>,
    u_is_floor: f32,
    u_light_pos: vec3<f32>,
    u_spot_dir: vec3<f32>,
}

struct spot_shadow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct spot_shadow_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

struct spot_main_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world_pos: vec3<f32>,
    @location(1) v_world_normal: vec3<f32>,
}

struct spot_main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

const SPOT_COS_OUTER: f32 = 0.848f;
const SPOT_COS_INNER: f32 = 0.9063f;
const DEPTH_BIAS: f32 = 0.0006f;
const SHADOW_FACTOR: f32 = 0.5f;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_world_pos_1: vec3<f32>;
@group(0) @binding(1) 
var shadow_map: texture_2d<f32>;
@group(0) @binding(2) 
var shadow_map_sampler: sampler;

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

fn cone(to_light: vec3<f32>) -> f32 {
    let _e6 = uniforms.u_spot_dir;
    return smoothstep(SPOT_COS_OUTER, SPOT_COS_INNER, dot(-(to_light), normalize(_e6)));
}

fn to_map(clip: vec4<f32>) -> vec3<f32> {
    return (((clip.xyz / vec3(max(clip.w, 0.0001f))) * 0.5f) + vec3(0.5f));
}

fn spot_shadow(world: vec3<f32>) -> f32 {
    let _e3 = uniforms.u_light_vp;
    let _e7 = to_map((_e3 * vec4<f32>(world, 1f)));
    let _e11 = textureSample(shadow_map, shadow_map_sampler, _e7.xy);
    let stored = _e11.x;
    return select(1f, SHADOW_FACTOR, ((_e7.z - DEPTH_BIAS) > stored));
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

@vertex 
fn spot_shadow_vs(@location(0) in_a_pos: vec3<f32>) -> spot_shadow_vs_out {
    var gl_Position: vec4<f32>;

    a_pos = in_a_pos;
    let _e3 = shadow_clip();
    gl_Position = _e3;
    let _e4 = gl_Position;
    return spot_shadow_vs_out(vec4<f32>(_e4.x, -(_e4.y), ((_e4.z + _e4.w) * 0.5f), _e4.w));
}

@fragment 
fn spot_shadow_fs() -> spot_shadow_fs_out {
    var f_FragColor: vec4<f32>;

    f_FragColor = vec4(1f);
    let _e3 = f_FragColor;
    return spot_shadow_fs_out(_e3);
}

@vertex 
fn spot_main_vs(@location(0) in_a_pos_1: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> spot_main_vs_out {
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
    return spot_main_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e27, _e28);
}

@fragment 
fn spot_main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) v_world_normal_1: vec3<f32>) -> spot_main_fs_out {
    var f_FragColor_1: vec4<f32>;

    v_world_pos_1 = in_v_world_pos;
    let n_1 = normalize(v_world_normal_1);
    let _e6 = uniforms.u_light_pos;
    let _e7 = v_world_pos_1;
    let l = normalize((_e6 - _e7));
    let _e11 = uniforms.u_cam_pos;
    let _e12 = v_world_pos_1;
    let v = normalize((_e11 - _e12));
    let ndotl = max(dot(n_1, l), 0f);
    let _e18 = cone(l);
    let _e19 = v_world_pos_1;
    let _e20 = spot_shadow(_e19);
    let light = (_e18 * _e20);
    let h = normalize((l + v));
    let _e29 = surface_gloss();
    let spec = select(0f, (pow(max(dot(n_1, h), 0f), 48f) * _e29), (ndotl > 0f));
    let color = vec3<f32>(1.25f, 1.15f, 0.95f);
    let _e36 = surface_albedo();
    let _e37 = hemisphere(n_1);
    let rgb = ((_e36 * (_e37 + (color * (ndotl * light)))) + vec3((spec * light)));
    f_FragColor_1 = vec4<f32>(rgb, 1f);
    let _e48 = f_FragColor_1;
    return spot_main_fs_out(_e48);
}
