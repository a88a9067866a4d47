#version 300 es

precision highp float;
precision highp int;

struct entry_io_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_tint;
    float v_shade;
};
layout(std140) uniform u_scale_block { float u_scale; };

vec3 a_pos = vec3(0.0);

vec3 v_tint = vec3(0.0);

int gen_gl_VertexID = 0;

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec2 _p2vs_location1;
smooth out vec2 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out float _vs2fs_location2;

void set_tint(float k) {
    v_tint = vec3(k, (1.0 - k), 0.5);
    return;
}

vec3 lifted() {
    vec3 _e1 = a_pos;
    int _e4 = gen_gl_VertexID;
    return (_e1 + vec3(0.0, float((_e4 - (2 * (_e4 / 2)))), 0.0));
}

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec2 a_uv = _p2vs_location1;
    uint in_VertexID = uint(gl_VertexID);
    vec2 v_uv = vec2(0.0);
    float v_shade = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    a_pos = in_a_pos;
    gen_gl_VertexID = int(in_VertexID);
    v_uv.x = a_uv.x;
    v_uv.y = (1.0 - a_uv.y);
    float _e16 = u_scale;
    vec2 _e17 = v_uv;
    v_uv = (_e17 * _e16);
    float _e21 = v_uv.x;
    set_tint(_e21);
    float _e25 = a_pos.z;
    v_shade = _e25;
    vec3 _e27 = lifted();
    float _e29 = u_scale;
    gen_gl_Position = vec4((_e27 * _e29), 1.0);
    int _e34 = gen_gl_VertexID;
    if ((_e34 > 2)) {
        float _e41 = a_pos.x;
        float _e42 = gen_gl_Position.w;
        gen_gl_Position.w = (_e42 + _e41);
    }
    vec4 _e45 = gen_gl_Position;
    vec2 _e47 = v_uv;
    vec3 _e49 = v_tint;
    float _e51 = v_shade;
    entry_io_vs_out _tmp_return = entry_io_vs_out(_e45, _e47, _e49, _e51);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_tint;
    _vs2fs_location2 = _tmp_return.v_shade;
    return;
}

