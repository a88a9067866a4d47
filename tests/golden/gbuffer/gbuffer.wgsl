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
    let _e33 = frame.proj;
    gl_Position = (_e33 * p);
    let _e36 = gl_Position;
    let _e47 = v_view_pos;
    let _e49 = v_normal;
    let _e51 = v_tangent;
    let _e53 = v_uv;
    return gbuffer_vs_out(vec4<f32>(_e36.x, -(_e36.y), ((_e36.z + _e36.w) * 0.5f), _e36.w), _e47, _e49, _e51, _e53);
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
    let _e14 = surface.alpha_cutoff;
    if (base.w < _e14) {
        discard;
    }
    let n = normalize(v_normal_1);
    let t = normalize((v_tangent_1.xyz - (n * dot(n, v_tangent_1.xyz))));
    let b = (cross(n, t) * v_tangent_1.w);
    let _e29 = textureSample(normal_map, normal_map_sampler, v_uv_1);
    tn = ((_e29.xyz * 2f) - vec3(1f));
    let _e37 = tn;
    let _e40 = surface.normal_scale;
    let _e42 = (_e37.xy * _e40);
    tn = vec3<f32>(_e42.x, _e42.y, _e37.z);
    let _e49 = tn;
    let mapped = normalize((mat3x3<f32>(t, b, n) * _e49));
    let orm = textureSample(orm_map, orm_map_sampler, v_uv_1);
    let _e60 = frame.near_far.x;
    let _e65 = frame.near_far.y;
    let _e69 = frame.near_far.x;
    let linear_depth = ((-(v_view_pos_1.z) - _e60) / (_e65 - _e69));
    let _e77 = surface.roughness;
    g_albedo = vec4<f32>(base.xyz, (orm.y * _e77));
    let _e89 = surface.metalness;
    g_normal = vec4<f32>(((mapped * 0.5f) + vec3(0.5f)), (orm.z * _e89));
    g_position = vec4<f32>(v_view_pos_1, linear_depth);
    let _e95 = g_albedo;
    let _e97 = g_normal;
    let _e99 = g_position;
    return gbuffer_fs_out(_e95, _e97, _e99);
}
