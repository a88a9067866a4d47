#version 300 es

precision highp float;
precision highp int;

struct pp_fs_out {
    vec4 f_color;
};
uniform vec3 u_light_dir;

in vec3 v_normal;
out vec4 f_color;

float lambert(vec3 n, vec3 l) {
    return (max(dot(n, l), 0.0) + 0.15);
}

void main() {
    vec3 in_v_normal = v_normal;
    vec4 out_f_color = vec4(0.0);
    vec3 c = vec3(0.0);
    vec3 n_1 = normalize(in_v_normal);
    vec3 _e4 = u_light_dir;
    float _e5 = lambert(n_1, _e4);
    c = vec3(_e5);
    vec3 _e8 = c;
    c = (_e8 * 0.9);
    vec3 _e11 = c;
    out_f_color = vec4(_e11, 1.0);
    vec4 _e14 = out_f_color;
    pp_fs_out _tmp_return = pp_fs_out(_e14);
    f_color = _tmp_return.f_color;
    return;
}

