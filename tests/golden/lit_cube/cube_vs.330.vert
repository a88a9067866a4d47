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

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec2 _p2vs_location2;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec2 _vs2fs_location2;

void main() {
    vec3 a_position = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec2 a_uv = _p2vs_location2;
    vec3 v_world = vec3(0.0);
    vec3 v_normal = vec3(0.0);
    vec2 v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e4 = u_model;
    vec4 world = (_e4 * vec4(a_position, 1.0));
    v_world = world.xyz;
    mat3x3 _e12 = u_normal_matrix;
    v_normal = (_e12 * a_normal);
    v_uv = a_uv;
    mat4x4 _e18 = camera.view_proj;
    gen_gl_Position = (_e18 * world);
    vec4 _e21 = gen_gl_Position;
    vec3 _e23 = v_world;
    vec3 _e25 = v_normal;
    vec2 _e27 = v_uv;
    cube_vs_out _tmp_return = cube_vs_out(_e21, _e23, _e25, _e27);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_world;
    _vs2fs_location1 = _tmp_return.v_normal;
    _vs2fs_location2 = _tmp_return.v_uv;
    return;
}

