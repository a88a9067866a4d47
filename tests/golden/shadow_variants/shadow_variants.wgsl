diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view_proj: mat4x4<f32>,
    u_light_view_proj: mat4x4<f32>,
    u_light_dir: vec3<f32>,
    u_eye: vec3<f32>,
    u_color: vec4<f32>,
}

struct variants_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
    @location(1) v_world: vec3<f32>,
    @location(2) v_light_pos: vec4<f32>,
}

struct variants_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var shadow_map: texture_depth_2d;
@group(0) @binding(2) 
var shadow_map_sampler: sampler_comparison;
var<private> v_light_pos_1: vec4<f32>;

fn shadow_lookup(coord: vec3<f32>, bias: f32) -> f32 {
    let _e7 = textureSampleCompare(shadow_map, shadow_map_sampler, coord.xy, (coord.z - bias));
    return _e7;
}

fn shadow_factor(ndotl: f32) -> f32 {
    let _e2 = v_light_pos_1;
    let _e5 = v_light_pos_1.w;
    let coord_1 = (((_e2.xyz / vec3(_e5)) * 0.5f) + vec3(0.5f));
    if (coord_1.z > 1f) {
        return 1f;
    }
    let _e16 = shadow_lookup(coord_1, 0.002f);
    return _e16;
}

@vertex 
fn variants_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>) -> variants_vs_out {
    var v_normal: vec3<f32>;
    var v_world: vec3<f32>;
    var v_light_pos: vec4<f32>;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_model;
    let world = (_e4 * vec4<f32>(a_position, 1f));
    v_world = world.xyz;
    let _e12 = uniforms.u_model;
    v_normal = (_e12 * vec4<f32>(a_normal, 0f)).xyz;
    let _e19 = uniforms.u_light_view_proj;
    v_light_pos = (_e19 * world);
    let _e23 = uniforms.u_view_proj;
    gl_Position = (_e23 * world);
    let _e25 = gl_Position;
    let _e35 = v_normal;
    let _e36 = v_world;
    let _e37 = v_light_pos;
    return variants_vs_out(vec4<f32>(_e25.x, -(_e25.y), ((_e25.z + _e25.w) * 0.5f), _e25.w), _e35, _e36, _e37);
}

@fragment 
fn variants_fs(@location(0) v_normal_1: vec3<f32>, @location(1) v_world_1: vec3<f32>, @location(2) in_v_light_pos: vec4<f32>) -> variants_fs_out {
    var f_color: vec4<f32>;
    var color: vec3<f32>;

    v_light_pos_1 = in_v_light_pos;
    let n = normalize(v_normal_1);
    let _e7 = uniforms.u_light_dir;
    let l = normalize(-(_e7));
    let _e11 = uniforms.u_eye;
    let v = normalize((_e11 - v_world_1));
    let ndotl_1 = max(dot(n, l), 0f);
    let _e17 = shadow_factor(ndotl_1);
    let _e20 = uniforms.u_color;
    color = (_e20.xyz * (0.15f + ((0.85f * ndotl_1) * _e17)));
    let _e29 = color;
    let _e32 = uniforms.u_color.w;
    f_color = vec4<f32>(_e29, _e32);
    let _e34 = f_color;
    return variants_fs_out(_e34);
}
