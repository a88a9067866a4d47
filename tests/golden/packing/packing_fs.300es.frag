#version 300 es

precision highp float;
precision highp int;

struct packing_fs_out {
    uvec4 g_packed;
    vec4 f_check;
};
uniform vec4 u_albedo;

in vec3 v_normal;
layout(location = 0) out uvec4 g_packed;
layout(location = 1) out vec4 f_check;

void main() {
    vec3 in_v_normal = v_normal;
    vec4 FragCoord = gl_FragCoord;
    uvec4 out_g_packed = uvec4(0u);
    vec4 out_f_check = vec4(0.0);
    vec3 n = normalize(in_v_normal);
    vec4 _e4 = u_albedo;
    uvec4 _e17 = uvec4(floor((vec4(0.5) + (vec4(255.0) * clamp(_e4, vec4(0.0), vec4(1.0))))));
    uint albedo = ((((_e17.x & 255u) | ((_e17.y & 255u) << 8u)) | ((_e17.z & 255u) << 16u)) | ((_e17.w & 255u) << 24u));
    uvec2 _e48 = uvec2(ivec2(floor((vec2(0.5) + (vec2(32767.0) * clamp(n.xy, vec2(-1.0), vec2(1.0)))))));
    uvec2 _e69 = uvec2(floor((vec2(0.5) + (vec2(65535.0) * clamp(((n.xy * 0.5) + vec2(0.5)), vec2(0.0), vec2(1.0))))));
    uint normal = (((_e48.x & 65535u) | ((_e48.y & 65535u) << 16u)) ^ ((_e69.x & 65535u) | ((_e69.y & 65535u) << 16u)));
    vec2 _e79 = vec2(FragCoord.z, n.z);
    uint _e82 = floatBitsToUint(_e79.x);
    uint _e86 = (_e82 & 2147483647u);
    uint _e113 = floatBitsToUint(_e79.y);
    uint _e115 = (_e113 & 2147483647u);
    uint depth = ((((_e86 >= 1199570944u) ? ((_e86 > 2139095040u) ? 32256u : 31744u) : ((_e86 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e86) + 0.5)) - 1056964608u) : (((_e86 + 3355447295u) + ((_e86 >> 13u) & 1u)) >> 13u))) | ((_e82 & 2147483648u) >> 16u)) | ((((_e115 >= 1199570944u) ? ((_e115 > 2139095040u) ? 32256u : 31744u) : ((_e115 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e115) + 0.5)) - 1056964608u) : (((_e115 + 3355447295u) + ((_e115 >> 13u) & 1u)) >> 13u))) | ((_e113 & 2147483648u) >> 16u)) << 16u));
    uvec4 _e148 = uvec4(ivec4(floor((vec4(0.5) + (vec4(127.0) * clamp(vec4(n, -(1.0)), vec4(-1.0), vec4(1.0)))))));
    out_g_packed = uvec4(albedo, normal, depth, ((((_e148.x & 255u) | ((_e148.y & 255u) << 8u)) | ((_e148.z & 255u) << 16u)) | ((_e148.w & 255u) << 24u)));
    uint _e179 = out_g_packed.w;
    vec4 back = ((vec4(float((albedo & 255u)), float(((albedo >> 8u) & 255u)), float(((albedo >> 16u) & 255u)), float(((albedo >> 24u) & 255u))) / vec4(255.0)) + max((vec4(float((int((_e179 << 24u)) >> 24u)), float((int((_e179 << 16u)) >> 24u)), float((int((_e179 << 8u)) >> 24u)), float((int(_e179) >> 24u))) / vec4(127.0)), vec4(-1.0)));
    uint _e201 = (depth & 65535u);
    uint _e202 = (depth >> 16u);
    uint _e205 = ((_e201 & 32767u) << 13u);
    uint _e207 = (_e205 & 260046848u);
    uint _e209 = (_e205 + 939524096u);
    uint _e228 = ((_e202 & 32767u) << 13u);
    uint _e229 = (_e228 & 260046848u);
    uint _e230 = (_e228 + 939524096u);
    float nz = ((vec2(uintBitsToFloat((((_e207 == 260046848u) ? (_e209 + 939524096u) : ((_e207 == 0u) ? floatBitsToUint((uintBitsToFloat((_e209 + 8388608u)) - 6.1035156e-5)) : _e209)) | ((_e201 & 32768u) << 16u))), uintBitsToFloat((((_e229 == 260046848u) ? (_e230 + 939524096u) : ((_e229 == 0u) ? floatBitsToUint((uintBitsToFloat((_e230 + 8388608u)) - 6.1035156e-5)) : _e230)) | ((_e202 & 32768u) << 16u)))).y + (max((vec2(float((int((normal << 16u)) >> 16u)), float((int(normal) >> 16u))) / vec2(32767.0)), vec2(-1.0)).x * 0.0)) + ((vec2(float((normal & 65535u)), float(((normal >> 16u) & 65535u))) / vec2(65535.0)).y * 0.0));
    out_f_check = vec4(back.xyz, nz);
    uvec4 _e275 = out_g_packed;
    vec4 _e276 = out_f_check;
    packing_fs_out _tmp_return = packing_fs_out(_e275, _e276);
    g_packed = _tmp_return.g_packed;
    f_check = _tmp_return.f_check;
    return;
}

