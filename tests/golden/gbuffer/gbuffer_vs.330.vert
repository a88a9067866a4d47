#version 330 core
struct Frame {
    mat4x4 view;
    mat4x4 proj;
    vec4 near_far;
};
struct gbuffer_vs_out {
    vec4 gen_gl_Position;
    vec3 v_view_pos;
    vec3 v_normal;
    vec4 v_tangent;
    vec2 v_uv;
};
layout(std140) uniform frame_block { Frame frame; };

layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec4 _vs2fs_location2;
smooth out vec2 _vs2fs_location3;

void main() {
    vec3 a_position = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec4 a_tangent = _p2vs_location2;
    vec2 a_uv = _p2vs_location3;
    vec3 v_view_pos = vec3(0.0);
    vec3 v_normal = vec3(0.0);
    vec4 v_tangent = vec4(0.0);
    vec2 v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e6 = frame.view;
    mat4x4 _e8 = u_model;
    mat4x4 model_view = (_e6 * _e8);
    vec4 p = (model_view * vec4(a_position, 1.0));
    v_view_pos = p.xyz;
    v_normal = (model_view * vec4(a_normal, 0.0)).xyz;
    v_tangent = vec4((model_view * vec4(a_tangent.xyz, 0.0)).xyz, a_tangent.w);
    v_uv = a_uv;
    mat4x4 _e32 = frame.proj;
    gen_gl_Position = (_e32 * p);
    vec4 _e35 = gen_gl_Position;
    vec3 _e37 = v_view_pos;
    vec3 _e39 = v_normal;
    vec4 _e41 = v_tangent;
    vec2 _e43 = v_uv;
    gbuffer_vs_out _tmp_return = gbuffer_vs_out(_e35, _e37, _e39, _e41, _e43);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_view_pos;
    _vs2fs_location1 = _tmp_return.v_normal;
    _vs2fs_location2 = _tmp_return.v_tangent;
    _vs2fs_location3 = _tmp_return.v_uv;
    return;
}

