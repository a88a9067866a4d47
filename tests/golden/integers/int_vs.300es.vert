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
    uint _e6 = h;
    h = (_e6 * 2146121005u);
    uint _e8 = h;
    uint _e12 = h;
    h = (_e12 ^ (_e8 >> uint(15)));
    uint _e14 = h;
    uint _e18 = h;
    h = ((_e14 << uint(3)) | (_e18 >> 29u));
    uint _e22 = h;
    return _e22;
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
    uint _e21 = u_seed;
    uint _e23 = hash((uint(int(VertexID)) + _e21));
    out_v_hash = _e23;
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e28 = gen_gl_Position;
    ivec2 _e29 = out_v_cell;
    uint _e30 = out_v_hash;
    int_vs_out _tmp_return = int_vs_out(_e28, _e29, _e30);
    gl_Position = _tmp_return.gen_gl_Position;
    v_cell = _tmp_return.v_cell;
    v_hash = _tmp_return.v_hash;
    return;
}

