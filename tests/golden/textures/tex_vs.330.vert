#version 330 core
struct tex_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_dir;
};
layout(location = 0) in vec3 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    vec3 v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos.xy * 0.5) + vec2(0.5));
    v_dir = a_pos;
    gen_gl_Position = vec4(a_pos, 1.0);
    vec4 _e13 = gen_gl_Position;
    vec2 _e15 = v_uv;
    vec3 _e17 = v_dir;
    tex_vs_out _tmp_return = tex_vs_out(_e13, _e15, _e17);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_dir;
    return;
}

