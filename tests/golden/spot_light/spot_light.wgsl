diagnostic(off, derivative_uniformity);

struct shadow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct shadow_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

struct main_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world_pos: vec3<f32>,
    @location(1) v_world_normal: vec3<f32>,
}

struct main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

const SPOT_COS_OUTER: f32 = 0.848f;
const SPOT_COS_INNER: f32 = 0.9063f;
const DEPTH_BIAS: f32 = 0.0006f;
const SHADOW_FACTOR: f32 = 0.5f;

@group(0) @binding(0) 
var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_view: mat4x4<f32>;
@group(0) @binding(2) 
var<uniform> u_proj: mat4x4<f32>;
@group(0) @binding(3) 
var<uniform> u_light_vp: mat4x4<f32>;
@group(0) @binding(4) 
var<uniform> u_cam_pos: vec3<f32>;
@group(0) @binding(5) 
var<uniform> u_is_floor: f32;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_world_pos: vec3<f32>;
var<private> v_world_normal: vec3<f32>;
var<private> f_FragColor: vec4<f32>;
@group(0) @binding(6) 
var<uniform> u_light_pos: vec3<f32>;
@group(0) @binding(7) 
var<uniform> u_spot_dir: vec3<f32>;
@group(0) @binding(8) 
var shadow_map: texture_2d<f32>;
@group(0) @binding(9) 
var shadow_map_sampler: sampler;
var<private> gl_Position: vec4<f32>;

fn cone(to_light: vec3<f32>) -> f32 {
    let _e5 = u_spot_dir;
    return smoothstep(SPOT_COS_OUTER, SPOT_COS_INNER, dot(-(to_light), normalize(_e5)));
}

fn to_map(clip: vec4<f32>) -> vec3<f32> {
    return (((clip.xyz / vec3(max(clip.w, 0.0001f))) * 0.5f) + vec3(0.5f));
}

fn spot_shadow(world: vec3<f32>) -> f32 {
    let _e2 = u_light_vp;
    let _e6 = to_map((_e2 * vec4<f32>(world, 1f)));
    let _e10 = textureSample(shadow_map, shadow_map_sampler, _e6.xy);
    let stored = _e10.x;
    return select(1f, SHADOW_FACTOR, ((_e6.z - DEPTH_BIAS) > stored));
}

fn surface_gloss() -> f32 {
    let _e1 = u_is_floor;
    return select(0.5f, 0.15f, (_e1 > 0.5f));
}

fn checker(p: vec3<f32>) -> vec3<f32> {
    let cell = (floor(((p.x * 0.5f) + 100f)) + floor(((p.z * 0.5f) + 100f)));
    let odd = (cell - (2f * floor((cell * 0.5f))));
    return (vec3(select(0.3f, 0.85f, (odd < 0.5f))) * vec3<f32>(0.8f, 0.82f, 0.88f));
}

fn surface_albedo() -> vec3<f32> {
    let _e1 = u_is_floor;
    if (_e1 > 0.5f) {
        let _e5 = v_world_pos;
        let _e6 = checker(_e5);
        return _e6;
    }
    return vec3<f32>(0.85f, 0.45f, 0.3f);
}

fn hemisphere(n: vec3<f32>) -> vec3<f32> {
    return mix(vec3<f32>(0.1f, 0.09f, 0.08f), vec3<f32>(0.3f, 0.34f, 0.42f), vec3(((n.y * 0.5f) + 0.5f)));
}

@vertex 
fn shadow_vs(@location(0) in_a_pos: vec3<f32>) -> shadow_vs_out {
    a_pos = in_a_pos;
    let _e4 = u_light_vp;
    let _e6 = u_model;
    let _e8 = a_pos;
    gl_Position = (_e4 * (_e6 * vec4<f32>(_e8, 1f)));
    let _e14 = gl_Position;
    return shadow_vs_out(vec4<f32>(_e14.x, -(_e14.y), ((_e14.z + _e14.w) * 0.5f), _e14.w));
}

@fragment 
fn shadow_fs() -> shadow_fs_out {
    f_FragColor = vec4(1f);
    let _e4 = f_FragColor;
    return shadow_fs_out(_e4);
}

@vertex 
fn main_vs(@location(0) in_a_pos_1: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> main_vs_out {
    a_pos = in_a_pos_1;
    a_normal = in_a_normal;
    let _e5 = u_model;
    let _e7 = a_pos;
    let world_1 = (_e5 * vec4<f32>(_e7, 1f));
    v_world_pos = world_1.xyz;
    let _e15 = u_model;
    let _e17 = a_normal;
    v_world_normal = (_e15 * vec4<f32>(_e17, 0f)).xyz;
    let _e24 = u_proj;
    let _e26 = u_view;
    gl_Position = (_e24 * (_e26 * world_1));
    let _e30 = gl_Position;
    let _e41 = v_world_pos;
    let _e43 = v_world_normal;
    return main_vs_out(vec4<f32>(_e30.x, -(_e30.y), ((_e30.z + _e30.w) * 0.5f), _e30.w), _e41, _e43);
}

@fragment 
fn main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>) -> main_fs_out {
    v_world_pos = in_v_world_pos;
    v_world_normal = in_v_world_normal;
    let _e5 = v_world_normal;
    let n_1 = normalize(_e5);
    let _e8 = u_light_pos;
    let _e10 = v_world_pos;
    let l = normalize((_e8 - _e10));
    let _e14 = u_cam_pos;
    let _e16 = v_world_pos;
    let v = normalize((_e14 - _e16));
    let ndotl = max(dot(n_1, l), 0f);
    let _e22 = cone(l);
    let _e24 = v_world_pos;
    let _e25 = spot_shadow(_e24);
    let light = (_e22 * _e25);
    let h = normalize((l + v));
    let _e36 = surface_gloss();
    let spec = select(0f, (pow(max(dot(n_1, h), 0f), 48f) * _e36), (ndotl > 0f));
    let color = vec3<f32>(1.25f, 1.15f, 0.95f);
    let _e44 = surface_albedo();
    let _e45 = hemisphere(n_1);
    let rgb = ((_e44 * (_e45 + (color * (ndotl * light)))) + vec3((spec * light)));
    f_FragColor = vec4<f32>(rgb, 1f);
    let _e57 = f_FragColor;
    return main_fs_out(_e57);
}
