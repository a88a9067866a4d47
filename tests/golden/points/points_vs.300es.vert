#version 300 es

precision highp float;
precision highp int;

struct points_vs_out {
    vec4 gen_gl_Position;
    float gen_gl_PointSize;
};
uniform float u_size;

layout(location = 0) in vec3 a_pos;

void main() {
    vec3 in_a_pos = a_pos;
    float gen_gl_PointSize = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    float _e3 = u_size;
    gen_gl_PointSize = (_e3 / max(in_a_pos.z, 0.1));
    gen_gl_Position = vec4(in_a_pos, 1.0);
    vec4 _e11 = gen_gl_Position;
    float _e12 = gen_gl_PointSize;
    points_vs_out _tmp_return = points_vs_out(_e11, _e12);
    gl_Position = _tmp_return.gen_gl_Position;
    gl_PointSize = _tmp_return.gen_gl_PointSize;
    return;
}

