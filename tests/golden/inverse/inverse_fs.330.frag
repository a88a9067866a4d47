#version 330 core
struct inverse_fs_out {
    vec4 f_color;
};
in vec3 v_normal;
out vec4 f_color;

void main() {
    vec3 in_v_normal = v_normal;
    vec4 out_f_color = vec4(0.0);
    out_f_color = vec4(((in_v_normal * 0.5) + vec3(0.5)), 1.0);
    vec4 _e8 = out_f_color;
    inverse_fs_out _tmp_return = inverse_fs_out(_e8);
    f_color = _tmp_return.f_color;
    return;
}

