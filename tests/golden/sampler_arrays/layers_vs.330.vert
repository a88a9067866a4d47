#version 330 core
struct layers_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
vec2 a_pos = vec2(0.0);

vec2 v_uv = vec2(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;

void main() {
    vec2 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    vec2 _e4 = a_pos;
    v_uv = ((_e4 * 0.5) + vec2(0.5));
    vec2 _e12 = a_pos;
    gen_gl_Position = vec4(_e12, 0.0, 1.0);
    vec4 _e17 = gen_gl_Position;
    vec2 _e19 = v_uv;
    layers_vs_out _tmp_return = layers_vs_out(_e17, _e19);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    return;
}

