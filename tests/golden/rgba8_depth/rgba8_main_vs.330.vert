#version 330 core
struct rgba8_main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
};
layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_view_block { mat4x4 u_view; };

layout(std140) uniform u_proj_block { mat4x4 u_proj; };

vec3 a_pos = vec3(0.0);

vec3 a_normal = vec3(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;

vec4 world_position() {
    mat4x4 _e1 = u_model;
    vec3 _e3 = a_pos;
    return (_e1 * vec4(_e3, 1.0));
}

vec3 world_normal() {
    mat4x4 _e1 = u_model;
    vec3 _e3 = a_normal;
    return (_e1 * vec4(_e3, 0.0)).xyz;
}

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    vec3 v_world_pos = vec3(0.0);
    vec3 v_world_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    vec4 _e4 = world_position();
    v_world_pos = _e4.xyz;
    vec3 _e8 = world_normal();
    v_world_normal = _e8;
    mat4x4 _e11 = u_proj;
    mat4x4 _e13 = u_view;
    gen_gl_Position = (_e11 * (_e13 * _e4));
    vec4 _e17 = gen_gl_Position;
    vec3 _e19 = v_world_pos;
    vec3 _e21 = v_world_normal;
    rgba8_main_vs_out _tmp_return = rgba8_main_vs_out(_e17, _e19, _e21);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_world_pos;
    _vs2fs_location1 = _tmp_return.v_world_normal;
    return;
}

