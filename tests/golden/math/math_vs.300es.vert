#version 300 es

precision highp float;
precision highp int;

struct math_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
uniform int u_frame;

layout(location = 0) in vec2 a_pos;
out vec2 v_uv;
flat out int v_id;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    int out_v_id = 0;
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    int _e8 = u_frame;
    out_v_id = ((_e8 << uint(2)) | 1);
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e18 = gen_gl_Position;
    vec2 _e19 = out_v_uv;
    int _e20 = out_v_id;
    math_vs_out _tmp_return = math_vs_out(_e18, _e19, _e20);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_id = _tmp_return.v_id;
    return;
}

