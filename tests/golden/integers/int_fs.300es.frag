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

flat in ivec2 v_cell;
flat in uint v_hash;
out vec4 f_color;

void main() {
    ivec2 in_v_cell = v_cell;
    uint in_v_hash = v_hash;
    vec4 out_f_color = vec4(0.0);
    uvec2 bits = uvec2(0u);
    ivec2 masked = ((in_v_cell & ivec2(255)) | (ivec2(1) << uvec2(ivec2(2, 3))));
    ivec2 flipped = (~(masked) ^ ivec2(NEG_MOD, NEG_DIV));
    bits = (uvec2(flipped) >> uvec2(1u, 2u));
    uvec2 _e26 = bits;
    bits = (_e26 % uvec2(7u));
    float f = (intBitsToFloat(1065353216) + uintBitsToFloat(floatBitsToUint(0.5)));
    uint _e35 = bits.x;
    uint _e37 = bits.y;
    float k = ((float(((_e35 + _e37) + (in_v_hash & WRAP))) + float(TRUNC)) + FMOD);
    out_f_color = vec4(fract((k * 0.001)), f, float((int((in_v_hash % 5u)) - 2)), 1.0);
    vec4 _e59 = out_f_color;
    int_fs_out _tmp_return = int_fs_out(_e59);
    f_color = _tmp_return.f_color;
    return;
}

