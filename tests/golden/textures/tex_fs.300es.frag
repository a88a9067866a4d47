#version 300 es

precision highp float;
precision highp int;
precision highp sampler3D;
precision highp sampler2DShadow;
precision highp samplerCubeShadow;
precision highp sampler2DArray;
precision highp sampler2DArrayShadow;
precision highp isampler2D;

struct tex_fs_out {
    vec4 f_color;
};
uniform highp sampler2D t_color;

uniform highp sampler3D t_volume;

uniform highp samplerCube t_sky;

uniform highp sampler2DArray t_layers;

uniform highp sampler2DShadow t_shadow;

uniform highp sampler2DArrayShadow t_shadow_layers;

uniform highp samplerCubeShadow t_shadow_cube;

uniform highp isampler2D t_ids;

smooth in vec2 v_uv;
smooth in vec3 v_dir;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec3 in_v_dir = v_dir;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    float s = 0.0;
    vec4 _e5 = texture(t_color, vec2(in_v_uv));
    c = _e5;
    vec4 _e10 = texture(t_color, vec2(in_v_uv), 0.5);
    vec4 _e11 = c;
    c = (_e11 + _e10);
    vec4 _e17 = textureLod(t_color, vec2(in_v_uv), 1.0);
    vec4 _e18 = c;
    c = (_e18 + _e17);
    vec3 _e22 = vec3(in_v_uv, 2.0);
    vec4 _e29 = texture(t_color, vec2((_e22.xy / vec2(_e22.z))));
    vec4 _e30 = c;
    c = (_e30 + _e29);
    vec4 _e38 = texelFetch(t_color, ivec2(3, 4), 0);
    vec4 _e39 = c;
    c = (_e39 + _e38);
    vec4 _e44 = texture(t_volume, vec3(in_v_dir));
    vec4 _e45 = c;
    c = (_e45 + _e44);
    vec4 _e50 = texture(t_sky, vec3(in_v_dir));
    vec4 _e51 = c;
    c = (_e51 + _e50);
    vec3 _e55 = vec3(in_v_uv, 2.0);
    vec4 _e62 = texture(t_layers, vec3(_e55.xy, int(roundEven(_e55.z))));
    vec4 _e63 = c;
    c = (_e63 + _e62);
    ivec2 size = ivec2(uvec2(textureSize(t_color, 0).xy));
    ivec3 layers = ivec3(ivec2(uvec2(textureSize(t_layers, 0).xy)), int(uint(textureSize(t_layers, 0).z)));
    float _e80 = texture(t_shadow, vec3(in_v_uv, 0.5));
    s = _e80;
    vec4 _e84 = vec4(in_v_uv, 0.5, 1.0);
    float _e93 = texture(t_shadow, vec3((_e84.xy / vec2(_e84.w)), (_e84.z / _e84.w)));
    float _e94 = s;
    s = (_e94 + _e93);
    vec3 _e98 = vec3(in_v_uv, 1.0);
    float _e106 = texture(t_shadow_layers, vec4(_e98.xy, int(roundEven(_e98.z)), 0.5));
    float _e107 = s;
    s = (_e107 + _e106);
    float _e113 = texture(t_shadow_cube, vec4(in_v_dir, 0.5));
    float _e114 = s;
    s = (_e114 + _e113);
    ivec4 id = texelFetch(t_ids, ivec2(0, 0), 0);
    float k = float(((size.x + layers.z) + id.x));
    vec4 _e130 = c;
    float _e132 = s;
    out_f_color = ((_e130 * _e132) + vec4((k * 0.0001)));
    vec4 _e139 = out_f_color;
    tex_fs_out _tmp_return = tex_fs_out(_e139);
    f_color = _tmp_return.f_color;
    return;
}

