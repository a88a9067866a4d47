#version 300 es

precision highp float;
precision highp int;

struct select_fs_out {
    vec4 f_color;
    uvec4 f_ids;
};
vec2 v_uv = vec2(0.0);

ivec2 v_cell = ivec2(0);

vec4 f_color = vec4(0.0);

uvec4 f_ids = uvec4(0u);

smooth in vec2 _vs2fs_location0;
flat in ivec2 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out uvec4 _fs2p_location1;

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    ivec2 in_v_cell = _vs2fs_location1;
    v_uv = in_v_uv;
    v_cell = in_v_cell;
    ivec2 _e5 = v_cell;
    bvec2 odd = equal((_e5 & ivec2(1)), ivec2(1));
    vec2 _e15 = v_uv;
    vec2 c = mix(_e15, vec2(1.0), odd);
    ivec2 _e18 = v_cell;
    ivec2 _e20 = (_e18 * 2);
    ivec2 _e22 = v_cell;
    ivec2 n = ivec2((odd.x ? _e20.x : _e22.x), (odd.y ? _e20.y : _e22.y));
    vec2 _e33 = v_uv;
    bvec2 _e36 = greaterThan(_e33, vec2(0.25));
    uvec2 _e39 = uvec2(7u, 8u);
    uvec2 _e40 = uvec2(n);
    uvec2 u = uvec2((_e36.x ? _e39.x : _e40.x), (_e36.y ? _e39.y : _e40.y));
    bvec2 _e52 = lessThan(n, ivec2(0));
    bvec2 _e53 = not(odd);
    bvec2 b = bvec2((_e52.x ? _e53.x : odd.x), (_e52.y ? _e53.y : odd.y));
    float any_b = (any(b) ? 1.0 : 0.0);
    float _e69 = v_uv.x;
    ivec3 pick = ((_e69 > 0.5) ? ivec3(n, 3) : ivec3(0));
    f_color = vec4(c, float(pick.z), any_b);
    f_ids = uvec4(u, uint(n.x), uint(pick.y));
    vec4 _e88 = f_color;
    uvec4 _e90 = f_ids;
    select_fs_out _tmp_return = select_fs_out(_e88, _e90);
    _fs2p_location0 = _tmp_return.f_color;
    _fs2p_location1 = _tmp_return.f_ids;
    return;
}

