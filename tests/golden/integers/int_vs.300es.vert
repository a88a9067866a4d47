#version 300 es

precision highp float;
precision highp int;

struct int_vs_out {
    vec4 gen_gl_Position;
    ivec2 v_cell;
    uint v_hash;
};
uniform uint u_seed;

layout(location = 0) in vec2 a_pos;
flat out ivec2 v_cell;
flat out uint v_hash;

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
    vec2 in_a_pos = a_pos;
    uint VertexID = uint(gl_VertexID);
    ivec2 out_v_cell = ivec2(0);
    uint out_v_hash = 0u;
    vec4 gen_gl_Position = vec4(0.0);
    ivec2 cell = ivec2(floor((in_a_pos * 8.0)));
    ivec2 _e9 = ivec2(3);
    out_v_cell = ((cell - (_e9 * (cell / _e9))) * (cell / ivec2(2, -(2))));
    uint _e22 = u_seed;
    uint _e24 = hash((uint(int(VertexID)) + _e22));
    out_v_hash = _e24;
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e30 = gen_gl_Position;
    ivec2 _e32 = out_v_cell;
    uint _e34 = out_v_hash;
    int_vs_out _tmp_return = int_vs_out(_e30, _e32, _e34);
    gl_Position = _tmp_return.gen_gl_Position;
    v_cell = _tmp_return.v_cell;
    v_hash = _tmp_return.v_hash;
    return;
}

