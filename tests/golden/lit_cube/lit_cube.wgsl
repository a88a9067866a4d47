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
var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(4) 
var<uniform> u_normal_matrix: mat3x3<f32>;
@group(0) @binding(5) 
var diffuse_map: texture_2d<f32>;
@group(0) @binding(6) 
var diffuse_map_sampler: sampler;
var<private> a_position: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> a_uv: vec2<f32>;
var<private> v_world: vec3<f32>;
var<private> v_normal: vec3<f32>;
var<private> v_uv: vec2<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;
var<private> gl_FrontFacing: bool;

fn blinn(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, color: vec3<f32>) -> vec3<f32> {
    let h = normalize((l + v));
    let diffuse = max(dot(n, l), 0f);
    let _e16 = material.shininess;
    let spec = select(0f, pow(max(dot(n, h), 0f), _e16), (diffuse > 0f));
    let _e23 = material.specular;
    return ((color * diffuse) + ((_e23 * color) * spec));
}

@vertex 
fn cube_vs(@location(0) in_a_position: vec3<f32>, @location(1) in_a_normal: vec3<f32>, @location(2) in_a_uv: vec2<f32>) -> cube_vs_out {
    a_position = in_a_position;
    a_normal = in_a_normal;
    a_uv = in_a_uv;
    let _e7 = u_model;
    let _e9 = a_position;
    let world = (_e7 * vec4<f32>(_e9, 1f));
    v_world = world.xyz;
    let _e17 = u_normal_matrix;
    let _e19 = a_normal;
    v_normal = (_e17 * _e19);
    let _e23 = a_uv;
    v_uv = _e23;
    let _e27 = camera.view_proj;
    gl_Position = (_e27 * world);
    let _e30 = gl_Position;
    let _e41 = v_world;
    let _e43 = v_normal;
    let _e45 = v_uv;
    return cube_vs_out(vec4<f32>(_e30.x, -(_e30.y), ((_e30.z + _e30.w) * 0.5f), _e30.w), _e41, _e43, _e45);
}

@fragment 
fn cube_fs(@location(0) in_v_world: vec3<f32>, @location(1) in_v_normal: vec3<f32>, @location(2) in_v_uv: vec2<f32>, @builtin(front_facing) in_FrontFacing: bool) -> cube_fs_out {
    var c: vec3<f32>;

    v_world = in_v_world;
    v_normal = in_v_normal;
    v_uv = in_v_uv;
    gl_FrontFacing = in_FrontFacing;
    let _e9 = v_uv;
    let _e12 = textureSample(diffuse_map, diffuse_map_sampler, _e9);
    let _e15 = material.tint;
    let albedo = (_e12 * _e15);
    let _e18 = gl_FrontFacing;
    let _e20 = v_normal;
    let _e22 = v_normal;
    let n_1 = normalize(select(-(_e22), _e20, _e18));
    let _e28 = camera.position;
    let _e30 = v_world;
    let v_1 = normalize((_e28 - _e30));
    let _e37 = lighting.ambient;
    c = (albedo.xyz * _e37);
    let _e43 = lighting.sun_dir;
    let _e48 = lighting.sun_color;
    let _e50 = blinn(n_1, normalize(-(_e43)), v_1, _e48.xyz);
    let _e52 = c;
    c = (_e52 + (albedo.xyz * _e50));
    let _e56 = lighting.point_pos;
    let _e58 = v_world;
    let to_point = (_e56 - _e58);
    let dist = length(to_point);
    let _e64 = lighting.point_range;
    let falloff = saturate((1f - (dist / _e64)));
    let _e74 = lighting.point_color;
    let _e76 = blinn(n_1, (to_point / vec3(dist)), v_1, _e74.xyz);
    let _e80 = c;
    c = (_e80 + ((albedo.xyz * _e76) * (falloff * falloff)));
    let _e84 = c;
    f_color = vec4<f32>(_e84, albedo.w);
    let _e88 = f_color;
    return cube_fs_out(_e88);
}
