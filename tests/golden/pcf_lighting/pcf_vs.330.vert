#version 330 core
struct pcf_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec4 v_light_pos;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view_proj;

uniform mat4x4 u_light_view_proj;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
out vec4 v_light_pos;

void main() {
    vec3 in_a_position = a_position;
    vec3 in_a_normal = a_normal;
    vec3 out_v_normal = vec3(0.0);
    vec4 out_v_light_pos = vec4(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(in_a_position, 1.0));
    mat4x4 _e8 = u_model;
    out_v_normal = (_e8 * vec4(in_a_normal, 0.0)).xyz;
    mat4x4 _e15 = u_light_view_proj;
    out_v_light_pos = (_e15 * world);
    mat4x4 _e19 = u_view_proj;
    gen_gl_Position = (_e19 * world);
    vec4 _e21 = gen_gl_Position;
    vec3 _e22 = out_v_normal;
    vec4 _e23 = out_v_light_pos;
    pcf_vs_out _tmp_return = pcf_vs_out(_e21, _e22, _e23);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    v_light_pos = _tmp_return.v_light_pos;
    return;
}

