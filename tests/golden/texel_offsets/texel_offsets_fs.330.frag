#version 330 core
struct texel_offsets_fs_out {
    vec4 f_color;
};
uniform sampler2D albedo;

uniform sampler2DArray layers;

uniform sampler3D volume;

uniform sampler2DShadow sun_shadow;

smooth in vec2 v_uv;
out vec4 f_color;

float pcf4_(vec2 uv, float depth) {
    float lit = 0.0;
    float _e8 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(0, 0));
    lit = _e8;
    float _e15 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(1, 0));
    float _e16 = lit;
    lit = (_e16 + _e15);
    float _e24 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(0, 1));
    float _e25 = lit;
    lit = (_e25 + _e24);
    float _e33 = textureOffset(sun_shadow, vec3(uv, depth), ivec2(1, 1));
    float _e34 = lit;
    lit = (_e34 + _e33);
    float _e37 = lit;
    return (_e37 * 0.25);
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 FragCoord = gl_FragCoord;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    vec4 _e8 = textureOffset(albedo, vec2(in_v_uv), ivec2(-2, 3));
    c = _e8;
    vec4 _e16 = textureOffset(albedo, vec2(in_v_uv), ivec2(-1, 0), 0.5);
    vec4 _e17 = c;
    c = (_e17 + _e16);
    vec3 _e21 = vec3(in_v_uv, 1.0);
    vec4 _e32 = textureLodOffset(layers, vec3(_e21.xy, int(roundEven(_e21.z))), 0.0, ivec2(7, -8));
    vec4 _e33 = c;
    c = (_e33 + _e32);
    vec4 _e44 = textureOffset(volume, vec3(vec3(in_v_uv, 0.5)), ivec3(0, 1, -1));
    vec4 _e45 = c;
    c = (_e45 + _e44);
    vec4 _e56 = texelFetch(albedo, (ivec2(FragCoord.xy) + ivec2(1, 1)), 0);
    vec4 _e57 = c;
    c = (_e57 + _e56);
    ivec3 _e63 = ivec3(ivec2(FragCoord.xy), 2);
    vec4 _e72 = texelFetch(layers, ivec3((_e63.xy + ivec2(1, 0)), _e63.z), 0);
    vec4 _e73 = c;
    c = (_e73 + _e72);
    vec4 _e77 = c;
    float _e79 = pcf4_(in_v_uv, 0.5);
    out_f_color = (_e77 * _e79);
    vec4 _e82 = out_f_color;
    texel_offsets_fs_out _tmp_return = texel_offsets_fs_out(_e82);
    f_color = _tmp_return.f_color;
    return;
}

