diagnostic(off, derivative_uniformity);

struct gbuffer_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
    @location(1) v_uv: vec2<f32>,
    @location(2) v_depth: f32,
}

struct gbuffer_fs_out {
    @location(0) g_albedo: vec4<f32>,
    @location(1) g_normal: vec4<f32>,
    @location(2) g_depth: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_view_proj: mat4x4<f32>;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> a_uv: vec2<f32>;
var<private> v_normal: vec3<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_depth: f32;
var<private> g_albedo: vec4<f32>;
var<private> g_normal: vec4<f32>;
var<private> g_depth: vec4<f32>;
var<private> gl_VertexID: i32;
var<private> gl_InstanceID: i32;
var<private> gl_Position: vec4<f32>;
var<private> gl_FrontFacing: bool;
var<private> gl_FragCoord: vec4<f32>;

@vertex 
fn gbuffer_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_normal: vec3<f32>, @location(2) in_a_uv: vec2<f32>, @builtin(vertex_index) in_VertexID: u32, @builtin(instance_index) in_InstanceID: u32) -> gbuffer_vs_out {
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    a_uv = in_a_uv;
    gl_VertexID = i32(in_VertexID);
    gl_InstanceID = i32(in_InstanceID);
    let _e13 = u_view_proj;
    let _e15 = a_pos;
    let p = (_e13 * vec4<f32>(_e15, 1f));
    let _e21 = a_normal;
    v_normal = _e21;
    let _e24 = a_uv;
    let _e26 = gl_VertexID;
    let _e31 = gl_InstanceID;
    v_uv = (_e24 + vec2<f32>((f32(_e26) * 0f), (f32(_e31) * 0f)));
    v_depth = (p.z / p.w);
    gl_Position = p;
    let _e43 = gl_Position;
    let _e54 = v_normal;
    let _e56 = v_uv;
    let _e58 = v_depth;
    return gbuffer_vs_out(vec4<f32>(_e43.x, -(_e43.y), ((_e43.z + _e43.w) * 0.5f), _e43.w), _e54, _e56, _e58);
}

@fragment 
fn gbuffer_fs(@location(0) in_v_normal: vec3<f32>, @location(1) in_v_uv: vec2<f32>, @location(2) in_v_depth: f32, @builtin(front_facing) in_FrontFacing: bool, @builtin(position) in_FragCoord: vec4<f32>) -> gbuffer_fs_out {
    var n: vec3<f32>;

    v_normal = in_v_normal;
    v_uv = in_v_uv;
    v_depth = in_v_depth;
    gl_FrontFacing = in_FrontFacing;
    gl_FragCoord = in_FragCoord;
    let _e12 = v_uv.x;
    if (fract((_e12 * 8f)) < 0.1f) {
        discard;
    }
    let _e20 = v_normal;
    n = normalize(_e20);
    let _e23 = gl_FrontFacing;
    if !(_e23) {
        let _e27 = n;
        n = -(_e27);
    }
    let _e31 = v_uv;
    g_albedo = vec4<f32>(_e31, 0.5f, 1f);
    let _e37 = n;
    g_normal = vec4<f32>(((_e37 * 0.5f) + vec3(0.5f)), 1f);
    let _e47 = v_depth;
    let _e49 = v_depth;
    let _e50 = fwidth(_e49);
    let _e53 = gl_FragCoord.z;
    g_depth = vec4<f32>(_e47, _e50, _e53, 1f);
    let _e57 = g_albedo;
    let _e59 = g_normal;
    let _e61 = g_depth;
    return gbuffer_fs_out(_e57, _e59, _e61);
}
