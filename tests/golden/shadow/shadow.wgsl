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
    @location(2) v_light_space: vec4<f32>,
}

struct main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

const SHADOW_MAP_SIZE: f32 = 1024f;
const PCF_RADIUS: i32 = 1i;

@group(0) @binding(0) 
var<uniform> u_light_vp: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(2) 
var<uniform> u_view: mat4x4<f32>;
@group(0) @binding(3) 
var<uniform> u_proj: mat4x4<f32>;
@group(0) @binding(4) 
var<uniform> u_light_dir: vec3<f32>;
@group(0) @binding(5) 
var<uniform> u_cam_pos: vec3<f32>;
@group(0) @binding(6) 
var<uniform> u_is_floor: f32;
@group(0) @binding(7) 
var shadow_map: texture_depth_2d;
@group(0) @binding(8) 
var shadow_map_sampler: sampler_comparison;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_world_pos: vec3<f32>;
var<private> v_world_normal: vec3<f32>;
var<private> v_light_space: vec4<f32>;
var<private> f_FragColor: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn sun_visibility(uv: vec2<f32>, depth: f32) -> f32 {
    var lit_1: f32;
    var taps: f32;
    var y: i32;
    var x: i32;

    let step_ = (1f / SHADOW_MAP_SIZE);
    lit_1 = 0f;
    taps = 0f;
    y = -(PCF_RADIUS);
    loop {
        let _e15 = y;
        if !((_e15 < (PCF_RADIUS + 1i))) {
            break;
        }
        x = -(PCF_RADIUS);
        loop {
            let _e24 = x;
            if !((_e24 < (PCF_RADIUS + 1i))) {
                break;
            }
            let _e29 = x;
            let _e31 = y;
            let _e39 = textureSampleCompare(shadow_map, shadow_map_sampler, (uv + (vec2<f32>(f32(_e29), f32(_e31)) * step_)), depth);
            let _e40 = lit_1;
            lit_1 = (_e40 + _e39);
            let _e44 = taps;
            taps = (_e44 + 1f);
            continuing {
                let _e46 = x;
                x = (_e46 + 1i);
            }
        }
        continuing {
            let _e49 = y;
            y = (_e49 + 1i);
        }
    }
    let _e53 = lit_1;
    let _e55 = taps;
    return (_e53 / _e55);
}

fn floor_albedo(p: vec3<f32>) -> vec3<f32> {
    let cell = (floor(((p.x * 0.5f) + 100f)) + floor(((p.z * 0.5f) + 100f)));
    let odd = (cell - (2f * floor((cell * 0.5f))));
    let shade = select(0.3f, 0.85f, (odd < 0.5f));
    return (vec3(shade) * vec3<f32>(0.8f, 0.82f, 0.88f));
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
    let world = (_e5 * vec4<f32>(_e7, 1f));
    v_world_pos = world.xyz;
    let _e15 = u_model;
    let _e17 = a_normal;
    v_world_normal = (_e15 * vec4<f32>(_e17, 0f)).xyz;
    let _e24 = u_light_vp;
    v_light_space = (_e24 * world);
    let _e28 = u_proj;
    let _e30 = u_view;
    gl_Position = (_e28 * (_e30 * world));
    let _e34 = gl_Position;
    let _e45 = v_world_pos;
    let _e47 = v_world_normal;
    let _e49 = v_light_space;
    return main_vs_out(vec4<f32>(_e34.x, -(_e34.y), ((_e34.z + _e34.w) * 0.5f), _e34.w), _e45, _e47, _e49);
}

@fragment 
fn main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>, @location(2) in_v_light_space: vec4<f32>) -> main_fs_out {
    var lit: f32;
    var albedo: vec3<f32>;
    var gloss: f32;

    v_world_pos = in_v_world_pos;
    v_world_normal = in_v_world_normal;
    v_light_space = in_v_light_space;
    let _e7 = v_world_normal;
    let n = normalize(_e7);
    let _e10 = u_light_dir;
    let l = normalize(_e10);
    let _e13 = u_cam_pos;
    let _e15 = v_world_pos;
    let v = normalize((_e13 - _e15));
    let ndotl = max(dot(n, l), 0f);
    let _e23 = v_light_space.w;
    let clip_w = max(_e23, 0.0001f);
    let _e27 = v_light_space;
    let ndc = (_e27.xyz / vec3(clip_w));
    let uv_1 = ((ndc.xy * 0.5f) + vec2(0.5f));
    let depth_1 = ((ndc.z * 0.5f) + 0.5f);
    let bias = max((0.0025f * (1f - ndotl)), 0.0008f);
    let _e50 = sun_visibility(uv_1, (depth_1 - bias));
    lit = _e50;
    if (ndotl < 0.05f) {
        lit = 0f;
    }
    let up = ((n.y * 0.5f) + 0.5f);
    let ambient = mix(vec3<f32>(0.1f, 0.09f, 0.08f), vec3<f32>(0.3f, 0.34f, 0.42f), vec3(up));
    let sun_color = vec3<f32>(1.3f, 1.15f, 0.9f);
    albedo = vec3<f32>(0.85f, 0.45f, 0.3f);
    gloss = 0.5f;
    let _e82 = u_is_floor;
    if (_e82 > 0.5f) {
        let _e87 = v_world_pos;
        let _e88 = floor_albedo(_e87);
        albedo = _e88;
        gloss = 0.15f;
    }
    let h = normalize((l + v));
    let _e99 = lit;
    let _e102 = gloss;
    let spec = ((pow(max(dot(n, h), 0f), 48f) * _e99) * _e102);
    let _e105 = albedo;
    let _e107 = lit;
    let color = ((_e105 * (ambient + (sun_color * (ndotl * _e107)))) + vec3(spec));
    f_FragColor = vec4<f32>(color, 1f);
    let _e118 = f_FragColor;
    return main_fs_out(_e118);
}
