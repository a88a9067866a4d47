#version 330 core
struct vector_shifts_fs_out {
    vec4 f_color;
};
uniform int u_bits;

uniform uvec4 u_mask;

out vec4 f_color;

void main() {
    vec4 FragCoord = gl_FragCoord;
    vec4 out_f_color = vec4(0.0);
    ivec3 acc = ivec3(0);
    ivec2 texel = ivec2(FragCoord.xy);
    ivec2 tile = (texel >> uvec2(uint(3)));
    uvec4 _e8 = u_mask;
    int _e10 = u_bits;
    uvec4 unpacked = ((_e8 >> uvec4(uint(_e10))) & uvec4(255u));
    acc = (ivec3(tile, 1) << uvec3(uint(2)));
    ivec3 _e24 = acc;
    acc = (_e24 << uvec3(uint(1)));
    int _e28 = u_bits;
    ivec3 _e29 = acc;
    acc = (_e29 >> uvec3(uint(_e28)));
    ivec3 _e34 = acc;
    out_f_color = vec4((vec3((_e34 & ivec3(7))) / vec3(7.0)), (float(unpacked.x) / 255.0));
    vec4 _e47 = out_f_color;
    vector_shifts_fs_out _tmp_return = vector_shifts_fs_out(_e47);
    f_color = _tmp_return.f_color;
    return;
}

