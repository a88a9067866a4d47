#version 330 core
struct math_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    int v_id;
};
layout(std140) uniform u_frame_block { int u_frame; };

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out int _vs2fs_location1;

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    int v_id = 0;
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    int _e9 = u_frame;
    v_id = ((_e9 << uint(2)) | 1);
    gen_gl_Position = vec4(a_pos, 0.0, 1.0);
    vec4 _e20 = gen_gl_Position;
    vec2 _e22 = v_uv;
    int _e24 = v_id;
    math_vs_out _tmp_return = math_vs_out(_e20, _e22, _e24);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_id;
    return;
}

