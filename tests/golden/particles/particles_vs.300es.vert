#version 300 es

precision highp float;
precision highp int;

struct particles_vs_out {
    vec4 gen_gl_Position;
    float v_age;
    vec4 v_color;
    float gen_gl_PointSize;
};
uniform mat4x4 u_view_proj;

uniform float u_time;

uniform float u_size;

uniform vec3 u_gravity;

layout(location = 0) in vec3 a_origin;
layout(location = 1) in vec3 a_velocity;
layout(location = 2) in float a_birth;
layout(location = 3) in float a_life;
out float v_age;
out vec4 v_color;

void main() {
    vec3 in_a_origin = a_origin;
    vec3 in_a_velocity = a_velocity;
    float in_a_birth = a_birth;
    float in_a_life = a_life;
    float out_v_age = 0.0;
    vec4 out_v_color = vec4(0.0);
    float gen_gl_PointSize = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    float _e5 = u_time;
    float _e6 = (_e5 - in_a_birth);
    float t = (_e6 - (in_a_life * floor((_e6 / in_a_life))));
    out_v_age = (t / in_a_life);
    vec3 _e16 = u_gravity;
    vec3 p = ((in_a_origin + (in_a_velocity * t)) + (_e16 * ((0.5 * t) * t)));
    mat4x4 _e23 = u_view_proj;
    vec4 clip = (_e23 * vec4(p, 1.0));
    float _e29 = u_size;
    float _e30 = out_v_age;
    gen_gl_PointSize = clamp(((_e29 * (1.0 - (_e30 * 0.5))) / max(clip.w, 0.001)), 1.0, 64.0);
    float _e48 = out_v_age;
    out_v_color = mix(vec4(1.0, 0.9, 0.5, 1.0), vec4(0.8, 0.2, 0.1, 0.0), vec4(_e48));
    gen_gl_Position = clip;
    vec4 _e52 = gen_gl_Position;
    float _e53 = out_v_age;
    vec4 _e54 = out_v_color;
    float _e55 = gen_gl_PointSize;
    particles_vs_out _tmp_return = particles_vs_out(_e52, _e53, _e54, _e55);
    gl_Position = _tmp_return.gen_gl_Position;
    v_age = _tmp_return.v_age;
    v_color = _tmp_return.v_color;
    gl_PointSize = _tmp_return.gen_gl_PointSize;
    return;
}

