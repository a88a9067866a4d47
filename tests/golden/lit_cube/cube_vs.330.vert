#version 330 core
struct Camera {
    mat4x4 view_proj;
    vec3 position;
    float time;
};
struct cube_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world;
    vec3 v_normal;
    vec2 v_uv;
};
layout(std140) uniform camera_block { Camera camera; };

layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_normal_matrix_block { mat3x3 u_normal_matrix; };

vec3 a_position = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec2 a_uv = vec2(0.0);

vec3 v_world = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec2 v_uv = vec2(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec2 _p2vs_location2;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec2 _vs2fs_location2;

void main() {
    vec3 in_a_position = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    vec2 in_a_uv = _p2vs_location2;
    a_position = in_a_position;
    a_normal = in_a_normal;
    a_uv = in_a_uv;
    mat4x4 _e7 = u_model;
    vec3 _e9 = a_position;
    vec4 world = (_e7 * vec4(_e9, 1.0));
    v_world = world.xyz;
    mat3x3 _e17 = u_normal_matrix;
    vec3 _e19 = a_normal;
    v_normal = (_e17 * _e19);
    vec2 _e23 = a_uv;
    v_uv = _e23;
    mat4x4 _e27 = camera.view_proj;
    gen_gl_Position = (_e27 * world);
    vec4 _e30 = gen_gl_Position;
    vec3 _e32 = v_world;
    vec3 _e34 = v_normal;
    vec2 _e36 = v_uv;
    cube_vs_out _tmp_return = cube_vs_out(_e30, _e32, _e34, _e36);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_world;
    _vs2fs_location1 = _tmp_return.v_normal;
    _vs2fs_location2 = _tmp_return.v_uv;
    return;
}

