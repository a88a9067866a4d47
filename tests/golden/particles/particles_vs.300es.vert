#version 300 es

precision highp float;
precision highp int;

struct particles_vs_out {
    vec4 gen_gl_Position;
    float v_age;
    vec4 v_color;
    float gen_gl_PointSize;
};
layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(std140) uniform u_time_block { float u_time; };

layout(std140) uniform u_size_block { float u_size; };

layout(std140) uniform u_gravity_block { vec3 u_gravity; };

vec3 a_origin = vec3(0.0);

vec3 a_velocity = vec3(0.0);

float a_birth = 0.0;

float a_life = 0.0;

float v_age = 0.0;

vec4 v_color = vec4(0.0);

float gen_gl_PointSize = 0.0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in float _p2vs_location2;
layout(location = 3) in float _p2vs_location3;
smooth out float _vs2fs_location0;
smooth out vec4 _vs2fs_location1;

void main() {
    vec3 in_a_origin = _p2vs_location0;
    vec3 in_a_velocity = _p2vs_location1;
    float in_a_birth = _p2vs_location2;
    float in_a_life = _p2vs_location3;
    a_origin = in_a_origin;
    a_velocity = in_a_velocity;
    a_birth = in_a_birth;
    a_life = in_a_life;
    float _e9 = u_time;
    float _e11 = a_birth;
    float _e12 = (_e9 - _e11);
    float _e14 = a_life;
    float t = (_e12 - (_e14 * floor((_e12 / _e14))));
    float _e21 = a_life;
    v_age = (t / _e21);
    vec3 _e24 = a_origin;
    vec3 _e26 = a_velocity;
    vec3 _e30 = u_gravity;
    vec3 p = ((_e24 + (_e26 * t)) + (_e30 * ((0.5 * t) * t)));
    mat4x4 _e37 = u_view_proj;
    vec4 clip = (_e37 * vec4(p, 1.0));
    float _e43 = u_size;
    float _e46 = v_age;
    gen_gl_PointSize = clamp(((_e43 * (1.0 - (_e46 * 0.5))) / max(clip.w, 0.001)), 1.0, 64.0);
    float _e70 = v_age;
    v_color = mix(vec4(1.0, 0.9, 0.5, 1.0), vec4(0.8, 0.2, 0.1, 0.0), vec4(_e70));
    gen_gl_Position = clip;
    vec4 _e75 = gen_gl_Position;
    float _e77 = v_age;
    vec4 _e79 = v_color;
    float _e81 = gen_gl_PointSize;
    particles_vs_out _tmp_return = particles_vs_out(_e75, _e77, _e79, _e81);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_age;
    _vs2fs_location1 = _tmp_return.v_color;
    gl_PointSize = _tmp_return.gen_gl_PointSize;
    return;
}

