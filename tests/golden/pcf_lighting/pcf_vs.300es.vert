#version 300 es

precision highp float;
precision highp int;

struct pcf_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec4 v_light_pos;
};
layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(std140) uniform u_light_view_proj_block { mat4x4 u_light_view_proj; };

vec3 a_position = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec4 v_light_pos = vec4(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec4 _vs2fs_location1;

void main() {
    vec3 in_a_position = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    a_position = in_a_position;
    a_normal = in_a_normal;
    mat4x4 _e5 = u_model;
    vec3 _e7 = a_position;
    vec4 world = (_e5 * vec4(_e7, 1.0));
    mat4x4 _e13 = u_model;
    vec3 _e15 = a_normal;
    v_normal = (_e13 * vec4(_e15, 0.0)).xyz;
    mat4x4 _e22 = u_light_view_proj;
    v_light_pos = (_e22 * world);
    mat4x4 _e26 = u_view_proj;
    gen_gl_Position = (_e26 * world);
    vec4 _e29 = gen_gl_Position;
    vec3 _e31 = v_normal;
    vec4 _e33 = v_light_pos;
    pcf_vs_out _tmp_return = pcf_vs_out(_e29, _e31, _e33);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    _vs2fs_location1 = _tmp_return.v_light_pos;
    return;
}

