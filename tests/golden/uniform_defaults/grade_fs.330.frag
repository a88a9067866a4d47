#version 330 core
struct Grade {
    vec3 lift;
    float gamma;
    vec4 gain;
};
struct grade_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_exposure_block { float u_exposure; };

layout(std140) uniform u_steps_block { int u_steps; };

layout(std140) uniform u_grade_block { Grade u_grade; };

layout(std140) uniform u_basis_block { mat3x3 u_basis; };

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 v_uv = _vs2fs_location0;
    vec4 f_color = vec4(0.0);
    int _e3 = u_steps;
    int _e8 = u_steps;
    float banded = (floor((v_uv.x * float(_e3))) / float(_e8));
    mat3x3 _e12 = u_basis;
    float _e18 = u_exposure;
    vec3 _e22 = u_grade.lift;
    vec3 c = (((_e12 * vec3(banded, v_uv.y, 0.5)) * _e18) + _e22);
    float _e28 = u_grade.gamma;
    vec4 _e36 = u_grade.gain;
    f_color = (vec4(pow(c, vec3((1.0 / _e28))), 1.0) * _e36);
    vec4 _e39 = f_color;
    grade_fs_out _tmp_return = grade_fs_out(_e39);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

