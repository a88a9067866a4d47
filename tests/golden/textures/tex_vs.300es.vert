#version 300 es

precision highp float;
precision highp int;

struct tex_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_dir;
};
layout(location = 0) in vec3 a_pos;
out vec2 v_uv;
out vec3 v_dir;

void main() {
    vec3 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec3 out_v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos.xy * 0.5) + vec2(0.5));
    out_v_dir = in_a_pos;
    gen_gl_Position = vec4(in_a_pos, 1.0);
    vec4 _e11 = gen_gl_Position;
    vec2 _e12 = out_v_uv;
    vec3 _e13 = out_v_dir;
    tex_vs_out _tmp_return = tex_vs_out(_e11, _e12, _e13);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_dir = _tmp_return.v_dir;
    return;
}

