#version 330 core
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

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in float _p2vs_location2;
layout(location = 3) in float _p2vs_location3;
smooth out float _vs2fs_location0;
smooth out vec4 _vs2fs_location1;

void main() {
    vec3 a_origin = _p2vs_location0;
    vec3 a_velocity = _p2vs_location1;
    float a_birth = _p2vs_location2;
    float a_life = _p2vs_location3;
    float v_age = 0.0;
    vec4 v_color = vec4(0.0);
    float gen_gl_PointSize = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    float _e5 = u_time;
    float _e6 = (_e5 - a_birth);
    float t = (_e6 - (a_life * floor((_e6 / a_life))));
    v_age = (t / a_life);
    vec3 _e16 = u_gravity;
    vec3 p = ((a_origin + (a_velocity * t)) + (_e16 * ((0.5 * t) * t)));
    mat4x4 _e23 = u_view_proj;
    vec4 clip = (_e23 * vec4(p, 1.0));
    float _e29 = u_size;
    float _e32 = v_age;
    gen_gl_PointSize = clamp(((_e29 * (1.0 - (_e32 * 0.5))) / max(clip.w, 0.001)), 1.0, 64.0);
    float _e56 = v_age;
    v_color = mix(vec4(1.0, 0.9, 0.5, 1.0), vec4(0.8, 0.2, 0.1, 0.0), vec4(_e56));
    gen_gl_Position = clip;
    vec4 _e61 = gen_gl_Position;
    float _e63 = v_age;
    vec4 _e65 = v_color;
    float _e67 = gen_gl_PointSize;
    particles_vs_out _tmp_return = particles_vs_out(_e61, _e63, _e65, _e67);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_age;
    _vs2fs_location1 = _tmp_return.v_color;
    gl_PointSize = _tmp_return.gen_gl_PointSize;
    return;
}

