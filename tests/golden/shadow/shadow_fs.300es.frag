#version 300 es

precision highp float;
precision highp int;

struct shadow_fs_out {
    vec4 f_FragColor;
};
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec4 f_FragColor = vec4(0.0);
    f_FragColor = vec4(1.0);
    vec4 _e4 = f_FragColor;
    shadow_fs_out _tmp_return = shadow_fs_out(_e4);
    _fs2p_location0 = _tmp_return.f_FragColor;
    return;
}

