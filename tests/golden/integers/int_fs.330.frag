#version 330 core
struct int_fs_out {
    vec4 f_color;
};
const int NEG_MOD = -1;
const int NEG_DIV = -3;
const uint WRAP = 4294967295u;
const int TRUNC = -2;
const float FMOD = 0.5;

flat in ivec2 _vs2fs_location0;
flat in uint _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    ivec2 v_cell = _vs2fs_location0;
    uint v_hash = _vs2fs_location1;
    vec4 f_color = vec4(0.0);
    uvec2 bits = uvec2(0u);
    ivec2 masked = ((v_cell & ivec2(255)) | (ivec2(1) << uvec2(ivec2(2, 3))));
    ivec2 flipped = (~(masked) ^ ivec2(NEG_MOD, NEG_DIV));
    bits = (uvec2(flipped) >> uvec2(1u, 2u));
    uvec2 _e27 = bits;
    bits = (_e27 % uvec2(7u));
    float f = (intBitsToFloat(1065353216) + uintBitsToFloat(floatBitsToUint(0.5)));
    uint _e37 = bits.x;
    uint _e40 = bits.y;
    float k = ((float(((_e37 + _e40) + (v_hash & WRAP))) + float(TRUNC)) + FMOD);
    f_color = vec4(fract((k * 0.001)), f, float((int((v_hash % 5u)) - 2)), 1.0);
    vec4 _e64 = f_color;
    int_fs_out _tmp_return = int_fs_out(_e64);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

