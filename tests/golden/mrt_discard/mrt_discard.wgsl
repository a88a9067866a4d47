diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_view_proj: mat4x4<f32>,
}

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
var<uniform> uniforms: Uniforms;

@vertex 
fn gbuffer_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>, @location(2) a_uv: vec2<f32>, @builtin(vertex_index) VertexID: u32, @builtin(instance_index) InstanceID: u32) -> gbuffer_vs_out {
    var v_normal: vec3<f32>;
    var v_uv: vec2<f32>;
    var v_depth: f32;
    var gl_Position: vec4<f32>;

    let _e9 = uniforms.u_view_proj;
    let p = (_e9 * vec4<f32>(a_pos, 1f));
    v_normal = a_normal;
    v_uv = (a_uv + vec2<f32>((f32(i32(VertexID)) * 0f), (f32(i32(InstanceID)) * 0f)));
    v_depth = (p.z / p.w);
    gl_Position = p;
    let _e27 = gl_Position;
    let _e37 = v_normal;
    let _e38 = v_uv;
    let _e39 = v_depth;
    return gbuffer_vs_out(vec4<f32>(_e27.x, -(_e27.y), ((_e27.z + _e27.w) * 0.5f), _e27.w), _e37, _e38, _e39);
}

@fragment 
fn gbuffer_fs(@location(0) v_normal_1: vec3<f32>, @location(1) v_uv_1: vec2<f32>, @location(2) v_depth_1: f32, @builtin(front_facing) FrontFacing: bool, @builtin(position) FragCoord: vec4<f32>) -> gbuffer_fs_out {
    var g_albedo: vec4<f32>;
    var g_normal: vec4<f32>;
    var g_depth: vec4<f32>;
    var n: vec3<f32>;

    if (fract((v_uv_1.x * 8f)) < 0.1f) {
        discard;
    }
    n = normalize(v_normal_1);
    if !(FrontFacing) {
        let _e14 = n;
        n = -(_e14);
    }
    g_albedo = vec4<f32>(v_uv_1, 0.5f, 1f);
    let _e21 = n;
    g_normal = vec4<f32>(((_e21 * 0.5f) + vec3(0.5f)), 1f);
    let _e27 = fwidth(v_depth_1);
    g_depth = vec4<f32>(v_depth_1, _e27, FragCoord.z, 1f);
    let _e30 = g_albedo;
    let _e31 = g_normal;
    let _e32 = g_depth;
    return gbuffer_fs_out(_e30, _e31, _e32);
}
