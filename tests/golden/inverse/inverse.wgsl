diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view_proj: mat4x4<f32>,
}

struct inverse_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
    @location(1) v_view_pos: vec3<f32>,
}

struct inverse_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn inverse_3x3_(m: mat3x3<f32>) -> mat3x3<f32> {
    let _e5 = cross(m[1], m[2]);
    return (transpose(mat3x3<f32>(_e5, cross(m[2], m[0]), cross(m[0], m[1]))) * (1f / dot(m[0], _e5)));
}

fn inverse_4x4_(m_1: mat4x4<f32>) -> mat4x4<f32> {
    let _e6 = m_1[0].xyz;
    let _e7 = m_1[1].xyz;
    let _e8 = m_1[2].xyz;
    let _e9 = m_1[3].xyz;
    let _e14 = cross(_e6, _e7);
    let _e15 = cross(_e8, _e9);
    let _e18 = ((_e6 * m_1[1].w) - (_e7 * m_1[0].w));
    let _e21 = ((_e8 * m_1[3].w) - (_e9 * m_1[2].w));
    let _e25 = (1f / (dot(_e14, _e21) + dot(_e15, _e18)));
    let _e26 = (_e14 * _e25);
    let _e27 = (_e15 * _e25);
    let _e28 = (_e18 * _e25);
    let _e29 = (_e21 * _e25);
    return transpose(mat4x4<f32>(vec4<f32>((cross(_e7, _e29) + (_e27 * m_1[1].w)), -(dot(_e7, _e27))), vec4<f32>((cross(_e29, _e6) - (_e27 * m_1[0].w)), dot(_e6, _e27)), vec4<f32>((cross(_e9, _e28) + (_e26 * m_1[3].w)), -(dot(_e9, _e26))), vec4<f32>((cross(_e28, _e8) - (_e26 * m_1[2].w)), dot(_e8, _e26))));
}

@vertex 
fn inverse_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> inverse_vs_out {
    var v_normal: vec3<f32>;
    var v_view_pos: vec3<f32>;
    var gl_Position: vec4<f32>;

    let _e5 = uniforms.u_model[0];
    let _e9 = uniforms.u_model[1];
    let _e13 = uniforms.u_model[2];
    let upper = mat3x3<f32>(_e5.xyz, _e9.xyz, _e13.xyz);
    let _e16 = inverse_3x3_(upper);
    let normal_matrix = transpose(_e16);
    v_normal = normalize((normal_matrix * a_normal));
    let _e22 = uniforms.u_view_proj;
    let _e24 = uniforms.u_model;
    let clip = (_e22 * (_e24 * vec4<f32>(a_pos, 1f)));
    let _e30 = uniforms.u_view_proj;
    let _e31 = inverse_4x4_(_e30);
    let world = (_e31 * clip);
    v_view_pos = (world.xyz / vec3(world.w));
    gl_Position = clip;
    let _e39 = gl_Position;
    let _e49 = v_normal;
    let _e50 = v_view_pos;
    return inverse_vs_out(vec4<f32>(_e39.x, -(_e39.y), ((_e39.z + _e39.w) * 0.5f), _e39.w), _e49, _e50);
}

@fragment 
fn inverse_fs(@location(0) v_normal_1: vec3<f32>) -> inverse_fs_out {
    var f_color: vec4<f32>;

    f_color = vec4<f32>(((v_normal_1 * 0.5f) + vec3(0.5f)), 1f);
    let _e8 = f_color;
    return inverse_fs_out(_e8);
}
