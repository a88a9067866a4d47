#version 300 es

precision highp float;
precision highp int;

struct main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
    vec4 v_light_space;
};
layout(std140) uniform u_light_vp_block { mat4x4 u_light_vp; };

layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_view_block { mat4x4 u_view; };

layout(std140) uniform u_proj_block { mat4x4 u_proj; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec4 _vs2fs_location2;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec3 v_world_pos = vec3(0.0);
    vec3 v_world_normal = vec3(0.0);
    vec4 v_light_space = vec4(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(a_pos, 1.0));
    v_world_pos = world.xyz;
    mat4x4 _e11 = u_model;
    v_world_normal = (_e11 * vec4(a_normal, 0.0)).xyz;
    mat4x4 _e18 = u_light_vp;
    v_light_space = (_e18 * world);
    mat4x4 _e22 = u_proj;
    mat4x4 _e24 = u_view;
    gen_gl_Position = (_e22 * (_e24 * world));
    vec4 _e28 = gen_gl_Position;
    vec3 _e30 = v_world_pos;
    vec3 _e32 = v_world_normal;
    vec4 _e34 = v_light_space;
    main_vs_out _tmp_return = main_vs_out(_e28, _e30, _e32, _e34);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_world_pos;
    _vs2fs_location1 = _tmp_return.v_world_normal;
    _vs2fs_location2 = _tmp_return.v_light_space;
    return;
}

