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

out vec2 v_p;
out vec2 v_m;
out float v_k;

void main() {
    uint VertexID = uint(gl_VertexID);
    vec2 out_v_p = vec2(0.0);
    vec2 out_v_m = vec2(0.0);
    float out_v_k = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e1 = int(VertexID);
    vec2 c = vec2(float(((_e1 << uint(1)) & 2)), float((_e1 & 2)));
    vec2 a_pos = ((c * 2.0) - vec2(1.0));
    mat3x2 _e18 = u_shear;
    vec2 _e22 = u_offset;
    out_v_p = ((_e18 * vec3(a_pos, 1.0)) + _e22);
    mat2x2 _e26 = u_rot;
    out_v_m = (_e26 * a_pos);
    float _e31 = u_weights[0];
    float _e33 = u_weights[8];
    int _e35 = u_count;
    bool _e40 = u_flip;
    int _e47 = u_steps[3];
    out_v_k = (((_e31 + (_e33 * float(_e35))) + (_e40 ? 0.25 : 0.0)) + (float(_e47) * 0.01));
    mat4x4 _e54 = u_model;
    float _e56 = u_scale;
    gen_gl_Position = (_e54 * vec4((a_pos * _e56), 0.0, 1.0));
    vec4 _e60 = gen_gl_Position;
    vec2 _e61 = out_v_p;
    vec2 _e62 = out_v_m;
    float _e63 = out_v_k;
    loose_vs_out _tmp_return = loose_vs_out(_e60, _e61, _e62, _e63);
    gl_Position = _tmp_return.gen_gl_Position;
    v_p = _tmp_return.v_p;
    v_m = _tmp_return.v_m;
    v_k = _tmp_return.v_k;
    return;
}

