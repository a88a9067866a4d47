#version 300 es

precision highp float;
precision highp int;

struct arrays_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
const int RING[4] = int[4](3, 1, 4, 1);

vec2 a_pos = vec2(0.0);

vec2 v_uv = vec2(0.0);

int v_id = 0;

int gen_gl_VertexID = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out int _vs2fs_location1;

void main() {
    vec2 in_a_pos = _p2vs_location0;
    uint in_VertexID = uint(gl_VertexID);
    a_pos = in_a_pos;
    gen_gl_VertexID = int(in_VertexID);
    vec2 _e7 = a_pos;
    v_uv = ((_e7 * 0.5) + vec2(0.5));
    int _e16 = gen_gl_VertexID;
    v_id = RING[(_e16 - (4 * (_e16 / 4)))];
    vec2 _e24 = a_pos;
    gen_gl_Position = vec4(_e24, 0.0, 1.0);
    vec4 _e29 = gen_gl_Position;
    vec2 _e31 = v_uv;
    int _e33 = v_id;
    arrays_vs_out _tmp_return = arrays_vs_out(_e29, _e31, _e33);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_id;
    return;
}

