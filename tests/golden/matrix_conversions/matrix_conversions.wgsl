diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view_proj: mat4x4<f32>,
}

struct matrix_conversions_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
    @location(1) v_skew: vec2<f32>,
}

struct matrix_conversions_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn inverse_3x3_(m: mat3x3<f32>) -> mat3x3<f32> {
    let _e5 = cross(m[1], m[2]);
    return (transpose(mat3x3<f32>(_e5, cross(m[2], m[0]), cross(m[0], m[1]))) * (1f / dot(m[0], _e5)));
}

@vertex 
fn matrix_conversions_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> matrix_conversions_vs_out {
    var v_normal: vec3<f32>;
    var v_skew: vec2<f32>;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_model;
    let _e14 = inverse_3x3_(mat3x3<f32>(_e4[0].xyz, _e4[1].xyz, _e4[2].xyz));
    let normal_matrix = transpose(_e14);
    v_normal = (normal_matrix * a_normal);
    let _e19 = uniforms.u_model;
    let flat = mat2x2<f32>(_e19[0].xy, _e19[1].xy);
    let mirrored = mat2x2<f32>(-(flat[0]), -(flat[1]));
    let _e34 = uniforms.u_view_proj;
    v_skew = ((mirrored * a_pos.xy) + mat2x3<f32>(_e34[0].xyz, _e34[1].xyz)[1].xy);
    let _e44 = uniforms.u_model;
    let _e51 = mat3x3<f32>(_e44[0].xyz, _e44[1].xyz, _e44[2].xyz);
    let rotation_only = mat4x4<f32>(vec4<f32>(_e51[0].x, _e51[0].y, _e51[0].z, 0f), vec4<f32>(_e51[1].x, _e51[1].y, _e51[1].z, 0f), vec4<f32>(_e51[2].x, _e51[2].y, _e51[2].z, 0f), vec4<f32>(0f, 0f, 0f, 1f));
    let _e71 = uniforms.u_view_proj;
    gl_Position = ((_e71 * rotation_only) * vec4<f32>(a_pos, 1f));
    let _e75 = gl_Position;
    let _e85 = v_normal;
    let _e86 = v_skew;
    return matrix_conversions_vs_out(vec4<f32>(_e75.x, -(_e75.y), ((_e75.z + _e75.w) * 0.5f), _e75.w), _e85, _e86);
}

@fragment 
fn matrix_conversions_fs(@location(0) v_normal_1: vec3<f32>, @location(1) v_skew_1: vec2<f32>) -> matrix_conversions_fs_out {
    var f_color: vec4<f32>;

    let n = normalize(v_normal_1);
    let _e9 = (mat2x2<f32>(vec2<f32>(1f, 0f), vec2<f32>(0f, 1f)) * 0.5f);
    let m_1 = mat3x3<f32>(vec3<f32>(_e9[0].x, _e9[0].y, 0f), vec3<f32>(_e9[1].x, _e9[1].y, 0f), vec3<f32>(0f, 0f, 1f));
    f_color = (vec4<f32>((((m_1 * n) * 0.5f) + vec3(0.5f)), 1f) + vec4<f32>((v_skew_1 * 0f), 0f, 0f));
    let _e29 = f_color;
    return matrix_conversions_fs_out(_e29);
}
