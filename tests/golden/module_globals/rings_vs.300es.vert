#version 300 es

precision highp float;
precision highp int;

struct rings_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    gen_gl_Position = vec4(a_pos, 0.0, 1.0);
    vec4 _e12 = gen_gl_Position;
    vec2 _e14 = v_uv;
    rings_vs_out _tmp_return = rings_vs_out(_e12, _e14);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    return;
}

