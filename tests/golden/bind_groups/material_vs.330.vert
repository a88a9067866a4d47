#version 330 core
struct material_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(std140) uniform u_model_block { mat4x4 u_model; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec2 _p2vs_location1;
smooth out vec2 _vs2fs_location0;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec2 a_uv = _p2vs_location1;
    vec2 v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = a_uv;
    mat4x4 _e5 = u_view_proj;
    mat4x4 _e7 = u_model;
    gen_gl_Position = ((_e5 * _e7) * vec4(a_pos, 1.0));
    vec4 _e13 = gen_gl_Position;
    vec2 _e15 = v_uv;
    material_vs_out _tmp_return = material_vs_out(_e13, _e15);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    return;
}

