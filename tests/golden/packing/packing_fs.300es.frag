#version 300 es

precision highp float;
precision highp int;

struct packing_fs_out {
    uvec4 g_packed;
    vec4 f_check;
};
uniform vec4 u_albedo;

smooth in vec3 v_normal;
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
    uvec2 _e53 = uvec2(ivec2(floor((vec2(0.5) + (vec2(32767.0) * clamp(n.xy, vec2(-1.0), vec2(1.0)))))));
    uvec2 _e81 = uvec2(floor((vec2(0.5) + (vec2(65535.0) * clamp(((n.xy * 0.5) + vec2(0.5)), vec2(0.0), vec2(1.0))))));
    uint normal = (((_e53.x & 65535u) | ((_e53.y & 65535u) << 16u)) ^ ((_e81.x & 65535u) | ((_e81.y & 65535u) << 16u)));
    vec2 _e94 = vec2(FragCoord.z, n.z);
    uint _e97 = floatBitsToUint(_e94.x);
    uint _e101 = (_e97 & 2147483647u);
    uint _e131 = floatBitsToUint(_e94.y);
    uint _e135 = (_e131 & 2147483647u);
    uint depth = ((((_e101 >= 1199570944u) ? ((_e101 > 2139095040u) ? 32256u : 31744u) : ((_e101 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e101) + 0.5)) - 1056964608u) : (((_e101 + 3355447295u) + ((_e101 >> 13u) & 1u)) >> 13u))) | ((_e97 & 2147483648u) >> 16u)) | ((((_e135 >= 1199570944u) ? ((_e135 > 2139095040u) ? 32256u : 31744u) : ((_e135 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e135) + 0.5)) - 1056964608u) : (((_e135 + 3355447295u) + ((_e135 >> 13u) & 1u)) >> 13u))) | ((_e131 & 2147483648u) >> 16u)) << 16u));
    uvec4 _e185 = uvec4(ivec4(floor((vec4(0.5) + (vec4(127.0) * clamp(vec4(n, -(1.0)), vec4(-1.0), vec4(1.0)))))));
    out_g_packed = uvec4(albedo, normal, depth, ((((_e185.x & 255u) | ((_e185.y & 255u) << 8u)) | ((_e185.z & 255u) << 16u)) | ((_e185.w & 255u) << 24u)));
    uint _e232 = out_g_packed.w;
    vec4 back = ((vec4(float((albedo & 255u)), float(((albedo >> 8u) & 255u)), float(((albedo >> 16u) & 255u)), float(((albedo >> 24u) & 255u))) / vec4(255.0)) + max((vec4(float((int((_e232 << 24u)) >> 24u)), float((int((_e232 << 16u)) >> 24u)), float((int((_e232 << 8u)) >> 24u)), float((int(_e232) >> 24u))) / vec4(127.0)), vec4(-1.0)));
    uint _e264 = (depth & 65535u);
    uint _e266 = (depth >> 16u);
    uint _e270 = ((_e264 & 32767u) << 13u);
    uint _e272 = (_e270 & 260046848u);
    uint _e274 = (_e270 + 939524096u);
    uint _e298 = ((_e266 & 32767u) << 13u);
    uint _e300 = (_e298 & 260046848u);
    uint _e302 = (_e298 + 939524096u);
    float nz = ((vec2(uintBitsToFloat((((_e272 == 260046848u) ? (_e274 + 939524096u) : ((_e272 == 0u) ? floatBitsToUint((uintBitsToFloat((_e274 + 8388608u)) - 6.1035156e-5)) : _e274)) | ((_e264 & 32768u) << 16u))), uintBitsToFloat((((_e300 == 260046848u) ? (_e302 + 939524096u) : ((_e300 == 0u) ? floatBitsToUint((uintBitsToFloat((_e302 + 8388608u)) - 6.1035156e-5)) : _e302)) | ((_e266 & 32768u) << 16u)))).y + (max((vec2(float((int((normal << 16u)) >> 16u)), float((int(normal) >> 16u))) / vec2(32767.0)), vec2(-1.0)).x * 0.0)) + ((vec2(float((normal & 65535u)), float(((normal >> 16u) & 65535u))) / vec2(65535.0)).y * 0.0));
    out_f_check = vec4(back.xyz, nz);
    uvec4 _e366 = out_g_packed;
    vec4 _e368 = out_f_check;
    packing_fs_out _tmp_return = packing_fs_out(_e366, _e368);
    g_packed = _tmp_return.g_packed;
    f_check = _tmp_return.f_check;
    return;
}

