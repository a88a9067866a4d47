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
    @location(2) v_shadow_coord: vec4<f32>,
}

struct main_fs_out {
    @location(0) f_FragColor: vec4<f32>,
}

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
var<uniform> u_light_dir: vec3<f32>;
@group(0) @binding(7) 
var shadow_map: texture_depth_2d;
@group(0) @binding(8) 
var shadow_map_sampler: sampler_comparison;
var<private> v_shadow_coord: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn bias_matrix() -> mat4x4<f32> {
    return mat4x4<f32>(vec4<f32>(0.5f, 0f, 0f, 0f), vec4<f32>(0f, 0.5f, 0f, 0f), vec4<f32>(0f, 0f, 0.5f, 0f), vec4<f32>(0.5f, 0.5f, 0.5f, 1f));
}

fn sun_ndotl() -> f32 {
    let _e1 = v_world_normal;
    let _e4 = u_light_dir;
    return max(dot(normalize(_e1), normalize(_e4)), 0f);
}

fn slope_bias(ndotl: f32) -> f32 {
    return max((0.0025f * (1f - ndotl)), 0.0008f);
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

fn sun_shade(visibility: f32) -> vec3<f32> {
    let _e2 = v_world_normal;
    let n_1 = normalize(_e2);
    let _e5 = u_light_dir;
    let l = normalize(_e5);
    let _e8 = u_cam_pos;
    let _e10 = v_world_pos;
    let v = normalize((_e8 - _e10));
    let ndotl_1 = max(dot(n_1, l), 0f);
    let lit = select(visibility, 0f, (ndotl_1 < 0.05f));
    let h = normalize((l + v));
    let _e28 = surface_gloss();
    let spec = ((pow(max(dot(n_1, h), 0f), 48f) * lit) * _e28);
    let sun = vec3<f32>(1.3f, 1.15f, 0.9f);
    let _e34 = surface_albedo();
    let _e35 = hemisphere(n_1);
    return ((_e34 * (_e35 + (sun * (ndotl_1 * lit)))) + vec3(spec));
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
    let _e23 = bias_matrix();
    let _e25 = u_light_vp;
    v_shadow_coord = ((_e23 * _e25) * world);
    let _e30 = u_proj;
    let _e32 = u_view;
    gl_Position = (_e30 * (_e32 * world));
    let _e36 = gl_Position;
    let _e47 = v_world_pos;
    let _e49 = v_world_normal;
    let _e51 = v_shadow_coord;
    return main_vs_out(vec4<f32>(_e36.x, -(_e36.y), ((_e36.z + _e36.w) * 0.5f), _e36.w), _e47, _e49, _e51);
}

@fragment 
fn main_fs(@location(0) in_v_world_pos: vec3<f32>, @location(1) in_v_world_normal: vec3<f32>, @location(2) in_v_shadow_coord: vec4<f32>) -> main_fs_out {
    v_world_pos = in_v_world_pos;
    v_world_normal = in_v_world_normal;
    v_shadow_coord = in_v_shadow_coord;
    let q = v_shadow_coord;
    let _e10 = sun_ndotl();
    let _e11 = slope_bias(_e10);
    let biased = vec4<f32>(q.xy, (q.z - (_e11 * q.w)), q.w);
    let _e26 = textureSampleCompare(shadow_map, shadow_map_sampler, (biased.xy / vec2(biased.w)), (biased.z / biased.w));
    let _e27 = sun_shade(_e26);
    f_FragColor = vec4<f32>(_e27, 1f);
    let _e31 = f_FragColor;
    return main_fs_out(_e31);
}
