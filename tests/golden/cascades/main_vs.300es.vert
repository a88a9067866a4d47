#version 300 es

precision highp float;
precision highp int;

struct main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
};
layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_view_block { mat4x4 u_view; };

layout(std140) uniform u_proj_block { mat4x4 u_proj; };

vec3 a_pos = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec3 v_world_pos = vec3(0.0);

vec3 v_world_normal = vec3(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    mat4x4 _e5 = u_model;
    vec3 _e7 = a_pos;
    vec4 world = (_e5 * vec4(_e7, 1.0));
    v_world_pos = world.xyz;
    mat4x4 _e15 = u_model;
    vec3 _e17 = a_normal;
    v_world_normal = (_e15 * vec4(_e17, 0.0)).xyz;
    mat4x4 _e24 = u_proj;
    mat4x4 _e26 = u_view;
    gen_gl_Position = (_e24 * (_e26 * world));
    vec4 _e30 = gen_gl_Position;
    vec3 _e32 = v_world_pos;
    vec3 _e34 = v_world_normal;
    main_vs_out _tmp_return = main_vs_out(_e30, _e32, _e34);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_world_pos;
    _vs2fs_location1 = _tmp_return.v_world_normal;
    return;
}

