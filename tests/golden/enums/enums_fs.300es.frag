#version 300 es

precision highp float;
precision highp int;

struct enums_fs_out {
    vec4 f_color;
};
const float WEIGHTS[4] = float[4](0.25, 0.5, 0.75, 1.0);

uniform int u_mode;

in vec2 v_uv;
out vec4 f_color;

float attenuate(uint f, float d) {
    if ((f == 1u)) {
        return 1.0;
    } else {
        if ((f == 2u)) {
            return max((1.0 - d), 0.0);
        }
    }
    return (1.0 / (1.0 + ((float(f) * d) * d)));
}

float channel(vec4 c, int ch) {
    return c[ch];
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    int _e2 = u_mode;
    int ch_1 = ((_e2 == 0) ? 0 : 2);
    uint f_1 = ((ch_1 > 1) ? 8u : 2u);
    vec4 c_1 = vec4(in_v_uv, 0.5, 1.0);
    float _e16 = attenuate(f_1, length(in_v_uv));
    float _e18 = channel(c_1, ch_1);
    out_f_color = vec4((_e18 * _e16), WEIGHTS[3], (float(ch_1) / 3.0), 1.0);
    vec4 _e26 = out_f_color;
    enums_fs_out _tmp_return = enums_fs_out(_e26);
    f_color = _tmp_return.f_color;
    return;
}

