#version 300 es

precision highp float;
precision highp int;

struct shadow_fs_out {
    vec4 f_FragColor;
};
vec4 f_FragColor = vec4(0.0);

vec4 gen_gl_FragCoord = vec4(0.0);

layout(location = 0) out vec4 _fs2p_location0;

vec4 encode_depth(float d) {
    vec4 digits = fract((d * vec4(1.0, 255.0, 65025.0, 16581375.0)));
    return (digits - (digits.yzww * vec4((1.0 / 255.0), (1.0 / 255.0), (1.0 / 255.0), 0.0)));
}

void main() {
    vec4 in_FragCoord = gl_FragCoord;
    gen_gl_FragCoord = in_FragCoord;
    float _e5 = gen_gl_FragCoord.z;
    vec4 _e6 = encode_depth(_e5);
    f_FragColor = _e6;
    vec4 _e8 = f_FragColor;
    shadow_fs_out _tmp_return = shadow_fs_out(_e8);
    _fs2p_location0 = _tmp_return.f_FragColor;
    return;
}

