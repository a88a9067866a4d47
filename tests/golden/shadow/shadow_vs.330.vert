#version 330 core
struct shadow_vs_out {
    vec4 gen_gl_Position;
};
uniform mat4x4 u_light_vp;

uniform mat4x4 u_model;

layout(location = 0) in vec3 a_pos;

void main() {
    vec3 in_a_pos = a_pos;
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_light_vp;
    mat4x4 _e5 = u_model;
    gen_gl_Position = (_e3 * (_e5 * vec4(in_a_pos, 1.0)));
    vec4 _e10 = gen_gl_Position;
    shadow_vs_out _tmp_return = shadow_vs_out(_e10);
    gl_Position = _tmp_return.gen_gl_Position;
    return;
}

