#version 300 es

precision highp float;
precision highp int;

struct math_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
layout(std140) uniform u_frame_block { int u_frame; };

vec2 a_pos = vec2(0.0);

vec2 v_uv = vec2(0.0);

int v_id = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out int _vs2fs_location1;

void main() {
    vec2 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    vec2 _e4 = a_pos;
    v_uv = ((_e4 * 0.5) + vec2(0.5));
    int _e12 = u_frame;
    v_id = ((_e12 << uint(2)) | 1);
    vec2 _e20 = a_pos;
    gen_gl_Position = vec4(_e20, 0.0, 1.0);
    vec4 _e25 = gen_gl_Position;
    vec2 _e27 = v_uv;
    int _e29 = v_id;
    math_vs_out _tmp_return = math_vs_out(_e25, _e27, _e29);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_id;
    return;
}

