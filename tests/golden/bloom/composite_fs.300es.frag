#version 300 es

precision highp float;
precision highp int;

struct composite_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_exposure_block { float u_exposure; };

layout(std140) uniform u_bloom_strength_block { float u_bloom_strength; };

uniform highp sampler2D hdr_scene;

uniform highp sampler2D bloom_src;

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

vec3 aces(vec3 x) {
    vec3 a = (x * ((x * 2.51) + vec3(0.03)));
    vec3 b = ((x * ((x * 2.43) + vec3(0.59))) + vec3(0.14));
    return clamp((a / b), vec3(0.0), vec3(1.0));
}

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    v_uv = in_v_uv;
    vec2 _e3 = v_uv;
    vec4 _e6 = texture(hdr_scene, vec2(_e3));
    vec2 _e9 = v_uv;
    vec4 _e12 = texture(bloom_src, vec2(_e9));
    float _e15 = u_bloom_strength;
    vec3 hdr = (_e6.xyz + (_e12.xyz * _e15));
    float _e19 = u_exposure;
    vec3 _e21 = aces((hdr * _e19));
    f_color = vec4(pow(_e21, vec3((1.0 / 2.2))), 1.0);
    vec4 _e31 = f_color;
    composite_fs_out _tmp_return = composite_fs_out(_e31);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

