#version 300 es

precision highp float;
precision highp int;

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
layout(std140) uniform uniforms_ubo { Uniforms uniforms; };

smooth in vec2 v_p;
smooth in vec2 v_m;
smooth in float v_k;
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
            int _e21 = i;
            i = (_e21 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < 9))) {
            break;
        }
        int _e15 = i;
        vec4 _e17 = uniforms.u_weights[_e15];
        float _e19 = s;
        s = (_e19 + _e17.x);
    }
    uint _e28 = uniforms.u_index;
    float _e31 = uniforms.u_taps[_e28].x;
    float _e36 = uniforms.u_taps[2].y;
    float t = (_e31 + _e36);
    mat3x3 _e40 = uniforms.u_basis;
    vec3 _e43 = uniforms.u_tint;
    vec3 c = (_e40 * _e43);
    vec3 _e48 = uniforms.u_gains[1];
    float _e51 = uniforms.u_bias;
    vec3 g = (_e48 * _e51);
    vec4 _e59 = uniforms.u_mix[0];
    vec4 _e62 = uniforms.u_mix[1];
    vec4 _e65 = uniforms.u_mix[2];
    vec4 _e68 = uniforms.u_mix[3];
    vec4 mx = (vec2(in_v_p.x, in_v_m.y) * mat4x2(_e59.xy, _e62.xy, _e65.xy, _e68.xy));
    uint _e76 = uniforms.u_mask.y;
    on = ((_e76 != 0u) ? 0.05 : 0.0);
    uint _e85 = uniforms.u_on.x;
    if ((_e85 != 0u)) {
        float _e90 = on;
        on = (_e90 + 0.1);
    }
    uint _e95 = uniforms.u_on.z;
    if ((_e95 != 0u)) {
        float _e100 = on;
        on = (_e100 + 0.2);
    }
    uint _e105 = uniforms.u_levels.x;
    uint _e109 = uniforms.u_levels.y;
    float lv = (float((_e105 + _e109)) * 0.01);
    vec4 _e116 = uniforms.u_color;
    vec3 base = (((_e116.xyz * 0.5) + (c * 0.1)) + g);
    float _e133 = on;
    float _e144 = s;
    ivec4 _e151 = uniforms.u_steps[1];
    vec3 rgb = (((base + (vec3(in_v_p.x, in_v_p.y, in_v_k) * 0.25)) + (vec3(mx.x, (mx.y + _e133), (mx.z + lv)) * 0.1)) + vec3((((t * 0.1) + (_e144 * 0.02)) + (float(_e151.x) * 0.01))));
    out_f_color = vec4(clamp(rgb, vec3(0.0), vec3(1.0)), 1.0);
    vec4 _e168 = out_f_color;
    blocks_fs_out _tmp_return = blocks_fs_out(_e168);
    f_color = _tmp_return.f_color;
    return;
}

