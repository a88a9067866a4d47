#version 300 es

precision highp float;
precision highp int;

struct select_fs_out {
    vec4 f_color;
    uvec4 f_ids;
};
in vec2 v_uv;
flat in ivec2 v_cell;
layout(location = 0) out vec4 f_color;
layout(location = 1) out uvec4 f_ids;

void main() {
    vec2 in_v_uv = v_uv;
    ivec2 in_v_cell = v_cell;
    vec4 out_f_color = vec4(0.0);
    uvec4 out_f_ids = uvec4(0u);
    bvec2 odd = equal((in_v_cell & ivec2(1)), ivec2(1));
    vec2 c = mix(in_v_uv, vec2(1.0), odd);
    ivec2 _e11 = (in_v_cell * 2);
    ivec2 n = ivec2((odd.x ? _e11.x : in_v_cell.x), (odd.y ? _e11.y : in_v_cell.y));
    bvec2 _e23 = greaterThan(in_v_uv, vec2(0.25));
    uvec2 _e26 = uvec2(7u, 8u);
    uvec2 _e27 = uvec2(n);
    uvec2 u = uvec2((_e23.x ? _e26.x : _e27.x), (_e23.y ? _e26.y : _e27.y));
    bvec2 _e39 = lessThan(n, ivec2(0));
    bvec2 _e40 = not(odd);
    bvec2 b = bvec2((_e39.x ? _e40.x : odd.x), (_e39.y ? _e40.y : odd.y));
    float any_b = (any(b) ? 1.0 : 0.0);
    ivec3 pick = ((in_v_uv.x > 0.5) ? ivec3(n, 3) : ivec3(0));
    out_f_color = vec4(c, float(pick.z), any_b);
    out_f_ids = uvec4(u, uint(n.x), uint(pick.y));
    vec4 _e70 = out_f_color;
    uvec4 _e71 = out_f_ids;
    select_fs_out _tmp_return = select_fs_out(_e70, _e71);
    f_color = _tmp_return.f_color;
    f_ids = _tmp_return.f_ids;
    return;
}

