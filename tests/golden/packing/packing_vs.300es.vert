#version 300 es

precision highp float;
precision highp int;

struct packing_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
};
layout(location = 0) in vec2 a_pos;
out vec3 v_normal;

void main() {
    vec2 in_a_pos = a_pos;
    vec3 out_v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_normal = normalize(vec3(in_a_pos, 1.0));
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e8 = gen_gl_Position;
    vec3 _e9 = out_v_normal;
    packing_vs_out _tmp_return = packing_vs_out(_e8, _e9);
    gl_Position = _tmp_return.gen_gl_Position;
    v_normal = _tmp_return.v_normal;
    return;
}

