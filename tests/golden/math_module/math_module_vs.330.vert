#version 330 core
struct math_module_vs_out {
    vec4 gen_gl_Position;
    vec2 v_pos;
};
layout(std140) uniform u_time_block { float u_time; };

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_pos = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    float s = 0.0;
    float c = 0.0;
    s = 0.0;
    c = 0.0;
    float _e6 = u_time;
    float sincos_x = ((_e6 * 2.0) * 3.1415927);
    s = sin(sincos_x);
    c = cos(sincos_x);
    float _e17 = c;
    float _e19 = s;
    float _e22 = s;
    float _e25 = c;
    v_pos = (mat2x2(vec2(_e17, _e19), vec2(-(_e22), _e25)) * a_pos);
    gen_gl_Position = vec4(((a_pos * 0.9) + vec2(0.05)), 0.0, 1.0);
    vec4 _e39 = gen_gl_Position;
    vec2 _e41 = v_pos;
    math_module_vs_out _tmp_return = math_module_vs_out(_e39, _e41);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_pos;
    return;
}

