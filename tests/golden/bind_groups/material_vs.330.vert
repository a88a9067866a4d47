#version 330 core
struct material_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
uniform mat4x4 u_view_proj;

uniform mat4x4 u_model;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec2 a_uv;
out vec2 v_uv;

void main() {
    vec3 in_a_pos = a_pos;
    vec2 in_a_uv = a_uv;
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = in_a_uv;
    mat4x4 _e5 = u_view_proj;
    mat4x4 _e7 = u_model;
    gen_gl_Position = ((_e5 * _e7) * vec4(in_a_pos, 1.0));
    vec4 _e12 = gen_gl_Position;
    vec2 _e13 = out_v_uv;
    material_vs_out _tmp_return = material_vs_out(_e12, _e13);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

