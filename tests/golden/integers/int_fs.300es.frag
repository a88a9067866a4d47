#version 300 es

precision highp float;
precision highp int;

struct int_fs_out {
    vec4 f_color;
};
const int NEG_MOD = -1;
const int NEG_DIV = -3;
const uint WRAP = 4294967295u;
const int TRUNC = -2;
const float FMOD = 0.5;

ivec2 v_cell = ivec2(0);

uint v_hash = 0u;

vec4 f_color = vec4(0.0);

flat in ivec2 _vs2fs_location0;
flat in uint _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    ivec2 in_v_cell = _vs2fs_location0;
    uint in_v_hash = _vs2fs_location1;
    uvec2 bits = uvec2(0u);
    v_cell = in_v_cell;
    v_hash = in_v_hash;
    ivec2 _e5 = v_cell;
    ivec2 masked = ((_e5 & ivec2(255)) | (ivec2(1) << uvec2(ivec2(2, 3))));
    ivec2 flipped = (~(masked) ^ ivec2(NEG_MOD, NEG_DIV));
    bits = (uvec2(flipped) >> uvec2(1u, 2u));
    uvec2 _e31 = bits;
    bits = (_e31 % uvec2(7u));
    float f = (intBitsToFloat(1065353216) + uintBitsToFloat(floatBitsToUint(0.5)));
    uint _e41 = bits.x;
    uint _e44 = bits.y;
    uint _e47 = v_hash;
    float k = ((float(((_e41 + _e44) + (_e47 & WRAP))) + float(TRUNC)) + FMOD);
    uint _e62 = v_hash;
    f_color = vec4(fract((k * 0.001)), f, float((int((_e62 % 5u)) - 2)), 1.0);
    vec4 _e72 = f_color;
    int_fs_out _tmp_return = int_fs_out(_e72);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

