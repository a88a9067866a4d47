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
var<uniform> u_model: mat4x4<f32>;
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
var<private> a_position: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> a_tangent: vec4<f32>;
var<private> a_uv: vec2<f32>;
var<private> v_view_pos: vec3<f32>;
var<private> v_normal: vec3<f32>;
var<private> v_tangent: vec4<f32>;
var<private> v_uv: vec2<f32>;
var<private> g_albedo: vec4<f32>;
var<private> g_normal: vec4<f32>;
var<private> g_position: vec4<f32>;
var<private> gl_Position: vec4<f32>;

@vertex 
fn gbuffer_vs(@location(0) in_a_position: vec3<f32>, @location(1) in_a_normal: vec3<f32>, @location(2) in_a_tangent: vec4<f32>, @location(3) in_a_uv: vec2<f32>) -> gbuffer_vs_out {
    a_position = in_a_position;
    a_normal = in_a_normal;
    a_tangent = in_a_tangent;
    a_uv = in_a_uv;
    let _e10 = frame.view;
    let _e12 = u_model;
    let model_view = (_e10 * _e12);
    let _e15 = a_position;
    let p = (model_view * vec4<f32>(_e15, 1f));
    v_view_pos = p.xyz;
    let _e23 = a_normal;
    v_normal = (model_view * vec4<f32>(_e23, 0f)).xyz;
    let _e30 = a_tangent;
    let _e38 = a_tangent.w;
    v_tangent = vec4<f32>((model_view * vec4<f32>(_e30.xyz, 0f)).xyz, _e38);
    let _e42 = a_uv;
    v_uv = _e42;
    let _e46 = frame.proj;
    gl_Position = (_e46 * p);
    let _e49 = gl_Position;
    let _e60 = v_view_pos;
    let _e62 = v_normal;
    let _e64 = v_tangent;
    let _e66 = v_uv;
    return gbuffer_vs_out(vec4<f32>(_e49.x, -(_e49.y), ((_e49.z + _e49.w) * 0.5f), _e49.w), _e60, _e62, _e64, _e66);
}

@fragment 
fn gbuffer_fs(@location(0) in_v_view_pos: vec3<f32>, @location(1) in_v_normal: vec3<f32>, @location(2) in_v_tangent: vec4<f32>, @location(3) in_v_uv: vec2<f32>) -> gbuffer_fs_out {
    var tn: vec3<f32>;

    v_view_pos = in_v_view_pos;
    v_normal = in_v_normal;
    v_tangent = in_v_tangent;
    v_uv = in_v_uv;
    let _e9 = v_uv;
    let _e12 = textureSample(albedo_map, albedo_map_sampler, _e9);
    let _e15 = surface.base_color;
    let base = (_e12 * _e15);
    let _e20 = surface.alpha_cutoff;
    if (base.w < _e20) {
        discard;
    }
    let _e23 = v_normal;
    let n = normalize(_e23);
    let _e26 = v_tangent;
    let _e29 = v_tangent;
    let t = normalize((_e26.xyz - (n * dot(n, _e29.xyz))));
    let _e38 = v_tangent.w;
    let b = (cross(n, t) * _e38);
    let _e42 = v_uv;
    let _e45 = textureSample(normal_map, normal_map_sampler, _e42);
    tn = ((_e45.xyz * 2f) - vec3(1f));
    let _e53 = tn;
    let _e56 = surface.normal_scale;
    let _e58 = (_e53.xy * _e56);
    tn = vec3<f32>(_e58.x, _e58.y, _e53.z);
    let _e65 = tn;
    let mapped = normalize((mat3x3<f32>(t, b, n) * _e65));
    let _e69 = v_uv;
    let orm = textureSample(orm_map, orm_map_sampler, _e69);
    let _e75 = v_view_pos.z;
    let _e80 = frame.near_far.x;
    let _e85 = frame.near_far.y;
    let _e89 = frame.near_far.x;
    let linear_depth = ((-(_e75) - _e80) / (_e85 - _e89));
    let _e97 = surface.roughness;
    g_albedo = vec4<f32>(base.xyz, (orm.y * _e97));
    let _e109 = surface.metalness;
    g_normal = vec4<f32>(((mapped * 0.5f) + vec3(0.5f)), (orm.z * _e109));
    let _e114 = v_view_pos;
    g_position = vec4<f32>(_e114, linear_depth);
    let _e117 = g_albedo;
    let _e119 = g_normal;
    let _e121 = g_position;
    return gbuffer_fs_out(_e117, _e119, _e121);
}
