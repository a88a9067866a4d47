#version 300 es

precision highp float;
precision highp int;

uniform uint naga_vs_first_instance;

struct gbuffer_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec2 v_uv;
    float v_depth;
};
uniform mat4x4 u_view_proj;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 v_normal;
out vec2 v_uv;
out float v_depth;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec2 in_a_uv = a_uv;
    uint VertexID = uint(gl_VertexID);
    uint InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    vec3 out_v_normal = vec3(0.0);
    vec2 out_v_uv = vec2(0.0);
    float out_v_depth = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e8 = u_view_proj;
    vec4 p = (_e8 * vec4(in_a_pos, 1.0));
    out_v_normal = in_a_normal;
    out_v_uv = (in_a_uv + vec2((float(int(VertexID)) * 0.0), (float(int(InstanceID)) * 0.0)));
    out_v_depth = (p.z / p.w);
    gen_gl_Position = p;
    vec4 _e26 = gen_gl_Position;
    vec3 _e27 = out_v_normal;
    vec2 _e28 = out_v_uv;
    float _e29 = out_v_depth;
    gbuffer_vs_out _tmp_return = gbuffer_vs_out(_e26, _e27, _e28, _e29);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    v_uv = _tmp_return.v_uv;
    v_depth = _tmp_return.v_depth;
    return;
}

