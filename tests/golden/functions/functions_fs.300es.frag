#version 300 es

precision highp float;
precision highp int;

struct functions_fs_out {
    vec4 f_color;
};
uniform float u_time;

in vec2 v_uv;
out vec4 f_color;

float wave(float x, float t) {
    return (0.5 + (0.5 * sin(((x * 6.283) + t))));
}

float square(float x_1) {
    return (x_1 * x_1);
}

vec3 tint(vec3 c, vec3 by) {
    return (c * by);
}

float vignette(vec2 uv, float strength, float radius) {
    float d = length((uv - vec2(0.5)));
    return (1.0 - (strength * smoothstep((radius * 0.5), radius, d)));
}

float luma_float3_(vec3 c_1) {
    return dot(c_1, vec3(0.2126, 0.7152, 0.0722));
}

float luma_float4_(vec4 c_2) {
    float _e2 = luma_float3_(c_2.xyz);
    return (_e2 * c_2.w);
}

float banded(float x_2) {
    if ((x_2 < 0.1)) {
        return 0.0;
    }
    if ((x_2 > 0.9)) {
        return 1.0;
    } else {
        return (floor((x_2 * 4.0)) / 4.0);
    }
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    float _e3 = u_time;
    float _e4 = wave(in_v_uv.x, _e3);
    float _e6 = square(in_v_uv.y);
    vec3 _e13 = tint(vec3(_e4, _e6, 0.25), vec3(1.0, 0.9, 0.8));
    float _e16 = vignette(in_v_uv, 0.6, 0.75);
    float _e18 = vignette(in_v_uv, 0.2, 0.75);
    float _e21 = vignette(in_v_uv, 0.1, 0.9);
    float _e24 = vignette(in_v_uv, 0.6, 1.2);
    float v = (((_e16 * _e18) * _e21) * _e24);
    float _e27 = luma_float4_(vec4(_e13, 1.0));
    float _e28 = luma_float3_(_e13);
    float g = (_e27 + _e28);
    float _e34 = banded((g * 0.5));
    out_f_color = vec4((_e13 * v), _e34);
    vec4 _e36 = out_f_color;
    functions_fs_out _tmp_return = functions_fs_out(_e36);
    f_color = _tmp_return.f_color;
    return;
}

