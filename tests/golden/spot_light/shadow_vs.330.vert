#version 330 core
struct shadow_vs_out {
    vec4 gen_gl_Position;
};
layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_light_vp_block { mat4x4 u_light_vp; };

vec3 a_pos = vec3(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    mat4x4 _e4 = u_light_vp;
    mat4x4 _e6 = u_model;
    vec3 _e8 = a_pos;
    gen_gl_Position = (_e4 * (_e6 * vec4(_e8, 1.0)));
    vec4 _e14 = gen_gl_Position;
    shadow_vs_out _tmp_return = shadow_vs_out(_e14);
    gl_Position = _tmp_return.gen_gl_Position;
    return;
}

