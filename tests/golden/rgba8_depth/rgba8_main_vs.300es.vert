#version 300 es

precision highp float;
precision highp int;

struct rgba8_main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view;

uniform mat4x4 u_proj;

vec3 io_a_pos = vec3(0.0);

vec3 io_a_normal = vec3(0.0);

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_world_pos;
out vec3 v_world_normal;

vec4 world_position() {
    mat4x4 _e1 = u_model;
    vec3 _e3 = io_a_pos;
    return (_e1 * vec4(_e3, 1.0));
}

vec3 world_normal() {
    mat4x4 _e1 = u_model;
    vec3 _e3 = io_a_normal;
    return (_e1 * vec4(_e3, 0.0)).xyz;
}

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_world_pos = vec3(0.0);
    vec3 out_v_world_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    io_a_pos = in_a_pos;
    io_a_normal = in_a_normal;
    vec4 _e4 = world_position();
    out_v_world_pos = _e4.xyz;
    vec3 _e8 = world_normal();
    out_v_world_normal = _e8;
    mat4x4 _e11 = u_proj;
    mat4x4 _e13 = u_view;
    gen_gl_Position = (_e11 * (_e13 * _e4));
    vec4 _e16 = gen_gl_Position;
    vec3 _e17 = out_v_world_pos;
    vec3 _e18 = out_v_world_normal;
    rgba8_main_vs_out _tmp_return = rgba8_main_vs_out(_e16, _e17, _e18);
    gl_Position = _tmp_return.gen_gl_Position;
    v_world_pos = _tmp_return.v_world_pos;
    v_world_normal = _tmp_return.v_world_normal;
    return;
}

