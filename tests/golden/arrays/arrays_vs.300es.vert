#version 300 es

precision highp float;
precision highp int;

struct arrays_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
const int RING[4] = int[4](3, 1, 4, 1);

layout(location = 0) in vec2 a_pos;
out vec2 v_uv;
flat out int v_id;

void main() {
    vec2 in_a_pos = a_pos;
    uint VertexID = uint(gl_VertexID);
    vec2 out_v_uv = vec2(0.0);
    int out_v_id = 0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e2 = int(VertexID);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    out_v_id = RING[(_e2 - (4 * (_e2 / 4)))];
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e19 = gen_gl_Position;
    vec2 _e20 = out_v_uv;
    int _e21 = out_v_id;
    arrays_vs_out _tmp_return = arrays_vs_out(_e19, _e20, _e21);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_id = _tmp_return.v_id;
    return;
}

