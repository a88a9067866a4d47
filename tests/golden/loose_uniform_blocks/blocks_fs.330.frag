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
struct blocks_fs_out {
    vec4 f_color;
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

in vec2 v_p;
in vec2 v_m;
in float v_k;
out vec4 f_color;

void main() {
    vec2 in_v_p = v_p;
    vec2 in_v_m = v_m;
    float in_v_k = v_k;
    vec4 out_f_color = vec4(0.0);
    float s = 0.0;
    int i = 0;
    float on = 0.0;
    s = 0.0;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e19 = i;
            i = (_e19 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < 9))) {
            break;
        }
        int _e13 = i;
        vec4 _e15 = uniforms.u_weights[_e13];
        float _e17 = s;
        s = (_e17 + _e15.x);
    }
    uint _e24 = uniforms.u_index;
    float _e27 = uniforms.u_taps[_e24].x;
    float _e31 = uniforms.u_taps[2].y;
    float t = (_e27 + _e31);
    mat3x3 _e34 = uniforms.u_basis;
    vec3 _e36 = uniforms.u_tint;
    vec3 c = (_e34 * _e36);
    vec3 _e40 = uniforms.u_gains[1];
    float _e42 = uniforms.u_bias;
    vec3 g = (_e40 * _e42);
    vec4 _e49 = uniforms.u_mix[0];
    vec4 _e52 = uniforms.u_mix[1];
    vec4 _e55 = uniforms.u_mix[2];
    vec4 _e58 = uniforms.u_mix[3];
    vec4 mx = (vec2(in_v_p.x, in_v_m.y) * mat4x2(_e49.xy, _e52.xy, _e55.xy, _e58.xy));
    uint _e65 = uniforms.u_mask.y;
    on = ((_e65 != 0u) ? 0.05 : 0.0);
    uint _e72 = uniforms.u_on.x;
    if ((_e72 != 0u)) {
        float _e75 = on;
        on = (_e75 + 0.1);
    }
    uint _e79 = uniforms.u_on.z;
    if ((_e79 != 0u)) {
        float _e82 = on;
        on = (_e82 + 0.2);
    }
    uint _e86 = uniforms.u_levels.x;
    uint _e89 = uniforms.u_levels.y;
    float lv = (float((_e86 + _e89)) * 0.01);
    vec4 _e95 = uniforms.u_color;
    vec3 base = (((_e95.xyz * 0.5) + (c * 0.1)) + g);
    float _e110 = on;
    float _e118 = s;
    ivec4 _e124 = uniforms.u_steps[1];
    vec3 rgb = (((base + (vec3(in_v_p.x, in_v_p.y, in_v_k) * 0.25)) + (vec3(mx.x, (mx.y + _e110), (mx.z + lv)) * 0.1)) + vec3((((t * 0.1) + (_e118 * 0.02)) + (float(_e124.x) * 0.01))));
    out_f_color = vec4(clamp(rgb, vec3(0.0), vec3(1.0)), 1.0);
    vec4 _e137 = out_f_color;
    blocks_fs_out _tmp_return = blocks_fs_out(_e137);
    f_color = _tmp_return.f_color;
    return;
}

