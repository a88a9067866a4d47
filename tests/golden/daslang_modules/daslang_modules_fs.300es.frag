#version 300 es

precision highp float;
precision highp int;

struct daslang_modules_fs_out {
    vec4 f_color;
};
uniform highp sampler2D u_tex;

uniform float u_lift;

smooth in vec2 v_uv;
out vec4 f_color;

vec3 grade(vec3 c, float lift, float gain) {
    return pow(max(((c * gain) + vec3(lift)), vec3(0.0)), vec3((1.0 / 2.2)));
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 _e3 = texture(u_tex, vec2(in_v_uv));
    vec3 c_1 = _e3.xyz;
    float _e6 = fwidth(in_v_uv.x);
    float _e8 = dFdx(in_v_uv.y);
    float edge = (_e6 + abs(_e8));
    float _e12 = u_lift;
    vec2 _e13 = vec2(edge, _e12);
    uint _e16 = floatBitsToUint(_e13.x);
    uint _e20 = (_e16 & 2147483647u);
    uint _e49 = floatBitsToUint(_e13.y);
    uint _e51 = (_e49 & 2147483647u);
    uint packed_ = ((((_e20 >= 1199570944u) ? ((_e20 > 2139095040u) ? 32256u : 31744u) : ((_e20 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e20) + 0.5)) - 1056964608u) : (((_e20 + 3355447295u) + ((_e20 >> 13u) & 1u)) >> 13u))) | ((_e16 & 2147483648u) >> 16u)) | ((((_e51 >= 1199570944u) ? ((_e51 > 2139095040u) ? 32256u : 31744u) : ((_e51 < 947912704u) ? (floatBitsToUint((uintBitsToFloat(_e51) + 0.5)) - 1056964608u) : (((_e51 + 3355447295u) + ((_e51 >> 13u) & 1u)) >> 13u))) | ((_e49 & 2147483648u) >> 16u)) << 16u));
    uint _e72 = (packed_ & 65535u);
    uint _e73 = (packed_ >> 16u);
    uint _e76 = ((_e72 & 32767u) << 13u);
    uint _e78 = (_e76 & 260046848u);
    uint _e80 = (_e76 + 939524096u);
    uint _e99 = ((_e73 & 32767u) << 13u);
    uint _e100 = (_e99 & 260046848u);
    uint _e101 = (_e99 + 939524096u);
    vec2 back = vec2(uintBitsToFloat((((_e78 == 260046848u) ? (_e80 + 939524096u) : ((_e78 == 0u) ? floatBitsToUint((uintBitsToFloat((_e80 + 8388608u)) - 6.1035156e-5)) : _e80)) | ((_e72 & 32768u) << 16u))), uintBitsToFloat((((_e100 == 260046848u) ? (_e101 + 939524096u) : ((_e100 == 0u) ? floatBitsToUint((uintBitsToFloat((_e101 + 8388608u)) - 6.1035156e-5)) : _e101)) | ((_e73 & 32768u) << 16u))));
    vec3 _e124 = grade(fract((c_1 * 4.0)), back.y, (1.0 + back.x));
    out_f_color = vec4(_e124, 1.0);
    vec4 _e126 = out_f_color;
    daslang_modules_fs_out _tmp_return = daslang_modules_fs_out(_e126);
    f_color = _tmp_return.f_color;
    return;
}

