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
layout(std140) uniform frame_ubo {
    mat4x4 view;
    mat4x4 proj;
    vec4 near_far;
} frame;

uniform mat4x4 u_model;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv;
out vec3 v_view_pos;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv;

void main() {
    vec3 in_a_position = a_position;
    vec3 in_a_normal = a_normal;
    vec4 in_a_tangent = a_tangent;
    vec2 in_a_uv = a_uv;
    vec3 out_v_view_pos = vec3(0.0);
    vec3 out_v_normal = vec3(0.0);
    vec4 out_v_tangent = vec4(0.0);
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e6 = frame.view;
    mat4x4 _e8 = u_model;
    mat4x4 model_view = (_e6 * _e8);
    vec4 p = (model_view * vec4(in_a_position, 1.0));
    out_v_view_pos = p.xyz;
    out_v_normal = (model_view * vec4(in_a_normal, 0.0)).xyz;
    out_v_tangent = vec4((model_view * vec4(in_a_tangent.xyz, 0.0)).xyz, in_a_tangent.w);
    out_v_uv = in_a_uv;
    mat4x4 _e30 = frame.proj;
    gen_gl_Position = (_e30 * p);
    vec4 _e32 = gen_gl_Position;
    vec3 _e33 = out_v_view_pos;
    vec3 _e34 = out_v_normal;
    vec4 _e35 = out_v_tangent;
    vec2 _e36 = out_v_uv;
    gbuffer_vs_out _tmp_return = gbuffer_vs_out(_e32, _e33, _e34, _e35, _e36);
    gl_Position = _tmp_return.gen_gl_Position;
    v_view_pos = _tmp_return.v_view_pos;
    v_normal = _tmp_return.v_normal;
    v_tangent = _tmp_return.v_tangent;
    v_uv = _tmp_return.v_uv;
    return;
}

