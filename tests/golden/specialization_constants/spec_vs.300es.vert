#version 300 es

precision highp float;
precision highp int;

struct spec_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
const float SPREAD = 0.125;
const int OFFSET = -2;

layout(location = 0) in vec2 a_pos;
out vec2 v_uv;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = (((in_a_pos * 0.5) + vec2(0.5)) + vec2((float(OFFSET) * SPREAD)));
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e16 = gen_gl_Position;
    vec2 _e17 = out_v_uv;
    spec_vs_out _tmp_return = spec_vs_out(_e16, _e17);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

