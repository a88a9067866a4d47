#version 330 core
struct inverse_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec3 v_view_pos;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view_proj;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
out vec3 v_view_pos;

mat3x3 inverse_3x3_(mat3x3 m) {
    vec3 _e5 = cross(m[1], m[2]);
    return (transpose(mat3x3(_e5, cross(m[2], m[0]), cross(m[0], m[1]))) * (1.0 / dot(m[0], _e5)));
}

mat4x4 inverse_4x4_(mat4x4 m_1) {
    vec3 _e6 = m_1[0].xyz;
    vec3 _e7 = m_1[1].xyz;
    vec3 _e8 = m_1[2].xyz;
    vec3 _e9 = m_1[3].xyz;
    vec3 _e14 = cross(_e6, _e7);
    vec3 _e15 = cross(_e8, _e9);
    vec3 _e18 = ((_e6 * m_1[1].w) - (_e7 * m_1[0].w));
    vec3 _e21 = ((_e8 * m_1[3].w) - (_e9 * m_1[2].w));
    float _e25 = (1.0 / (dot(_e14, _e21) + dot(_e15, _e18)));
    vec3 _e26 = (_e14 * _e25);
    vec3 _e27 = (_e15 * _e25);
    vec3 _e28 = (_e18 * _e25);
    vec3 _e29 = (_e21 * _e25);
    return transpose(mat4x4(vec4((cross(_e7, _e29) + (_e27 * m_1[1].w)), -(dot(_e7, _e27))), vec4((cross(_e29, _e6) - (_e27 * m_1[0].w)), dot(_e6, _e27)), vec4((cross(_e9, _e28) + (_e26 * m_1[3].w)), -(dot(_e9, _e26))), vec4((cross(_e28, _e8) - (_e26 * m_1[2].w)), dot(_e8, _e26))));
}

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_normal = vec3(0.0);
    vec3 out_v_view_pos = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    vec4 _e4 = u_model[0];
    vec4 _e7 = u_model[1];
    vec4 _e10 = u_model[2];
    mat3x3 upper = mat3x3(_e4.xyz, _e7.xyz, _e10.xyz);
    mat3x3 _e13 = inverse_3x3_(upper);
    mat3x3 normal_matrix = transpose(_e13);
    out_v_normal = normalize((normal_matrix * in_a_normal));
    mat4x4 _e19 = u_view_proj;
    mat4x4 _e20 = u_model;
    vec4 clip = (_e19 * (_e20 * vec4(in_a_pos, 1.0)));
    mat4x4 _e25 = u_view_proj;
    mat4x4 _e26 = inverse_4x4_(_e25);
    vec4 world = (_e26 * clip);
    out_v_view_pos = (world.xyz / vec3(world.w));
    gen_gl_Position = clip;
    vec4 _e34 = gen_gl_Position;
    vec3 _e35 = out_v_normal;
    vec3 _e36 = out_v_view_pos;
    inverse_vs_out _tmp_return = inverse_vs_out(_e34, _e35, _e36);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    v_view_pos = _tmp_return.v_view_pos;
    return;
}

