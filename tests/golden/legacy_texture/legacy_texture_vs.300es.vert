#version 300 es

precision highp float;
precision highp int;

struct legacy_texture_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_dir;
};
layout(location = 0) in vec2 a_pos;
out vec2 v_uv;
out vec3 v_dir;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec3 out_v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    out_v_dir = vec3(in_a_pos, 1.0);
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e12 = gen_gl_Position;
    vec2 _e13 = out_v_uv;
    vec3 _e14 = out_v_dir;
    legacy_texture_vs_out _tmp_return = legacy_texture_vs_out(_e12, _e13, _e14);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_dir = _tmp_return.v_dir;
    return;
}

