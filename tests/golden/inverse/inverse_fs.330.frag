#version 330 core
struct inverse_fs_out {
    vec4 f_color;
};
smooth in vec3 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec3 v_normal = _vs2fs_location0;
    vec4 f_color = vec4(0.0);
    f_color = vec4(((v_normal * 0.5) + vec3(0.5)), 1.0);
    vec4 _e10 = f_color;
    inverse_fs_out _tmp_return = inverse_fs_out(_e10);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

