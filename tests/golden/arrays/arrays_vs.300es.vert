#version 300 es

precision highp float;
precision highp int;

struct arrays_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
const int RING[4] = int[4](3, 1, 4, 1);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out int _vs2fs_location1;

void main() {
    vec2 a_pos = _p2vs_location0;
    uint VertexID = uint(gl_VertexID);
    vec2 v_uv = vec2(0.0);
    int v_id = 0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e2 = int(VertexID);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    v_id = RING[(_e2 - (4 * (_e2 / 4)))];
    gen_gl_Position = vec4(a_pos, 0.0, 1.0);
    vec4 _e21 = gen_gl_Position;
    vec2 _e23 = v_uv;
    int _e25 = v_id;
    arrays_vs_out _tmp_return = arrays_vs_out(_e21, _e23, _e25);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_id;
    return;
}

