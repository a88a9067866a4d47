diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_view_proj: mat4x4<f32>,
    u_model: mat4x4<f32>,
}

struct Set1Uniforms {
    u_tint: vec4<f32>,
}

struct material_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct material_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(1) @binding(2) 
var<uniform> set1_uniforms: Set1Uniforms;
@group(1) @binding(0) 
var albedo: texture_2d<f32>;
@group(1) @binding(1) 
var albedo_sampler: sampler;

@vertex 
fn material_vs(@location(0) a_pos: vec3<f32>, @location(1) a_uv: vec2<f32>) -> material_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = a_uv;
    let _e6 = uniforms.u_view_proj;
    let _e8 = uniforms.u_model;
    gl_Position = ((_e6 * _e8) * vec4<f32>(a_pos, 1f));
    let _e13 = gl_Position;
    let _e23 = v_uv;
    return material_vs_out(vec4<f32>(_e13.x, -(_e13.y), ((_e13.z + _e13.w) * 0.5f), _e13.w), _e23);
}

@fragment 
fn material_fs(@location(0) v_uv_1: vec2<f32>) -> material_fs_out {
    var f_color: vec4<f32>;

    let _e4 = textureSample(albedo, albedo_sampler, v_uv_1);
    let _e7 = set1_uniforms.u_tint;
    f_color = (_e4 * _e7);
    let _e9 = f_color;
    return material_fs_out(_e9);
}
