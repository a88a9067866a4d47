#version 330 core
struct struct_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
};
layout(std140) uniform u_mvp_block { mat4x4 u_mvp; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec3 v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_normal = a_normal;
    mat4x4 _e5 = u_mvp;
    gen_gl_Position = (_e5 * vec4(a_pos, 1.0));
    vec4 _e10 = gen_gl_Position;
    vec3 _e12 = v_normal;
    struct_vs_out _tmp_return = struct_vs_out(_e10, _e12);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    return;
}

