#version 300 es

precision highp float;
precision highp int;

struct matrix_conversions_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec2 v_skew;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view_proj;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
out vec2 v_skew;

mat3x3 inverse_3x3_(mat3x3 m) {
    vec3 _e5 = cross(m[1], m[2]);
    return (transpose(mat3x3(_e5, cross(m[2], m[0]), cross(m[0], m[1]))) * (1.0 / dot(m[0], _e5)));
}

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_normal = vec3(0.0);
    vec2 out_v_skew = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    mat3x3 _e13 = inverse_3x3_(mat3x3(_e3[0].xyz, _e3[1].xyz, _e3[2].xyz));
    mat3x3 normal_matrix = transpose(_e13);
    out_v_normal = (normal_matrix * in_a_normal);
    mat4x4 _e17 = u_model;
    mat2x2 flat_ = mat2x2(_e17[0].xy, _e17[1].xy);
    mat2x2 mirrored = mat2x2(-(flat_[0]), -(flat_[1]));
    mat4x4 _e32 = u_view_proj;
    out_v_skew = ((mirrored * in_a_pos.xy) + mat2x3(_e32[0].xyz, _e32[1].xyz)[1].xy);
    mat4x4 _e41 = u_model;
    mat3x3 _e48 = mat3x3(_e41[0].xyz, _e41[1].xyz, _e41[2].xyz);
    mat4x4 rotation_only = mat4x4(vec4(_e48[0].x, _e48[0].y, _e48[0].z, 0.0), vec4(_e48[1].x, _e48[1].y, _e48[1].z, 0.0), vec4(_e48[2].x, _e48[2].y, _e48[2].z, 0.0), vec4(0.0, 0.0, 0.0, 1.0));
    mat4x4 _e67 = u_view_proj;
    gen_gl_Position = ((_e67 * rotation_only) * vec4(in_a_pos, 1.0));
    vec4 _e71 = gen_gl_Position;
    vec3 _e72 = out_v_normal;
    vec2 _e73 = out_v_skew;
    matrix_conversions_vs_out _tmp_return = matrix_conversions_vs_out(_e71, _e72, _e73);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    v_skew = _tmp_return.v_skew;
    return;
}

