#version 300 es

precision highp float;
precision highp int;

struct loose_vs_out {
    vec4 gen_gl_Position;
    vec2 v_p;
    vec2 v_m;
    float v_k;
};
uniform float u_scale;

uniform vec2 u_offset;

uniform bool u_flip;

uniform int u_count;

uniform float u_weights[9];

uniform mat3x2 u_shear;

uniform mat2x2 u_rot;

uniform mat4x4 u_model;

uniform int u_steps[4];

layout(location = 0) in vec2 a_pos;
smooth out vec2 v_p;
smooth out vec2 v_m;
smooth out float v_k;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_p = vec2(0.0);
    vec2 out_v_m = vec2(0.0);
    float out_v_k = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    mat3x2 _e3 = u_shear;
    vec2 _e8 = u_offset;
    out_v_p = ((_e3 * vec3(in_a_pos, 1.0)) + _e8);
    mat2x2 _e12 = u_rot;
    out_v_m = (_e12 * in_a_pos);
    float _e17 = u_weights[0];
    float _e20 = u_weights[8];
    int _e22 = u_count;
    bool _e27 = u_flip;
    int _e34 = u_steps[3];
    out_v_k = (((_e17 + (_e20 * float(_e22))) + (_e27 ? 0.25 : 0.0)) + (float(_e34) * 0.01));
    mat4x4 _e41 = u_model;
    float _e43 = u_scale;
    gen_gl_Position = (_e41 * vec4((in_a_pos * _e43), 0.0, 1.0));
    vec4 _e50 = gen_gl_Position;
    vec2 _e52 = out_v_p;
    vec2 _e54 = out_v_m;
    float _e56 = out_v_k;
    loose_vs_out _tmp_return = loose_vs_out(_e50, _e52, _e54, _e56);
    gl_Position = _tmp_return.gen_gl_Position;
    v_p = _tmp_return.v_p;
    v_m = _tmp_return.v_m;
    v_k = _tmp_return.v_k;
    return;
}

