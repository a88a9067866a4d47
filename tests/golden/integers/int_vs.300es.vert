#version 300 es

precision highp float;
precision highp int;

struct int_vs_out {
    vec4 gen_gl_Position;
    ivec2 v_cell;
    uint v_hash;
};
layout(std140) uniform u_seed_block { uint u_seed; };

vec2 a_pos = vec2(0.0);

ivec2 v_cell = ivec2(0);

uint v_hash = 0u;

int gen_gl_VertexID = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
flat out ivec2 _vs2fs_location0;
flat out uint _vs2fs_location1;

uint hash(uint x) {
    uint h = 0u;
    h = (x ^ (x >> 16u));
    uint _e7 = h;
    h = (_e7 * 2146121005u);
    uint _e11 = h;
    uint _e15 = h;
    h = (_e15 ^ (_e11 >> uint(15)));
    uint _e19 = h;
    uint _e24 = h;
    h = ((_e19 << uint(3)) | (_e24 >> 29u));
    uint _e29 = h;
    return _e29;
}

void main() {
    vec2 in_a_pos = _p2vs_location0;
    uint in_VertexID = uint(gl_VertexID);
    a_pos = in_a_pos;
    gen_gl_VertexID = int(in_VertexID);
    vec2 _e6 = a_pos;
    ivec2 cell = ivec2(floor((_e6 * 8.0)));
    ivec2 _e13 = ivec2(3);
    v_cell = ((cell - (_e13 * (cell / _e13))) * (cell / ivec2(2, -(2))));
    int _e25 = gen_gl_VertexID;
    uint _e28 = u_seed;
    uint _e30 = hash((uint(_e25) + _e28));
    v_hash = _e30;
    vec2 _e33 = a_pos;
    gen_gl_Position = vec4(_e33, 0.0, 1.0);
    vec4 _e38 = gen_gl_Position;
    ivec2 _e40 = v_cell;
    uint _e42 = v_hash;
    int_vs_out _tmp_return = int_vs_out(_e38, _e40, _e42);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_cell;
    _vs2fs_location1 = _tmp_return.v_hash;
    return;
}

