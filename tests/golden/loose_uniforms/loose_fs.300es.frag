#version 300 es

precision highp float;
precision highp int;

struct loose_fs_out {
    vec4 f_color;
};
uniform vec3 u_tint;

uniform vec4 u_color;

uniform bvec2 u_mask;

uniform uint u_index;

uniform float u_weights[9];

uniform vec2 u_taps[3];

uniform mat3x3 u_basis;

uniform int u_steps[4];

uniform vec3 u_gains[2];

uniform float u_bias;

uniform uvec2 u_levels;

uniform bvec3 u_on;

uniform mat4x2 u_mix;

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
            int _e17 = i;
            i = (_e17 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < 9))) {
            break;
        }
        int _e12 = i;
        float _e14 = u_weights[_e12];
        float _e15 = s;
        s = (_e15 + _e14);
    }
    uint _e22 = u_index;
    float _e25 = u_taps[_e22].x;
    float _e28 = u_taps[2].y;
    float t = (_e25 + _e28);
    mat3x3 _e31 = u_basis;
    vec3 _e33 = u_tint;
    vec3 c = (_e31 * _e33);
    vec3 _e37 = u_gains[1];
    float _e39 = u_bias;
    vec3 g = (_e37 * _e39);
    mat4x2 _e45 = u_mix;
    vec4 mx = (vec2(in_v_p.x, in_v_m.y) * _e45);
    bool _e50 = u_mask.y;
    on = (_e50 ? 0.05 : 0.0);
    bool _e55 = u_on.x;
    if (_e55) {
        float _e57 = on;
        on = (_e57 + 0.1);
    }
    bool _e60 = u_on.z;
    if (_e60) {
        float _e62 = on;
        on = (_e62 + 0.2);
    }
    uint _e66 = u_levels.x;
    uint _e68 = u_levels.y;
    float lv = (float((_e66 + _e68)) * 0.01);
    vec4 _e74 = u_color;
    vec3 base = (((_e74.xyz * 0.5) + (c * 0.1)) + g);
    float _e89 = on;
    float _e97 = s;
    int _e103 = u_steps[1];
    vec3 rgb = (((base + (vec3(in_v_p.x, in_v_p.y, in_v_k) * 0.25)) + (vec3(mx.x, (mx.y + _e89), (mx.z + lv)) * 0.1)) + vec3((((t * 0.1) + (_e97 * 0.02)) + (float(_e103) * 0.01))));
    out_f_color = vec4(clamp(rgb, vec3(0.0), vec3(1.0)), 1.0);
    vec4 _e115 = out_f_color;
    loose_fs_out _tmp_return = loose_fs_out(_e115);
    f_color = _tmp_return.f_color;
    return;
}

