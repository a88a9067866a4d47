#version 330 core
struct references_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
layout(location = 0) in vec2 a_pos;
out vec2 v_uv;

void flip_y(inout vec2 uv_1) {
    float _e4 = uv_1.y;
    uv_1.y = (1.0 - _e4);
    return;
}

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    vec2 uv = vec2(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    vec2 _e6 = out_v_uv;
    uv = _e6;
    flip_y(uv);
    vec2 _e8 = uv;
    out_v_uv = _e8;
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e13 = gen_gl_Position;
    vec2 _e14 = out_v_uv;
    references_vs_out _tmp_return = references_vs_out(_e13, _e14);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

