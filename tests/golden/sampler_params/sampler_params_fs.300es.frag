#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct sampler_params_fs_out {
    vec4 f_color;
};
uniform highp sampler2D albedo;

uniform highp sampler2D detail;

uniform highp sampler2DShadow sun_shadow;

uniform highp sampler2DShadow cascades_1;

uniform float u_texel;

in vec2 v_uv;
in float v_height;
out vec4 f_color;

vec4 tap_albedo(vec2 uv) {
    vec4 _e3 = texture(albedo, vec2(uv));
    return _e3;
}

vec4 blur_albedo(vec2 uv_1) {
    float _e2 = u_texel;
    vec4 _e6 = tap_albedo((uv_1 - vec2(_e2, 0.0)));
    float _e7 = u_texel;
    vec4 _e10 = tap_albedo((uv_1 + vec2(_e7, 0.0)));
    return ((_e6 + _e10) * 0.5);
}

vec4 tap_detail(vec2 uv_2) {
    vec4 _e3 = texture(detail, vec2(uv_2));
    return _e3;
}

vec4 blur_detail(vec2 uv_3) {
    float _e2 = u_texel;
    vec4 _e6 = tap_detail((uv_3 - vec2(_e2, 0.0)));
    float _e7 = u_texel;
    vec4 _e10 = tap_detail((uv_3 + vec2(_e7, 0.0)));
    return ((_e6 + _e10) * 0.5);
}

float pcf_sun_shadow(vec2 uv_4, float depth) {
    float lit = 0.0;
    int y = 0;
    int x = 0;
    lit = 0.0;
    y = -(1);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e32 = y;
            y = (_e32 + 1);
        }
        loop_init = false;
        int _e8 = y;
        if (!((_e8 < 2))) {
            break;
        }
        x = -(1);
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                int _e30 = x;
                x = (_e30 + 1);
            }
            loop_init_1 = false;
            int _e13 = x;
            if (!((_e13 < 2))) {
                break;
            }
            int _e16 = x;
            int _e18 = y;
            float _e22 = u_texel;
            float _e27 = texture(sun_shadow, vec3((uv_4 + (vec2(float(_e16), float(_e18)) * _e22)), depth));
            float _e28 = lit;
            lit = (_e28 + _e27);
        }
    }
    float _e34 = lit;
    return (_e34 / 9.0);
}

float pcf_cascades_1_(vec2 uv_5, float depth_1) {
    float lit_1 = 0.0;
    int y_1 = 0;
    int x_1 = 0;
    lit_1 = 0.0;
    y_1 = -(1);
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e32 = y_1;
            y_1 = (_e32 + 1);
        }
        loop_init_2 = false;
        int _e8 = y_1;
        if (!((_e8 < 2))) {
            break;
        }
        x_1 = -(1);
        bool loop_init_3 = true;
        while(true) {
            if (!loop_init_3) {
                int _e30 = x_1;
                x_1 = (_e30 + 1);
            }
            loop_init_3 = false;
            int _e13 = x_1;
            if (!((_e13 < 2))) {
                break;
            }
            int _e16 = x_1;
            int _e18 = y_1;
            float _e22 = u_texel;
            float _e27 = texture(cascades_1, vec3((uv_5 + (vec2(float(_e16), float(_e18)) * _e22)), depth_1));
            float _e28 = lit_1;
            lit_1 = (_e28 + _e27);
        }
    }
    float _e34 = lit_1;
    return (_e34 / 9.0);
}

void main() {
    vec2 in_v_uv = v_uv;
    float in_v_height = v_height;
    vec4 out_f_color = vec4(0.0);
    vec4 _e2 = blur_albedo(in_v_uv);
    vec4 _e7 = blur_detail((in_v_uv * 4.0));
    vec4 base = ((_e2 * 0.75) + (_e7 * 0.25));
    float _e12 = pcf_sun_shadow(in_v_uv, 0.5);
    float _e13 = pcf_cascades_1_(in_v_uv, in_v_height);
    float lit_2 = (_e12 * _e13);
    vec4 _e18 = tap_detail(in_v_uv);
    out_f_color = vec4((base.xyz * lit_2), _e18.w);
    vec4 _e21 = out_f_color;
    sampler_params_fs_out _tmp_return = sampler_params_fs_out(_e21);
    f_color = _tmp_return.f_color;
    return;
}

