#version 300 es

precision highp float;
precision highp int;

struct entry_io_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_tint;
    float v_shade;
};
uniform float u_scale;

vec3 io_a_pos = vec3(0.0);

vec3 io_v_tint = vec3(0.0);

int gen_gl_VertexID = 0;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec2 a_uv;
out vec2 v_uv;
out vec3 v_tint;
out float v_shade;

void set_tint(float k) {
    io_v_tint = vec3(k, (1.0 - k), 0.5);
    return;
}

vec3 lifted() {
    vec3 _e1 = io_a_pos;
    int _e4 = gen_gl_VertexID;
    return (_e1 + vec3(0.0, float((_e4 - (2 * (_e4 / 2)))), 0.0));
}

void main() {
    vec3 in_a_pos = a_pos;
    vec2 in_a_uv = a_uv;
    uint in_VertexID = uint(gl_VertexID);
    vec2 out_v_uv = vec2(0.0);
    float out_v_shade = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    io_a_pos = in_a_pos;
    gen_gl_VertexID = int(in_VertexID);
    out_v_uv.x = in_a_uv.x;
    out_v_uv.y = (1.0 - in_a_uv.y);
    float _e14 = u_scale;
    vec2 _e15 = out_v_uv;
    out_v_uv = (_e15 * _e14);
    float _e18 = out_v_uv.x;
    set_tint(_e18);
    float _e21 = io_a_pos.z;
    out_v_shade = _e21;
    vec3 _e23 = lifted();
    float _e24 = u_scale;
    gen_gl_Position = vec4((_e23 * _e24), 1.0);
    int _e27 = gen_gl_VertexID;
    if ((_e27 > 2)) {
        float _e32 = io_a_pos.x;
        float _e33 = gen_gl_Position.w;
        gen_gl_Position.w = (_e33 + _e32);
    }
    vec4 _e35 = gen_gl_Position;
    vec2 _e36 = out_v_uv;
    vec3 _e38 = io_v_tint;
    float _e39 = out_v_shade;
    entry_io_vs_out _tmp_return = entry_io_vs_out(_e35, _e36, _e38, _e39);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_tint = _tmp_return.v_tint;
    v_shade = _tmp_return.v_shade;
    return;
}

