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
layout(std140) uniform uniforms_ubo {
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
} uniforms;

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
    vec4 _e20 = uniforms.u_shear[0];
    vec4 _e23 = uniforms.u_shear[1];
    vec4 _e26 = uniforms.u_shear[2];
    vec2 _e32 = uniforms.u_offset;
    out_v_p = ((mat3x2(_e20.xy, _e23.xy, _e26.xy) * vec3(a_pos, 1.0)) + _e32);
    vec4 _e37 = uniforms.u_rot[0];
    vec4 _e40 = uniforms.u_rot[1];
    out_v_m = (mat2x2(_e37.xy, _e40.xy) * a_pos);
    vec4 _e47 = uniforms.u_weights[0];
    vec4 _e51 = uniforms.u_weights[8];
    int _e54 = uniforms.u_count;
    uint _e59 = uniforms.u_flip;
    ivec4 _e68 = uniforms.u_steps[3];
    out_v_k = (((_e47.x + (_e51.x * float(_e54))) + ((_e59 != 0u) ? 0.25 : 0.0)) + (float(_e68.x) * 0.01));
    mat4x4 _e76 = uniforms.u_model;
    float _e78 = uniforms.u_scale;
    gen_gl_Position = (_e76 * vec4((a_pos * _e78), 0.0, 1.0));
    vec4 _e82 = gen_gl_Position;
    vec2 _e83 = out_v_p;
    vec2 _e84 = out_v_m;
    float _e85 = out_v_k;
    blocks_vs_out _tmp_return = blocks_vs_out(_e82, _e83, _e84, _e85);
    gl_Position = _tmp_return.gen_gl_Position;
    v_p = _tmp_return.v_p;
    v_m = _tmp_return.v_m;
    v_k = _tmp_return.v_k;
    return;
}

