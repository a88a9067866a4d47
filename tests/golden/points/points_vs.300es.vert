#version 300 es

precision highp float;
precision highp int;

struct points_vs_out {
    vec4 gen_gl_Position;
    float gen_gl_PointSize;
};
layout(std140) uniform u_size_block { float u_size; };

vec3 a_pos = vec3(0.0);

float gen_gl_PointSize = 0.0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    float _e4 = u_size;
    float _e7 = a_pos.z;
    gen_gl_PointSize = (_e4 / max(_e7, 0.1));
    vec3 _e13 = a_pos;
    gen_gl_Position = vec4(_e13, 1.0);
    vec4 _e17 = gen_gl_Position;
    float _e19 = gen_gl_PointSize;
    points_vs_out _tmp_return = points_vs_out(_e17, _e19);
    gl_Position = _tmp_return.gen_gl_Position;
    gl_PointSize = _tmp_return.gen_gl_PointSize;
    return;
}

