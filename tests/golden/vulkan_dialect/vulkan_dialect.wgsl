diagnostic(off, derivative_uniformity);

struct Frame {
    view_proj: mat4x4<f32>,
    tint: vec4<f32>,
}

struct Model {
    model: mat4x4<f32>,
    layer: i32,
}

struct lit_vert_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_depth: f32,
    @location(2) @interpolate(flat) v_layer: i32,
    @location(3) @interpolate(flat) v_weight: f32,
}

struct lit_frag_out {
    @location(0) o_color: vec4<f32>,
}

struct depth_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> frame: Frame;
@group(0) @binding(2) 
var<uniform> model: Model;
@group(0) @binding(1) 
var albedo: texture_2d<f32>;
@group(0) @binding(3) 
var albedo_sampler: sampler;
@group(1) @binding(0) 
var shadow: texture_depth_2d;
@group(1) @binding(1) 
var shadow_sampler: sampler_comparison;

@vertex 
fn lit_vert(@location(0) a_pos: vec3<f32>, @location(1) a_uv: vec2<f32>, @builtin(vertex_index) VertexID: u32) -> lit_vert_out {
    var v_uv: vec2<f32>;
    var v_depth: f32;
    var v_layer: i32;
    var v_weight: f32;
    var gl_Position: vec4<f32>;

    let _e6 = model.model;
    let world = (_e6 * vec4<f32>(a_pos, 1f));
    let _e13 = frame.view_proj;
    gl_Position = (_e13 * world);
    v_uv = a_uv;
    let _e18 = gl_Position.z;
    let _e20 = gl_Position.w;
    v_depth = (_e18 / _e20);
    let _e24 = model.layer;
    v_layer = _e24;
    v_weight = f32((i32(VertexID) % 3i));
    let _e29 = gl_Position;
    let _e36 = v_uv;
    let _e37 = v_depth;
    let _e38 = v_layer;
    let _e39 = v_weight;
    return lit_vert_out(vec4<f32>(_e29.x, -(_e29.y), _e29.z, _e29.w), _e36, _e37, _e38, _e39);
}

@fragment 
fn lit_frag(@location(0) f_uv: vec2<f32>, @location(1) f_depth: f32, @location(2) @interpolate(flat) f_layer: i32, @location(3) @interpolate(flat) f_weight: f32) -> lit_frag_out {
    var o_color: vec4<f32>;

    let lit = textureSampleCompare(shadow, shadow_sampler, f_uv, f_depth);
    let _e9 = textureSample(albedo, albedo_sampler, f_uv);
    let _e12 = frame.tint;
    let c = (_e9 * _e12);
    o_color = vec4<f32>(((c.xyz * lit) * f_weight), f32(f_layer));
    let _e20 = o_color;
    return lit_frag_out(_e20);
}

@vertex 
fn depth_vs(@location(0) a_pos_1: vec3<f32>) -> depth_vs_out {
    var gl_Position_1: vec4<f32>;

    let _e4 = frame.view_proj;
    let _e7 = model.model;
    gl_Position_1 = ((_e4 * _e7) * vec4<f32>(a_pos_1, 1f));
    let _e12 = gl_Position_1;
    return depth_vs_out(vec4<f32>(_e12.x, -(_e12.y), _e12.z, _e12.w));
}
