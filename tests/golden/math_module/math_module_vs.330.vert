#version 330 core
struct math_module_vs_out {
    vec4 gen_gl_Position;
    vec2 v_pos;
};
uniform float u_time;

layout(location = 0) in vec2 a_pos;
out vec2 v_pos;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_pos = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    float s = 0.0;
    float c = 0.0;
    s = 0.0;
    c = 0.0;
    float _e5 = u_time;
    float sincos_x = ((_e5 * 2.0) * 3.1415927);
    s = sin(sincos_x);
    c = cos(sincos_x);
    float _e13 = c;
    float _e14 = s;
    float _e16 = s;
    float _e18 = c;
    out_v_pos = (mat2x2(vec2(_e13, _e14), vec2(-(_e16), _e18)) * in_a_pos);
    gen_gl_Position = vec4(((in_a_pos * 0.9) + vec2(0.05)), 0.0, 1.0);
    vec4 _e31 = gen_gl_Position;
    vec2 _e32 = out_v_pos;
    math_module_vs_out _tmp_return = math_module_vs_out(_e31, _e32);
    gl_Position = _tmp_return.gen_gl_Position;
    v_pos = _tmp_return.v_pos;
    return;
}

