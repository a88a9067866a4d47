#version 430 core
struct prim_vs_out {
    vec4 gen_gl_Position;
};
layout(location = 0) in vec2 a_pos;

void main() {
    vec2 in_a_pos = a_pos;
    vec4 gen_gl_Position = vec4(0.0);
    gen_gl_Position = vec4(in_a_pos, 0.0, 1.0);
    vec4 _e5 = gen_gl_Position;
    prim_vs_out _tmp_return = prim_vs_out(_e5);
    gl_Position = _tmp_return.gen_gl_Position;
    return;
}

