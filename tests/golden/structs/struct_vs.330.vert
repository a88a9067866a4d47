#version 330 core
struct struct_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
};
layout(std140) uniform u_mvp_block { mat4x4 u_mvp; };

vec3 a_pos = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    vec3 _e6 = a_normal;
    v_normal = _e6;
    mat4x4 _e9 = u_mvp;
    vec3 _e11 = a_pos;
    gen_gl_Position = (_e9 * vec4(_e11, 1.0));
    vec4 _e16 = gen_gl_Position;
    vec3 _e18 = v_normal;
    struct_vs_out _tmp_return = struct_vs_out(_e16, _e18);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    return;
}

