#version 330 core
struct cascades_shadow_fs_out {
    vec4 f_FragColor;
};
out vec4 f_FragColor;

void main() {
    vec4 out_f_FragColor = vec4(0.0);
    out_f_FragColor = vec4(1.0);
    vec4 _e3 = out_f_FragColor;
    cascades_shadow_fs_out _tmp_return = cascades_shadow_fs_out(_e3);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

