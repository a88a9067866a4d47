#version 330 core
struct daslang_modules_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
uniform mat4x4 u_mvp;

layout(location = 0) in vec3 a_pos;
smooth out vec2 v_uv;

void main() {
    vec3 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos.xy * 0.5) + vec2(0.5));
    mat4x4 _e9 = u_mvp;
    gen_gl_Position = (_e9 * vec4(in_a_pos, 1.0));
    vec4 _e13 = gen_gl_Position;
    vec2 _e14 = out_v_uv;
    daslang_modules_vs_out _tmp_return = daslang_modules_vs_out(_e13, _e14);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

