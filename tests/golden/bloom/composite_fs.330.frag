#version 330 core
struct composite_fs_out {
    vec4 f_color;
};
uniform float u_exposure;

uniform float u_bloom_strength;

uniform sampler2D hdr_scene;

uniform sampler2D bloom_src;

in vec2 v_uv;
out vec4 f_color;

vec3 aces(vec3 x) {
    vec3 a = (x * ((x * 2.51) + vec3(0.03)));
    vec3 b = ((x * ((x * 2.43) + vec3(0.59))) + vec3(0.14));
    return clamp((a / b), vec3(0.0), vec3(1.0));
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 _e3 = texture(hdr_scene, vec2(in_v_uv));
    vec4 _e7 = texture(bloom_src, vec2(in_v_uv));
    float _e10 = u_bloom_strength;
    vec3 hdr = (_e3.xyz + (_e7.xyz * _e10));
    float _e14 = u_exposure;
    vec3 _e16 = aces((hdr * _e14));
    out_f_color = vec4(pow(_e16, vec3((1.0 / 2.2))), 1.0);
    vec4 _e24 = out_f_color;
    composite_fs_out _tmp_return = composite_fs_out(_e24);
    f_color = _tmp_return.f_color;
    return;
}

