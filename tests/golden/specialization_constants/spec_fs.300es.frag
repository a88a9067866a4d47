#version 300 es

precision highp float;
precision highp int;

struct spec_fs_out {
    vec4 f_color;
};
const uint TAPS = 4u;
const float SPREAD = 0.125;
const bool INVERT = false;

uniform highp sampler2D u_tex;

in vec2 v_uv;
out vec4 f_color;

vec2 tap(uint i_1) {
    return vec2((float(i_1) * SPREAD), 0.0);
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    int i = 0;
    c = vec4(0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e20 = i;
            i = (_e20 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < int(TAPS)))) {
            break;
        }
        int _e11 = i;
        vec2 _e13 = tap(uint(_e11));
        vec4 _e17 = texture(u_tex, vec2((in_v_uv + _e13)));
        vec4 _e18 = c;
        c = (_e18 + _e17);
    }
    vec4 _e26 = c;
    c = (_e26 / vec4(float(max(TAPS, 1u))));
    vec4 _e33 = c;
    vec4 _e35 = c;
    out_f_color = (INVERT ? (vec4(1.0) - _e33) : _e35);
    vec4 _e37 = out_f_color;
    spec_fs_out _tmp_return = spec_fs_out(_e37);
    f_color = _tmp_return.f_color;
    return;
}

