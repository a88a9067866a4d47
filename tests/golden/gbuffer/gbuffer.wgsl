diagnostic(off, derivative_uniformity);

struct Frame {
    view: mat4x4<f32>,
    proj: mat4x4<f32>,
    near_far: vec4<f32>,
}

struct Surface {
    base_color: vec4<f32>,
    roughness: f32,
    metalness: f32,
    normal_scale: f32,
    alpha_cutoff: f32,
}

struct Uniforms {
    u_model: mat4x4<f32>,
}

struct gbuffer_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_view_pos: vec3<f32>,
    @location(1) v_normal: vec3<f32>,
    @location(2) v_tangent: vec4<f32>,
    @location(3) v_uv: vec2<f32>,
}

struct gbuffer_fs_out {
    @location(0) g_albedo: vec4<f32>,
    @location(1) g_normal: vec4<f32>,
    @location(2) g_position: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> frame: Frame;
@group(0) @binding(1) 
var<uniform> surface: Surface;
@group(0) @binding(2) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(3) 
var albedo_map: texture_2d<f32>;
@group(0) @binding(4) 
var albedo_map_sampler: sampler;
@group(0) @binding(5) 
var normal_map: texture_2d<f32>;
@group(0) @binding(6) 
var normal_map_sampler: sampler;
@group(0) @binding(7) 
var orm_map: texture_2d<f32>;
@group(0) @binding(8) 
var orm_map_sampler: sampler;

@vertex 
fn gbuffer_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>, @location(2) a_tangent: vec4<f32>, @location(3) a_uv: vec2<f32>) -> gbuffer_vs_out {
    var v_view_pos: vec3<f32>;
    var v_normal: vec3<f32>;
    var v_tangent: vec4<f32>;
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    let _e6 = frame.view;
    let _e9 = uniforms.u_model;
    let model_view = (_e6 * _e9);
    let p = (model_view * vec4<f32>(a_position, 1f));
    v_view_pos = p.xyz;
    v_normal = (model_view * vec4<f32>(a_normal, 0f)).xyz;
    v_tangent = vec4<f32>((model_view * vec4<f32>(a_tangent.xyz, 0f)).xyz, a_tangent.w);
    v_uv = a_uv;
    let _e31 = frame.proj;
    gl_Position = (_e31 * p);
    let _e33 = gl_Position;
    let _e43 = v_view_pos;
    let _e44 = v_normal;
    let _e45 = v_tangent;
    let _e46 = v_uv;
    return gbuffer_vs_out(vec4<f32>(_e33.x, -(_e33.y), ((_e33.z + _e33.w) * 0.5f), _e33.w), _e43, _e44, _e45, _e46);
}

@fragment 
fn gbuffer_fs(@location(0) v_view_pos_1: vec3<f32>, @location(1) v_normal_1: vec3<f32>, @location(2) v_tangent_1: vec4<f32>, @location(3) v_uv_1: vec2<f32>) -> gbuffer_fs_out {
    var g_albedo: vec4<f32>;
    var g_normal: vec4<f32>;
    var g_position: vec4<f32>;
    var tn: vec3<f32>;

    let _e6 = textureSample(albedo_map, albedo_map_sampler, v_uv_1);
    let _e9 = surface.base_color;
    let base = (_e6 * _e9);
    let _e13 = surface.alpha_cutoff;
    if (base.w < _e13) {
        discard;
    }
    let n = normalize(v_normal_1);
    let t = normalize((v_tangent_1.xyz - (n * dot(n, v_tangent_1.xyz))));
    let b = (cross(n, t) * v_tangent_1.w);
    let _e28 = textureSample(normal_map, normal_map_sampler, v_uv_1);
    tn = ((_e28.xyz * 2f) - vec3(1f));
    let _e35 = tn;
    let _e37 = surface.normal_scale;
    let _e39 = (_e35.xy * _e37);
    tn = vec3<f32>(_e39.x, _e39.y, _e35.z);
    let _e45 = tn;
    let mapped = normalize((mat3x3<f32>(t, b, n) * _e45));
    let orm = textureSample(orm_map, orm_map_sampler, v_uv_1);
    let _e56 = frame.near_far.x;
    let _e60 = frame.near_far.y;
    let _e63 = frame.near_far.x;
    let linear_depth = ((-(v_view_pos_1.z) - _e56) / (_e60 - _e63));
    let _e70 = surface.roughness;
    g_albedo = vec4<f32>(base.xyz, (orm.y * _e70));
    let _e80 = surface.metalness;
    g_normal = vec4<f32>(((mapped * 0.5f) + vec3(0.5f)), (orm.z * _e80));
    g_position = vec4<f32>(v_view_pos_1, linear_depth);
    let _e85 = g_albedo;
    let _e86 = g_normal;
    let _e87 = g_position;
    return gbuffer_fs_out(_e85, _e86, _e87);
}
