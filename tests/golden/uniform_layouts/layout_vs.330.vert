#version 330 core
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
layout(std140) uniform scene_ubo {
    mat3x3 normal_matrix;
    Light lights[4];
    Fog fog;
    int light_count;
    float exposure;
    vec2 tint;
} scene;

uniform mat4x4 u_mvp;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_pos;
out vec3 v_normal;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_normal = a_normal;
    vec3 out_v_pos = vec3(0.0);
    vec3 out_v_normal = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_pos = in_a_pos;
    mat3x3 _e6 = scene.normal_matrix;
    out_v_normal = (_e6 * in_a_normal);
    mat4x4 _e10 = u_mvp;
    gen_gl_Position = (_e10 * vec4(in_a_pos, 1.0));
    vec4 _e14 = gen_gl_Position;
    vec3 _e15 = out_v_pos;
    vec3 _e16 = out_v_normal;
    layout_vs_out _tmp_return = layout_vs_out(_e14, _e15, _e16);
    gl_Position = _tmp_return.gen_gl_Position;
    v_pos = _tmp_return.v_pos;
    v_normal = _tmp_return.v_normal;
    return;
}

