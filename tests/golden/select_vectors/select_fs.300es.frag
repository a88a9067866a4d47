#version 300 es

precision highp float;
precision highp int;

struct select_fs_out {
    vec4 f_color;
    uvec4 f_ids;
};
smooth in vec2 _vs2fs_location0;
flat in ivec2 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out uvec4 _fs2p_location1;

void main() {
    vec2 v_uv = _vs2fs_location0;
    ivec2 v_cell = _vs2fs_location1;
    vec4 f_color = vec4(0.0);
    uvec4 f_ids = uvec4(0u);
    bvec2 odd = equal((v_cell & ivec2(1)), ivec2(1));
    vec2 c = mix(v_uv, vec2(1.0), odd);
    ivec2 _e12 = (v_cell * 2);
    ivec2 n = ivec2((odd.x ? _e12.x : v_cell.x), (odd.y ? _e12.y : v_cell.y));
    bvec2 _e24 = greaterThan(v_uv, vec2(0.25));
    uvec2 _e27 = uvec2(7u, 8u);
    uvec2 _e28 = uvec2(n);
    uvec2 u = uvec2((_e24.x ? _e27.x : _e28.x), (_e24.y ? _e27.y : _e28.y));
    bvec2 _e40 = lessThan(n, ivec2(0));
    bvec2 _e41 = not(odd);
    bvec2 b = bvec2((_e40.x ? _e41.x : odd.x), (_e40.y ? _e41.y : odd.y));
    float any_b = (any(b) ? 1.0 : 0.0);
    ivec3 pick = ((v_uv.x > 0.5) ? ivec3(n, 3) : ivec3(0));
    f_color = vec4(c, float(pick.z), any_b);
    f_ids = uvec4(u, uint(n.x), uint(pick.y));
    vec4 _e74 = f_color;
    uvec4 _e76 = f_ids;
    select_fs_out _tmp_return = select_fs_out(_e74, _e76);
    _fs2p_location0 = _tmp_return.f_color;
    _fs2p_location1 = _tmp_return.f_ids;
    return;
}

