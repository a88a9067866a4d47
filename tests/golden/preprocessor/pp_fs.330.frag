#version 330 core
struct pp_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_light_dir_block { vec3 u_light_dir; };

vec3 v_normal = vec3(0.0);

vec4 f_color = vec4(0.0);

smooth in vec3 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

float lambert(vec3 n, vec3 l) {
    return (max(dot(n, l), 0.0) + 0.15);
}

void main() {
    vec3 in_v_normal = _vs2fs_location0;
    vec3 c = vec3(0.0);
    v_normal = in_v_normal;
    vec3 _e3 = v_normal;
    vec3 n_1 = normalize(_e3);
    vec3 _e7 = u_light_dir;
    float _e8 = lambert(n_1, _e7);
    c = vec3(_e8);
    vec3 _e12 = c;
    c = (_e12 * 0.9);
    vec3 _e16 = c;
    f_color = vec4(_e16, 1.0);
    vec4 _e20 = f_color;
    pp_fs_out _tmp_return = pp_fs_out(_e20);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

