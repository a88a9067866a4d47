#version 300 es

precision highp float;
precision highp int;
precision highp sampler3D;
precision highp sampler2DShadow;
precision highp sampler2DArray;

struct texel_offsets_fs_out {
    vec4 f_color;
};
uniform highp sampler2D albedo;

uniform highp sampler2DArray layers;

uniform highp sampler3D volume;

uniform highp sampler2DShadow sun_shadow;

in vec2 v_uv;
out vec4 f_color;

float pcf4_(vec2 uv, float depth) {
    float lit = 0.0;
    float _e7 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(0, 0));
    lit = _e7;
    float _e10 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(1, 0));
    float _e11 = lit;
    lit = (_e11 + _e10);
    float _e14 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(0, 1));
    float _e15 = lit;
    lit = (_e15 + _e14);
    float _e18 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(1, 1));
    float _e19 = lit;
    lit = (_e19 + _e18);
    float _e21 = lit;
    return (_e21 * 0.25);
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 FragCoord = gl_FragCoord;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    vec4 _e8 = textureOffset(albedo, vec2(in_v_uv), ivec2(-2, 3));
    c = _e8;
    vec4 _e13 = textureOffset(albedo, vec2(in_v_uv), ivec2(-1, 0), 0.5);
    vec4 _e14 = c;
    c = (_e14 + _e13);
    vec3 _e17 = vec3(in_v_uv, 1.0);
    vec4 _e28 = textureLodOffset(layers, vec3(_e17.xy, int(roundEven(_e17.z))), 0.0, ivec2(7, -8));
    vec4 _e29 = c;
    c = (_e29 + _e28);
    vec4 _e36 = textureOffset(volume, vec3(vec3(in_v_uv, 0.5)), ivec3(0, 1, -1));
    vec4 _e37 = c;
    c = (_e37 + _e36);
    vec4 _e43 = texelFetch(albedo, (ivec2(FragCoord.xy) + ivec2(1, 1)), 0);
    vec4 _e44 = c;
    c = (_e44 + _e43);
    ivec3 _e49 = ivec3(ivec2(FragCoord.xy), 2);
    vec4 _e54 = texelFetch(layers, ivec3((_e49.xy + ivec2(1, 0)), _e49.z), 0);
    vec4 _e55 = c;
    c = (_e55 + _e54);
    vec4 _e58 = c;
    float _e59 = pcf4_(in_v_uv, 0.5);
    out_f_color = (_e58 * _e59);
    vec4 _e61 = out_f_color;
    texel_offsets_fs_out _tmp_return = texel_offsets_fs_out(_e61);
    f_color = _tmp_return.f_color;
    return;
}

