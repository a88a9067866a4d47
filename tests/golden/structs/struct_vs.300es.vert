#version 300 es

precision highp float;
precision highp int;

struct struct_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
};
uniform mat4x4 u_mvp;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_normal = in_a_normal;
    mat4x4 _e5 = u_mvp;
    gen_gl_Position = (_e5 * vec4(in_a_pos, 1.0));
    vec4 _e9 = gen_gl_Position;
    vec3 _e10 = out_v_normal;
    struct_vs_out _tmp_return = struct_vs_out(_e9, _e10);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    return;
}

