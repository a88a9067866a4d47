#version 330 core
struct select_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    ivec2 v_cell;
};
layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out ivec2 _vs2fs_location1;

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    ivec2 v_cell = ivec2(0);
    vec4 gen_gl_Position = vec4(0.0);
    bvec2 inside = lessThan(abs(a_pos), vec2(0.5));
    ivec2 _e8 = ivec2(1, 2);
    ivec2 _e13 = ivec2(-(1), -(2));
    v_cell = ivec2((inside.x ? _e8.x : _e13.x), (inside.y ? _e8.y : _e13.y));
    v_uv = mix(vec2(0.0), a_pos, inside);
    gen_gl_Position = vec4(a_pos, 0.0, 1.0);
    vec4 _e32 = gen_gl_Position;
    vec2 _e34 = v_uv;
    ivec2 _e36 = v_cell;
    select_vs_out _tmp_return = select_vs_out(_e32, _e34, _e36);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_cell;
    return;
}

