#version 300 es

precision highp float;
precision highp int;

struct legacy_texture_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    vec3 v_dir;
};
layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    vec3 v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    v_dir = vec3(a_pos, 1.0);
    gen_gl_Position = vec4(a_pos, 0.0, 1.0);
    vec4 _e15 = gen_gl_Position;
    vec2 _e17 = v_uv;
    vec3 _e19 = v_dir;
    legacy_texture_vs_out _tmp_return = legacy_texture_vs_out(_e15, _e17, _e19);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_dir;
    return;
}

