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

in vec2 v_uv;
in vec3 v_dir;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec3 in_v_dir = v_dir;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    float s = 0.0;
    vec4 _e5 = texture(t_color, vec2(in_v_uv));
    c = _e5;
    vec4 _e7 = texture(t_color, vec2(in_v_uv), 0.5);
    vec4 _e8 = c;
    c = (_e8 + _e7);
    vec4 _e11 = textureLod(t_color, vec2(in_v_uv), 1.0);
    vec4 _e12 = c;
    c = (_e12 + _e11);
    vec3 _e15 = vec3(in_v_uv, 2.0);
    vec4 _e20 = texture(t_color, vec2((_e15.xy / vec2(_e15.z))));
    vec4 _e21 = c;
    c = (_e21 + _e20);
    vec4 _e27 = texelFetch(t_color, ivec2(3, 4), 0);
    vec4 _e28 = c;
    c = (_e28 + _e27);
    vec4 _e32 = texture(t_volume, vec3(in_v_dir));
    vec4 _e33 = c;
    c = (_e33 + _e32);
    vec4 _e37 = texture(t_sky, vec3(in_v_dir));
    vec4 _e38 = c;
    c = (_e38 + _e37);
    vec3 _e40 = vec3(in_v_uv, 2.0);
    vec4 _e47 = texture(t_layers, vec3(_e40.xy, int(roundEven(_e40.z))));
    vec4 _e48 = c;
    c = (_e48 + _e47);
    ivec2 size = ivec2(uvec2(textureSize(t_color, 0).xy));
    ivec3 layers = ivec3(ivec2(uvec2(textureSize(t_layers, 0).xy)), int(uint(textureSize(t_layers, 0).z)));
    float _e60 = texture(t_shadow, vec3(in_v_uv, 0.5));
    s = _e60;
    vec4 _e61 = vec4(in_v_uv, 0.5, 1.0);
    float _e68 = texture(t_shadow, vec3((_e61.xy / vec2(_e61.w)), (_e61.z / _e61.w)));
    float _e69 = s;
    s = (_e69 + _e68);
    vec3 _e71 = vec3(in_v_uv, 1.0);
    float _e78 = texture(t_shadow_layers, vec4(_e71.xy, int(roundEven(_e71.z)), 0.5));
    float _e79 = s;
    s = (_e79 + _e78);
    float _e83 = texture(t_shadow_cube, vec4(in_v_dir, 0.5));
    float _e84 = s;
    s = (_e84 + _e83);
    ivec4 id = texelFetch(t_ids, ivec2(0, 0), 0);
    float k = float(((size.x + layers.z) + id.x));
    vec4 _e96 = c;
    float _e97 = s;
    out_f_color = ((_e96 * _e97) + vec4((k * 0.0001)));
    vec4 _e103 = out_f_color;
    tex_fs_out _tmp_return = tex_fs_out(_e103);
    f_color = _tmp_return.f_color;
    return;
}

