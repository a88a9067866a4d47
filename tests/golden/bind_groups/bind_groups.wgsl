diagnostic(off, derivative_uniformity);

struct material_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct material_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_view_proj: mat4x4<f32>;
@group(1) @binding(2) 
var<uniform> u_tint: vec4<f32>;
@group(1) @binding(0) 
var albedo: texture_2d<f32>;
@group(1) @binding(1) 
var albedo_sampler: sampler;
@group(0) @binding(1) 
var<uniform> u_model: mat4x4<f32>;

@vertex 
fn material_vs(@location(0) a_pos: vec3<f32>, @location(1) a_uv: vec2<f32>) -> material_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = a_uv;
    let _e5 = u_view_proj;
    let _e7 = u_model;
    gl_Position = ((_e5 * _e7) * vec4<f32>(a_pos, 1f));
    let _e13 = gl_Position;
    let _e24 = v_uv;
    return material_vs_out(vec4<f32>(_e13.x, -(_e13.y), ((_e13.z + _e13.w) * 0.5f), _e13.w), _e24);
}

@fragment 
fn material_fs(@location(0) v_uv_1: vec2<f32>) -> material_fs_out {
    var f_color: vec4<f32>;

    let _e4 = textureSample(albedo, albedo_sampler, v_uv_1);
    let _e6 = u_tint;
    f_color = (_e4 * _e6);
    let _e9 = f_color;
    return material_fs_out(_e9);
}
