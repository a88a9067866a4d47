#version 330 core
struct sky_vs_out {
    vec4 gen_gl_Position;
    vec3 v_dir;
};
uniform mat4x4 u_view;

uniform mat4x4 u_proj;

layout(location = 0) in vec3 a_position;
out vec3 v_dir;

void main() {
    vec3 in_a_position = a_position;
    vec3 out_v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    vec4 _e3 = u_view[0];
    vec4 _e6 = u_view[1];
    vec4 _e9 = u_view[2];
    mat3x3 rot = mat3x3(_e3.xyz, _e6.xyz, _e9.xyz);
    mat4x4 view = mat4x4(vec4(rot[0], 0.0), vec4(rot[1], 0.0), vec4(rot[2], 0.0), vec4(0.0, 0.0, 0.0, 1.0));
    out_v_dir = in_a_position;
    mat4x4 _e24 = u_proj;
    vec4 p = ((_e24 * view) * vec4(in_a_position, 1.0));
    gen_gl_Position = p.xyww;
    vec4 _e30 = gen_gl_Position;
    vec3 _e31 = out_v_dir;
    sky_vs_out _tmp_return = sky_vs_out(_e30, _e31);
    gl_Position = _tmp_return.gen_gl_Position;
    v_dir = _tmp_return.v_dir;
    return;
}

