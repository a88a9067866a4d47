#version 300 es

precision highp float;
precision highp int;

struct constant_builtins_vs_out {
    vec4 gen_gl_Position;
    vec3 v_dir;
};
const mat3x3 TILT = mat3x3(vec3(0.5, 0.0, 0.0), vec3(0.0, 0.5, 0.0), vec3(0.0, 0.0, 0.5));

layout(location = 0) in vec3 a_pos;
out vec3 v_dir;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 out_v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_dir = (TILT * in_a_pos);
    gen_gl_Position = vec4(in_a_pos, 1.0);
    vec4 _e7 = gen_gl_Position;
    vec3 _e8 = out_v_dir;
    constant_builtins_vs_out _tmp_return = constant_builtins_vs_out(_e7, _e8);
    gl_Position = _tmp_return.gen_gl_Position;
    v_dir = _tmp_return.v_dir;
    return;
}

