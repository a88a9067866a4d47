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
layout(std140) uniform camera_ubo {
    mat4x4 view_proj;
    vec3 position;
    float time;
} camera;

uniform mat4x4 u_model;

uniform mat3x3 u_normal_matrix;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;

void main() {
    vec3 in_a_position = a_position;
    vec3 in_a_normal = a_normal;
    vec2 in_a_uv = a_uv;
    vec3 out_v_world = vec3(0.0);
    vec3 out_v_normal = vec3(0.0);
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e4 = u_model;
    vec4 world = (_e4 * vec4(in_a_position, 1.0));
    out_v_world = world.xyz;
    mat3x3 _e12 = u_normal_matrix;
    out_v_normal = (_e12 * in_a_normal);
    out_v_uv = in_a_uv;
    mat4x4 _e18 = camera.view_proj;
    gen_gl_Position = (_e18 * world);
    vec4 _e20 = gen_gl_Position;
    vec3 _e21 = out_v_world;
    vec3 _e22 = out_v_normal;
    vec2 _e23 = out_v_uv;
    cube_vs_out _tmp_return = cube_vs_out(_e20, _e21, _e22, _e23);
    gl_Position = _tmp_return.gen_gl_Position;
    v_world = _tmp_return.v_world;
    v_normal = _tmp_return.v_normal;
    v_uv = _tmp_return.v_uv;
    return;
}

