#version 330 core
struct tex_fs_out {
    vec4 f_color;
};
uniform sampler2D t_color;

uniform sampler3D t_volume;

uniform samplerCube t_sky;

uniform sampler2DArray t_layers;

uniform sampler2DShadow t_shadow;

uniform sampler2DArrayShadow t_shadow_layers;

uniform samplerCubeShadow t_shadow_cube;

uniform isampler2D t_ids;

vec2 v_uv = vec2(0.0);

vec3 v_dir = vec3(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    vec3 in_v_dir = _vs2fs_location1;
    vec4 c = vec4(0.0);
    float s = 0.0;
    v_uv = in_v_uv;
    v_dir = in_v_dir;
    vec2 _e6 = v_uv;
    vec4 _e9 = texture(t_color, vec2(_e6));
    c = _e9;
    vec2 _e12 = v_uv;
    vec4 _e16 = texture(t_color, vec2(_e12), 0.5);
    vec4 _e17 = c;
    c = (_e17 + _e16);
    vec2 _e21 = v_uv;
    vec4 _e25 = textureLod(t_color, vec2(_e21), 1.0);
    vec4 _e26 = c;
    c = (_e26 + _e25);
    vec2 _e30 = v_uv;
    vec3 _e32 = vec3(_e30, 2.0);
    vec4 _e39 = texture(t_color, vec2((_e32.xy / vec2(_e32.z))));
    vec4 _e40 = c;
    c = (_e40 + _e39);
    vec4 _e48 = texelFetch(t_color, ivec2(3, 4), 0);
    vec4 _e49 = c;
    c = (_e49 + _e48);
    vec3 _e53 = v_dir;
    vec4 _e56 = texture(t_volume, vec3(_e53));
    vec4 _e57 = c;
    c = (_e57 + _e56);
    vec3 _e61 = v_dir;
    vec4 _e64 = texture(t_sky, vec3(_e61));
    vec4 _e65 = c;
    c = (_e65 + _e64);
    vec2 _e69 = v_uv;
    vec3 _e71 = vec3(_e69, 2.0);
    vec4 _e78 = texture(t_layers, vec3(_e71.xy, int(roundEven(_e71.z))));
    vec4 _e79 = c;
    c = (_e79 + _e78);
    ivec2 size = ivec2(uvec2(textureSize(t_color, 0).xy));
    ivec3 layers = ivec3(ivec2(uvec2(textureSize(t_layers, 0).xy)), int(uint(textureSize(t_layers, 0).z)));
    vec2 _e94 = v_uv;
    float _e98 = texture(t_shadow, vec3(_e94, 0.5));
    s = _e98;
    vec2 _e101 = v_uv;
    vec4 _e104 = vec4(_e101, 0.5, 1.0);
    float _e113 = texture(t_shadow, vec3((_e104.xy / vec2(_e104.w)), (_e104.z / _e104.w)));
    float _e114 = s;
    s = (_e114 + _e113);
    vec2 _e118 = v_uv;
    vec3 _e120 = vec3(_e118, 1.0);
    float _e128 = texture(t_shadow_layers, vec4(_e120.xy, int(roundEven(_e120.z)), 0.5));
    float _e129 = s;
    s = (_e129 + _e128);
    vec3 _e133 = v_dir;
    float _e137 = texture(t_shadow_cube, vec4(_e133, 0.5));
    float _e138 = s;
    s = (_e138 + _e137);
    ivec4 id = texelFetch(t_ids, ivec2(0, 0), 0);
    float k = float(((size.x + layers.z) + id.x));
    vec4 _e154 = c;
    float _e156 = s;
    f_color = ((_e154 * _e156) + vec4((k * 0.0001)));
    vec4 _e163 = f_color;
    tex_fs_out _tmp_return = tex_fs_out(_e163);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

