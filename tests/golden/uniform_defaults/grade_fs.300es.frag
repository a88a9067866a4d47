#version 300 es

precision highp float;
precision highp int;

struct Grade {
    vec3 lift;
    float gamma;
    vec4 gain;
};
struct grade_fs_out {
    vec4 f_color;
};
uniform float u_exposure;

uniform int u_steps;

layout(std140) uniform u_grade_ubo {
    vec3 lift;
    float gamma;
    vec4 gain;
} u_grade;

uniform mat3x3 u_basis;

in vec2 v_uv;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    int _e3 = u_steps;
    int _e7 = u_steps;
    float banded = (floor((in_v_uv.x * float(_e3))) / float(_e7));
    mat3x3 _e11 = u_basis;
    float _e17 = u_exposure;
    vec3 _e21 = u_grade.lift;
    vec3 c = (((_e11 * vec3(banded, in_v_uv.y, 0.5)) * _e17) + _e21);
    float _e26 = u_grade.gamma;
    vec4 _e32 = u_grade.gain;
    out_f_color = (vec4(pow(c, vec3((1.0 / _e26))), 1.0) * _e32);
    vec4 _e34 = out_f_color;
    grade_fs_out _tmp_return = grade_fs_out(_e34);
    f_color = _tmp_return.f_color;
    return;
}

