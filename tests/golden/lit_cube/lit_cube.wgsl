diagnostic(off, derivative_uniformity);

struct Camera {
    view_proj: mat4x4<f32>,
    position: vec3<f32>,
    time: f32,
}

struct Material {
    specular: vec3<f32>,
    shininess: f32,
    tint: vec4<f32>,
}

struct Lighting {
    sun_dir: vec3<f32>,
    ambient: f32,
    sun_color: vec4<f32>,
    point_pos: vec3<f32>,
    point_range: f32,
    point_color: vec4<f32>,
}

struct Uniforms {
    u_model: mat4x4<f32>,
    u_normal_matrix: mat3x3<f32>,
}

struct cube_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world: vec3<f32>,
    @location(1) v_normal: vec3<f32>,
    @location(2) v_uv: vec2<f32>,
}

struct cube_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> camera: Camera;
@group(0) @binding(1) 
var<uniform> material: Material;
@group(0) @binding(2) 
var<uniform> lighting: Lighting;
@group(0) @binding(3) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(4) 
var diffuse_map: texture_2d<f32>;
@group(0) @binding(5) 
var diffuse_map_sampler: sampler;

fn blinn(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, color: vec3<f32>) -> vec3<f32> {
    let h = normalize((l + v));
    let diffuse = max(dot(n, l), 0f);
    let _e14 = material.shininess;
    let spec = select(0f, pow(max(dot(n, h), 0f), _e14), (diffuse > 0f));
    let _e19 = material.specular;
    return ((color * diffuse) + ((_e19 * color) * spec));
}

@vertex 
fn cube_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>, @location(2) a_uv: vec2<f32>) -> cube_vs_out {
    var v_world: vec3<f32>;
    var v_normal: vec3<f32>;
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    let _e5 = uniforms.u_model;
    let world = (_e5 * vec4<f32>(a_position, 1f));
    v_world = world.xyz;
    let _e13 = uniforms.u_normal_matrix;
    v_normal = (_e13 * a_normal);
    v_uv = a_uv;
    let _e19 = camera.view_proj;
    gl_Position = (_e19 * world);
    let _e21 = gl_Position;
    let _e31 = v_world;
    let _e32 = v_normal;
    let _e33 = v_uv;
    return cube_vs_out(vec4<f32>(_e21.x, -(_e21.y), ((_e21.z + _e21.w) * 0.5f), _e21.w), _e31, _e32, _e33);
}

@fragment 
fn cube_fs(@location(0) v_world_1: vec3<f32>, @location(1) v_normal_1: vec3<f32>, @location(2) v_uv_1: vec2<f32>, @builtin(front_facing) FrontFacing: bool) -> cube_fs_out {
    var f_color: vec4<f32>;
    var c: vec3<f32>;

    let _e6 = textureSample(diffuse_map, diffuse_map_sampler, v_uv_1);
    let _e9 = material.tint;
    let albedo = (_e6 * _e9);
    let n_1 = normalize(select(-(v_normal_1), v_normal_1, FrontFacing));
    let _e16 = camera.position;
    let v_1 = normalize((_e16 - v_world_1));
    let _e23 = lighting.ambient;
    c = (albedo.xyz * _e23);
    let _e27 = lighting.sun_dir;
    let _e31 = lighting.sun_color;
    let _e33 = blinn(n_1, normalize(-(_e27)), v_1, _e31.xyz);
    let _e35 = c;
    c = (_e35 + (albedo.xyz * _e33));
    let _e38 = lighting.point_pos;
    let to_point = (_e38 - v_world_1);
    let dist = length(to_point);
    let _e43 = lighting.point_range;
    let falloff = saturate((1f - (dist / _e43)));
    let _e51 = lighting.point_color;
    let _e53 = blinn(n_1, (to_point / vec3(dist)), v_1, _e51.xyz);
    let _e57 = c;
    c = (_e57 + ((albedo.xyz * _e53) * (falloff * falloff)));
    let _e60 = c;
    f_color = vec4<f32>(_e60, albedo.w);
    let _e63 = f_color;
    return cube_fs_out(_e63);
}
