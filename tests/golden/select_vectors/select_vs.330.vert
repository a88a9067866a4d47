#version 330 core
struct select_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    ivec2 v_cell;
};
vec2 a_pos = vec2(0.0);

vec2 v_uv = vec2(0.0);

ivec2 v_cell = ivec2(0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
flat out ivec2 _vs2fs_location1;

void main() {
    vec2 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    vec2 _e3 = a_pos;
    bvec2 inside = lessThan(abs(_e3), vec2(0.5));
    ivec2 _e11 = ivec2(1, 2);
    ivec2 _e16 = ivec2(-(1), -(2));
    v_cell = ivec2((inside.x ? _e11.x : _e16.x), (inside.y ? _e11.y : _e16.y));
    vec2 _e28 = a_pos;
    v_uv = mix(vec2(0.0), _e28, inside);
    vec2 _e34 = a_pos;
    gen_gl_Position = vec4(_e34, 0.0, 1.0);
    vec4 _e39 = gen_gl_Position;
    vec2 _e41 = v_uv;
    ivec2 _e43 = v_cell;
    select_vs_out _tmp_return = select_vs_out(_e39, _e41, _e43);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_cell;
    return;
}

