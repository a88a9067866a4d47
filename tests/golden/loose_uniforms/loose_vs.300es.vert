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

smooth out vec2 v_p;
smooth out vec2 v_m;
smooth out float v_k;

void main() {
    uint VertexID = uint(gl_VertexID);
    vec2 out_v_p = vec2(0.0);
    vec2 out_v_m = vec2(0.0);
    float out_v_k = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e1 = int(VertexID);
    vec2 c = vec2(float(((_e1 << uint(1)) & 2)), float((_e1 & 2)));
    vec2 a_pos = ((c * 2.0) - vec2(1.0));
    mat3x2 _e19 = u_shear;
    vec2 _e24 = u_offset;
    out_v_p = ((_e19 * vec3(a_pos, 1.0)) + _e24);
    mat2x2 _e28 = u_rot;
    out_v_m = (_e28 * a_pos);
    float _e33 = u_weights[0];
    float _e36 = u_weights[8];
    int _e38 = u_count;
    bool _e43 = u_flip;
    int _e50 = u_steps[3];
    out_v_k = (((_e33 + (_e36 * float(_e38))) + (_e43 ? 0.25 : 0.0)) + (float(_e50) * 0.01));
    mat4x4 _e57 = u_model;
    float _e59 = u_scale;
    gen_gl_Position = (_e57 * vec4((a_pos * _e59), 0.0, 1.0));
    vec4 _e66 = gen_gl_Position;
    vec2 _e68 = out_v_p;
    vec2 _e70 = out_v_m;
    float _e72 = out_v_k;
    loose_vs_out _tmp_return = loose_vs_out(_e66, _e68, _e70, _e72);
    gl_Position = _tmp_return.gen_gl_Position;
    v_p = _tmp_return.v_p;
    v_m = _tmp_return.v_m;
    v_k = _tmp_return.v_k;
    return;
}

