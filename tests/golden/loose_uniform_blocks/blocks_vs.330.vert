#version 330 core
struct Uniforms {
    float u_scale;
    vec2 u_offset;
    vec3 u_tint;
    vec4 u_color;
    uint u_flip;
    uvec2 u_mask;
    int u_count;
    uint u_index;
    vec4 u_weights[9];
    vec4 u_taps[3];
    vec4 u_shear[3];
    vec4 u_rot[2];
    mat3x3 u_basis;
    mat4x4 u_model;
    ivec4 u_steps[4];
    vec3 u_gains[2];
    float u_bias;
    uvec2 u_levels;
    uvec3 u_on;
    vec4 u_mix[4];
};
struct blocks_vs_out {
    vec4 gen_gl_Position;
    vec2 v_p;
    vec2 v_m;
    float v_k;
};
layout(std140) uniform uniforms_ubo { Uniforms uniforms; };

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
    vec4 _e5 = uniforms.u_shear[0];
    vec4 _e8 = uniforms.u_shear[1];
    vec4 _e11 = uniforms.u_shear[2];
    vec2 _e19 = uniforms.u_offset;
    out_v_p = ((mat3x2(_e5.xy, _e8.xy, _e11.xy) * vec3(in_a_pos, 1.0)) + _e19);
    vec4 _e25 = uniforms.u_rot[0];
    vec4 _e28 = uniforms.u_rot[1];
    out_v_m = (mat2x2(_e25.xy, _e28.xy) * in_a_pos);
    vec4 _e36 = uniforms.u_weights[0];
    vec4 _e41 = uniforms.u_weights[8];
    int _e45 = uniforms.u_count;
    uint _e51 = uniforms.u_flip;
    ivec4 _e61 = uniforms.u_steps[3];
    out_v_k = (((_e36.x + (_e41.x * float(_e45))) + ((_e51 != 0u) ? 0.25 : 0.0)) + (float(_e61.x) * 0.01));
    mat4x4 _e70 = uniforms.u_model;
    float _e73 = uniforms.u_scale;
    gen_gl_Position = (_e70 * vec4((in_a_pos * _e73), 0.0, 1.0));
    vec4 _e80 = gen_gl_Position;
    vec2 _e82 = out_v_p;
    vec2 _e84 = out_v_m;
    float _e86 = out_v_k;
    blocks_vs_out _tmp_return = blocks_vs_out(_e80, _e82, _e84, _e86);
    gl_Position = _tmp_return.gen_gl_Position;
    v_p = _tmp_return.v_p;
    v_m = _tmp_return.v_m;
    v_k = _tmp_return.v_k;
    return;
}

