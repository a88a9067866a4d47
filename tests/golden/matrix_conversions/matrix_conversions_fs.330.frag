#version 330 core
struct matrix_conversions_fs_out {
    vec4 f_color;
};
in vec3 v_normal;
in vec2 v_skew;
out vec4 f_color;

void main() {
    vec3 in_v_normal = v_normal;
    vec2 in_v_skew = v_skew;
    vec4 out_f_color = vec4(0.0);
    vec3 n = normalize(in_v_normal);
    mat2x2 _e9 = (mat2x2(vec2(1.0, 0.0), vec2(0.0, 1.0)) * 0.5);
    mat3x3 m = mat3x3(vec3(_e9[0].x, _e9[0].y, 0.0), vec3(_e9[1].x, _e9[1].y, 0.0), vec3(0.0, 0.0, 1.0));
    out_f_color = (vec4((((m * n) * 0.5) + vec3(0.5)), 1.0) + vec4((in_v_skew * 0.0), 0.0, 0.0));
    vec4 _e29 = out_f_color;
    matrix_conversions_fs_out _tmp_return = matrix_conversions_fs_out(_e29);
    f_color = _tmp_return.f_color;
    return;
}

