#version 300 es

precision highp float;
precision highp int;

struct select_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    ivec2 v_cell;
};
layout(location = 0) in vec2 a_pos;
out vec2 v_uv;
flat out ivec2 v_cell;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    ivec2 out_v_cell = ivec2(0);
    vec4 gen_gl_Position = vec4(0.0);
    bvec2 inside = lessThan(abs(in_a_pos), vec2(0.5));
    ivec2 _e8 = ivec2(1, 2);
    ivec2 _e11 = ivec2(-(1), -(2));
    out_v_cell = ivec2((inside.x ? _e8.x : _e11.x), (inside.y ? _e8.y : _e11.y));
    out_v_uv = mix(vec2(0.0), in_a_pos, inside);
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e28 = gen_gl_Position;
    vec2 _e29 = out_v_uv;
    ivec2 _e30 = out_v_cell;
    select_vs_out _tmp_return = select_vs_out(_e28, _e29, _e30);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_cell = _tmp_return.v_cell;
    return;
}

