#version 330 core
struct sky_vs_out {
    vec4 gen_gl_Position;
    vec3 v_dir;
};
layout(std140) uniform u_view_block { mat4x4 u_view; };

layout(std140) uniform u_proj_block { mat4x4 u_proj; };

vec3 a_position = vec3(0.0);

vec3 v_dir = vec3(0.0);

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
smooth out vec3 _vs2fs_location0;

void main() {
    vec3 in_a_position = _p2vs_location0;
    a_position = in_a_position;
    vec4 _e4 = u_view[0];
    vec4 _e8 = u_view[1];
    vec4 _e12 = u_view[2];
    mat3x3 rot = mat3x3(_e4.xyz, _e8.xyz, _e12.xyz);
    mat4x4 view = mat4x4(vec4(rot[0], 0.0), vec4(rot[1], 0.0), vec4(rot[2], 0.0), vec4(0.0, 0.0, 0.0, 1.0));
    vec3 _e32 = a_position;
    v_dir = _e32;
    mat4x4 _e34 = u_proj;
    vec3 _e37 = a_position;
    vec4 p = ((_e34 * view) * vec4(_e37, 1.0));
    gen_gl_Position = p.xyww;
    vec4 _e44 = gen_gl_Position;
    vec3 _e46 = v_dir;
    sky_vs_out _tmp_return = sky_vs_out(_e44, _e46);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_dir;
    return;
}

