#version 330 core
struct variants_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec3 v_world;
    vec4 v_light_pos;
};
layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(std140) uniform u_light_view_proj_block { mat4x4 u_light_view_proj; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec4 _vs2fs_location2;

void main() {
    vec3 a_position = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec3 v_normal = vec3(0.0);
    vec3 v_world = vec3(0.0);
    vec4 v_light_pos = vec4(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(a_position, 1.0));
    v_world = world.xyz;
    mat4x4 _e11 = u_model;
    v_normal = (_e11 * vec4(a_normal, 0.0)).xyz;
    mat4x4 _e18 = u_light_view_proj;
    v_light_pos = (_e18 * world);
    mat4x4 _e22 = u_view_proj;
    gen_gl_Position = (_e22 * world);
    vec4 _e25 = gen_gl_Position;
    vec3 _e27 = v_normal;
    vec3 _e29 = v_world;
    vec4 _e31 = v_light_pos;
    variants_vs_out _tmp_return = variants_vs_out(_e25, _e27, _e29, _e31);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    _vs2fs_location1 = _tmp_return.v_world;
    _vs2fs_location2 = _tmp_return.v_light_pos;
    return;
}

