#version 300 es

precision highp float;
precision highp int;

struct deferred_geometry_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world;
    vec3 v_normal;
};
uniform mat4x4 u_model;

uniform mat4x4 u_view_proj;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_world = vec3(0.0);
    vec3 out_v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e3 = u_model;
    vec4 world = (_e3 * vec4(in_a_pos, 1.0));
    out_v_world = world.xyz;
    mat4x4 _e10 = u_model;
    out_v_normal = (_e10 * vec4(in_a_normal, 0.0)).xyz;
    mat4x4 _e17 = u_view_proj;
    gen_gl_Position = (_e17 * world);
    vec4 _e19 = gen_gl_Position;
    vec3 _e20 = out_v_world;
    vec3 _e21 = out_v_normal;
    deferred_geometry_vs_out _tmp_return = deferred_geometry_vs_out(_e19, _e20, _e21);
    gl_Position = _tmp_return.gen_gl_Position;
    v_world = _tmp_return.v_world;
    v_normal = _tmp_return.v_normal;
    return;
}

