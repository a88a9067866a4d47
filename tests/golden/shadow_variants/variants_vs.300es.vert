#version 300 es

precision highp float;
precision highp int;

struct variants_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec3 v_world;
    vec4 v_light_pos;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view_proj;

uniform mat4x4 u_light_view_proj;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
out vec3 v_world;
out vec4 v_light_pos;

void main() {
    vec3 in_a_position = a_position;
    vec3 in_a_normal = a_normal;
    vec3 out_v_normal = vec3(0.0);
    vec3 out_v_world = vec3(0.0);
    vec4 out_v_light_pos = vec4(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(in_a_position, 1.0));
    out_v_world = world.xyz;
    mat4x4 _e10 = u_model;
    out_v_normal = (_e10 * vec4(in_a_normal, 0.0)).xyz;
    mat4x4 _e17 = u_light_view_proj;
    out_v_light_pos = (_e17 * world);
    mat4x4 _e21 = u_view_proj;
    gen_gl_Position = (_e21 * world);
    vec4 _e23 = gen_gl_Position;
    vec3 _e24 = out_v_normal;
    vec3 _e25 = out_v_world;
    vec4 _e26 = out_v_light_pos;
    variants_vs_out _tmp_return = variants_vs_out(_e23, _e24, _e25, _e26);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    v_world = _tmp_return.v_world;
    v_light_pos = _tmp_return.v_light_pos;
    return;
}

