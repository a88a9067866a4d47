#version 300 es

precision highp float;
precision highp int;

struct rgba8_shadow_fs_out {
    vec4 f_FragColor;
};
out vec4 f_FragColor;

vec4 encode_depth(float d) {
    vec4 digits = fract((d * vec4(1.0, 255.0, 65025.0, 16581375.0)));
    return (digits - (digits.yzww * vec4((1.0 / 255.0), (1.0 / 255.0), (1.0 / 255.0), 0.0)));
}

void main() {
    vec4 FragCoord = gl_FragCoord;
    vec4 out_f_FragColor = vec4(0.0);
    vec4 _e3 = encode_depth(FragCoord.z);
    out_f_FragColor = _e3;
    vec4 _e4 = out_f_FragColor;
    rgba8_shadow_fs_out _tmp_return = rgba8_shadow_fs_out(_e4);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

