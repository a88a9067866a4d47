#version 300 es

precision highp float;
precision highp int;

struct matrix_conversions_fs_out {
    vec4 f_color;
};
smooth in vec3 _vs2fs_location0;
smooth in vec2 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec3 v_normal = _vs2fs_location0;
    vec2 v_skew = _vs2fs_location1;
    vec4 f_color = vec4(0.0);
    vec3 n = normalize(v_normal);
    mat2x2 _e9 = (mat2x2(vec2(1.0, 0.0), vec2(0.0, 1.0)) * 0.5);
    mat3x3 m = mat3x3(vec3(_e9[0].x, _e9[0].y, 0.0), vec3(_e9[1].x, _e9[1].y, 0.0), vec3(0.0, 0.0, 1.0));
    f_color = (vec4((((m * n) * 0.5) + vec3(0.5)), 1.0) + vec4((v_skew * 0.0), 0.0, 0.0));
    vec4 _e38 = f_color;
    matrix_conversions_fs_out _tmp_return = matrix_conversions_fs_out(_e38);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

