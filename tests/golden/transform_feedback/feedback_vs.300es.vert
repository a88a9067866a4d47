#version 300 es

precision highp float;
precision highp int;

struct feedback_vs_out {
    vec4 gen_gl_Position;
    float v_speed;
    vec3 o_pos;
    vec3 o_vel;
    int o_alive;
};
layout(std140) uniform u_dt_block { float u_dt; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out float _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec3 _vs2fs_location2;
flat out int _vs2fs_location3;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 a_vel = _p2vs_location1;
    float v_speed = 0.0;
    vec3 o_pos = vec3(0.0);
    vec3 o_vel = vec3(0.0);
    int o_alive = 0;
    vec4 gen_gl_Position = vec4(0.0);
    float _e8 = u_dt;
    vec3 v = (a_vel + (vec3(0.0, -(9.81), 0.0) * _e8));
    float _e13 = u_dt;
    o_pos = (a_pos + (v * _e13));
    o_vel = v;
    float _e20 = o_pos.y;
    o_alive = ((_e20 > 0.0) ? 1 : 0);
    v_speed = length(v);
    vec3 _e30 = o_pos;
    gen_gl_Position = vec4(_e30, 1.0);
    vec4 _e34 = gen_gl_Position;
    float _e36 = v_speed;
    vec3 _e38 = o_pos;
    vec3 _e40 = o_vel;
    int _e42 = o_alive;
    feedback_vs_out _tmp_return = feedback_vs_out(_e34, _e36, _e38, _e40, _e42);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_speed;
    _vs2fs_location1 = _tmp_return.o_pos;
    _vs2fs_location2 = _tmp_return.o_vel;
    _vs2fs_location3 = _tmp_return.o_alive;
    return;
}

