#version 300 es

precision highp float;
precision highp int;

struct pp_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_light_dir_block { vec3 u_light_dir; };

smooth in vec3 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

float lambert(vec3 n, vec3 l) {
    return (max(dot(n, l), 0.0) + 0.15);
}

void main() {
    vec3 v_normal = _vs2fs_location0;
    vec4 f_color = vec4(0.0);
    vec3 c = vec3(0.0);
    vec3 n_1 = normalize(v_normal);
    vec3 _e4 = u_light_dir;
    float _e5 = lambert(n_1, _e4);
    c = vec3(_e5);
    vec3 _e9 = c;
    c = (_e9 * 0.9);
    vec3 _e13 = c;
    f_color = vec4(_e13, 1.0);
    vec4 _e17 = f_color;
    pp_fs_out _tmp_return = pp_fs_out(_e17);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

