#version 300 es

precision highp float;
precision highp int;

struct proj_shadow_vs_out {
    vec4 gen_gl_Position;
};
uniform mat4x4 u_model;

uniform mat4x4 u_light_vp;

vec3 io_a_pos = vec3(0.0);

layout(location = 0) in vec3 a_pos;

vec4 shadow_clip() {
    mat4x4 _e1 = u_light_vp;
    mat4x4 _e3 = u_model;
    vec3 _e5 = io_a_pos;
    return (_e1 * (_e3 * vec4(_e5, 1.0)));
}

void main() {
    vec3 in_a_pos = a_pos;
    vec4 gen_gl_Position = vec4(0.0);
    io_a_pos = in_a_pos;
    vec4 _e3 = shadow_clip();
    gen_gl_Position = _e3;
    vec4 _e4 = gen_gl_Position;
    proj_shadow_vs_out _tmp_return = proj_shadow_vs_out(_e4);
    gl_Position = _tmp_return.gen_gl_Position;
    return;
}

