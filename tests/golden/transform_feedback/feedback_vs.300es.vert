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
uniform float u_dt;

layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_vel;
out float v_speed;
out vec3 o_pos;
out vec3 o_vel;
flat out int o_alive;

void main() {
    vec3 in_a_pos = a_pos;
    vec3 in_a_vel = a_vel;
    float out_v_speed = 0.0;
    vec3 out_o_pos = vec3(0.0);
    vec3 out_o_vel = vec3(0.0);
    int out_o_alive = 0;
    vec4 gen_gl_Position = vec4(0.0);
    float _e7 = u_dt;
    vec3 v = (in_a_vel + (vec3(0.0, -(9.81), 0.0) * _e7));
    float _e11 = u_dt;
    out_o_pos = (in_a_pos + (v * _e11));
    out_o_vel = v;
    float _e17 = out_o_pos.y;
    out_o_alive = ((_e17 > 0.0) ? 1 : 0);
    out_v_speed = length(v);
    vec3 _e25 = out_o_pos;
    gen_gl_Position = vec4(_e25, 1.0);
    vec4 _e28 = gen_gl_Position;
    float _e29 = out_v_speed;
    vec3 _e30 = out_o_pos;
    vec3 _e31 = out_o_vel;
    int _e32 = out_o_alive;
    feedback_vs_out _tmp_return = feedback_vs_out(_e28, _e29, _e30, _e31, _e32);
    gl_Position = _tmp_return.gen_gl_Position;
    v_speed = _tmp_return.v_speed;
    o_pos = _tmp_return.o_pos;
    o_vel = _tmp_return.o_vel;
    o_alive = _tmp_return.o_alive;
    return;
}

