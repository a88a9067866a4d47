#version 300 es

precision highp float;
precision highp int;

struct Light {
    vec3 position;
    float radius;
    vec4 color;
};
struct Fog {
    vec3 color;
    float density;
};
struct Scene {
    mat3x3 normal_matrix;
    Light lights[4];
    Fog fog;
    int light_count;
    float exposure;
    vec2 tint;
};
struct layout_vs_out {
    vec4 gen_gl_Position;
    vec3 v_pos;
    vec3 v_normal;
};
layout(std140) uniform scene_block { Scene scene; };

layout(std140) uniform u_mvp_block { mat4x4 u_mvp; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec3 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec3 v_pos = vec3(0.0);
    vec3 v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_pos = a_pos;
    mat3x3 _e6 = scene.normal_matrix;
    v_normal = (_e6 * a_normal);
    mat4x4 _e10 = u_mvp;
    gen_gl_Position = (_e10 * vec4(a_pos, 1.0));
    vec4 _e15 = gen_gl_Position;
    vec3 _e17 = v_pos;
    vec3 _e19 = v_normal;
    layout_vs_out _tmp_return = layout_vs_out(_e15, _e17, _e19);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_pos;
    _vs2fs_location1 = _tmp_return.v_normal;
    return;
}

