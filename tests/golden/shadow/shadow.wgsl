diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_light_vp: mat4x4<f32>,
    u_model: mat4x4<f32>,
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_light_dir: vec3<f32>,
    u_cam_pos: vec3<f32>,
    u_is_floor: f32,
}

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
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var shadow_map: texture_depth_2d;
@group(0) @binding(2) 
var shadow_map_sampler: sampler_comparison;

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
        let _e13 = y;
        if !((_e13 < (PCF_RADIUS + 1i))) {
            break;
        }
        x = -(PCF_RADIUS);
        loop {
            let _e19 = x;
            if !((_e19 < (PCF_RADIUS + 1i))) {
                break;
            }
            let _e22 = x;
            let _e23 = y;
            let _e31 = textureSampleCompare(shadow_map, shadow_map_sampler, (uv + (vec2<f32>(f32(_e22), f32(_e23)) * step_)), depth);
            let _e32 = lit_1;
            lit_1 = (_e32 + _e31);
            let _e34 = taps;
            taps = (_e34 + 1f);
            continuing {
                let _e36 = x;
                x = (_e36 + 1i);
            }
        }
        continuing {
            let _e38 = y;
            y = (_e38 + 1i);
        }
    }
    let _e40 = lit_1;
    let _e41 = taps;
    return (_e40 / _e41);
}

fn floor_albedo(p: vec3<f32>) -> vec3<f32> {
    let cell = (floor(((p.x * 0.5f) + 100f)) + floor(((p.z * 0.5f) + 100f)));
    let odd = (cell - (2f * floor((cell * 0.5f))));
    let shade = select(0.3f, 0.85f, (odd < 0.5f));
    return (vec3(shade) * vec3<f32>(0.8f, 0.82f, 0.88f));
}

@vertex 
fn shadow_vs(@location(0) a_pos: vec3<f32>) -> shadow_vs_out {
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_light_vp;
    let _e6 = uniforms.u_model;
    gl_Position = (_e4 * (_e6 * vec4<f32>(a_pos, 1f)));
    let _e11 = gl_Position;
    return shadow_vs_out(vec4<f32>(_e11.x, -(_e11.y), ((_e11.z + _e11.w) * 0.5f), _e11.w));
}

@fragment 
fn shadow_fs() -> shadow_fs_out {
    var f_FragColor: vec4<f32>;

    f_FragColor = vec4(1f);
    let _e3 = f_FragColor;
    return shadow_fs_out(_e3);
}

@vertex 
fn main_vs(@location(0) a_pos_1: vec3<f32>, @location(1) a_normal: vec3<f32>) -> main_vs_out {
    var v_world_pos: vec3<f32>;
    var v_world_normal: vec3<f32>;
    var v_light_space: vec4<f32>;
    var gl_Position_1: vec4<f32>;

    let _e4 = uniforms.u_model;
    let world = (_e4 * vec4<f32>(a_pos_1, 1f));
    v_world_pos = world.xyz;
    let _e12 = uniforms.u_model;
    v_world_normal = (_e12 * vec4<f32>(a_normal, 0f)).xyz;
    let _e19 = uniforms.u_light_vp;
    v_light_space = (_e19 * world);
    let _e23 = uniforms.u_proj;
    let _e25 = uniforms.u_view;
    gl_Position_1 = (_e23 * (_e25 * world));
    let _e28 = gl_Position_1;
    let _e38 = v_world_pos;
    let _e39 = v_world_normal;
    let _e40 = v_light_space;
    return main_vs_out(vec4<f32>(_e28.x, -(_e28.y), ((_e28.z + _e28.w) * 0.5f), _e28.w), _e38, _e39, _e40);
}

@fragment 
fn main_fs(@location(0) v_world_pos_1: vec3<f32>, @location(1) v_world_normal_1: vec3<f32>, @location(2) v_light_space_1: vec4<f32>) -> main_fs_out {
    var f_FragColor_1: vec4<f32>;
    var lit: f32;
    var albedo: vec3<f32>;
    var gloss: f32;

    let n = normalize(v_world_normal_1);
    let _e6 = uniforms.u_light_dir;
    let l = normalize(_e6);
    let _e9 = uniforms.u_cam_pos;
    let v = normalize((_e9 - v_world_pos_1));
    let ndotl = max(dot(n, l), 0f);
    let clip_w = max(v_light_space_1.w, 0.0001f);
    let ndc = (v_light_space_1.xyz / vec3(clip_w));
    let uv_1 = ((ndc.xy * 0.5f) + vec2(0.5f));
    let depth_1 = ((ndc.z * 0.5f) + 0.5f);
    let bias = max((0.0025f * (1f - ndotl)), 0.0008f);
    let _e37 = sun_visibility(uv_1, (depth_1 - bias));
    lit = _e37;
    if (ndotl < 0.05f) {
        lit = 0f;
    }
    let up = ((n.y * 0.5f) + 0.5f);
    let ambient = mix(vec3<f32>(0.1f, 0.09f, 0.08f), vec3<f32>(0.3f, 0.34f, 0.42f), vec3(up));
    let sun_color = vec3<f32>(1.3f, 1.15f, 0.9f);
    albedo = vec3<f32>(0.85f, 0.45f, 0.3f);
    gloss = 0.5f;
    let _e63 = uniforms.u_is_floor;
    if (_e63 > 0.5f) {
        let _e65 = floor_albedo(v_world_pos_1);
        albedo = _e65;
        gloss = 0.15f;
    }
    let h = normalize((l + v));
    let _e73 = lit;
    let _e75 = gloss;
    let spec = ((pow(max(dot(n, h), 0f), 48f) * _e73) * _e75);
    let _e77 = albedo;
    let _e78 = lit;
    let color = ((_e77 * (ambient + (sun_color * (ndotl * _e78)))) + vec3(spec));
    f_FragColor_1 = vec4<f32>(color, 1f);
    let _e87 = f_FragColor_1;
    return main_fs_out(_e87);
}
