#version 330 core
struct feedback_vs_out {
    vec4 gen_gl_Position;
    float v_speed;
    vec3 o_pos;
    vec3 o_vel;
    int o_alive;
};
layout(std140) uniform u_dt_block { float u_dt; };

vec3 a_pos = vec3(0.0);

vec3 a_vel = vec3(0.0);

float v_speed = 0.0;

vec3 o_pos = vec3(0.0);

vec3 o_vel = vec3(0.0);

int o_alive = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out float _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec3 _vs2fs_location2;
flat out int _vs2fs_location3;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec3 in_a_vel = _p2vs_location1;
    a_pos = in_a_pos;
    a_vel = in_a_vel;
    vec3 _e5 = a_vel;
    float _e12 = u_dt;
    vec3 v = (_e5 + (vec3(0.0, -(9.81), 0.0) * _e12));
    vec3 _e17 = a_pos;
    float _e19 = u_dt;
    o_pos = (_e17 + (v * _e19));
    o_vel = v;
    float _e26 = o_pos.y;
    o_alive = ((_e26 > 0.0) ? 1 : 0);
    v_speed = length(v);
    vec3 _e36 = o_pos;
    gen_gl_Position = vec4(_e36, 1.0);
    vec4 _e40 = gen_gl_Position;
    float _e42 = v_speed;
    vec3 _e44 = o_pos;
    vec3 _e46 = o_vel;
    int _e48 = o_alive;
    feedback_vs_out _tmp_return = feedback_vs_out(_e40, _e42, _e44, _e46, _e48);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_speed;
    _vs2fs_location1 = _tmp_return.o_pos;
    _vs2fs_location2 = _tmp_return.o_vel;
    _vs2fs_location3 = _tmp_return.o_alive;
    return;
}

