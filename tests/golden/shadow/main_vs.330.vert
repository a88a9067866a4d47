#version 330 core
struct main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
    vec4 v_light_space;
};
uniform mat4x4 u_light_vp;

uniform mat4x4 u_model;

uniform mat4x4 u_view;

uniform mat4x4 u_proj;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_world_pos;
out vec3 v_world_normal;
out vec4 v_light_space;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_world_pos = vec3(0.0);
    vec3 out_v_world_normal = vec3(0.0);
    vec4 out_v_light_space = vec4(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(in_a_pos, 1.0));
    out_v_world_pos = world.xyz;
    mat4x4 _e10 = u_model;
    out_v_world_normal = (_e10 * vec4(in_a_normal, 0.0)).xyz;
    mat4x4 _e17 = u_light_vp;
    out_v_light_space = (_e17 * world);
    mat4x4 _e21 = u_proj;
    mat4x4 _e23 = u_view;
    gen_gl_Position = (_e21 * (_e23 * world));
    vec4 _e26 = gen_gl_Position;
    vec3 _e27 = out_v_world_pos;
    vec3 _e28 = out_v_world_normal;
    vec4 _e29 = out_v_light_space;
    main_vs_out _tmp_return = main_vs_out(_e26, _e27, _e28, _e29);
    gl_Position = _tmp_return.gen_gl_Position;
    v_world_pos = _tmp_return.v_world_pos;
    v_world_normal = _tmp_return.v_world_normal;
    v_light_space = _tmp_return.v_light_space;
    return;
}

