#version 330 core
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
            int _e19 = i;
            i = (_e19 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < 9))) {
            break;
        }
        int _e14 = i;
        float _e16 = u_weights[_e14];
        float _e17 = s;
        s = (_e17 + _e16);
    }
    uint _e24 = u_index;
    float _e27 = u_taps[_e24].x;
    float _e31 = u_taps[2].y;
    float t = (_e27 + _e31);
    mat3x3 _e34 = u_basis;
    vec3 _e36 = u_tint;
    vec3 c = (_e34 * _e36);
    vec3 _e40 = u_gains[1];
    float _e42 = u_bias;
    vec3 g = (_e40 * _e42);
    mat4x2 _e48 = u_mix;
    vec4 mx = (vec2(in_v_p.x, in_v_m.y) * _e48);
    bool _e53 = u_mask.y;
    on = (_e53 ? 0.05 : 0.0);
    bool _e59 = u_on.x;
    if (_e59) {
        float _e62 = on;
        on = (_e62 + 0.1);
    }
    bool _e66 = u_on.z;
    if (_e66) {
        float _e69 = on;
        on = (_e69 + 0.2);
    }
    uint _e73 = u_levels.x;
    uint _e76 = u_levels.y;
    float lv = (float((_e73 + _e76)) * 0.01);
    vec4 _e82 = u_color;
    vec3 base = (((_e82.xyz * 0.5) + (c * 0.1)) + g);
    float _e99 = on;
    float _e110 = s;
    int _e116 = u_steps[1];
    vec3 rgb = (((base + (vec3(in_v_p.x, in_v_p.y, in_v_k) * 0.25)) + (vec3(mx.x, (mx.y + _e99), (mx.z + lv)) * 0.1)) + vec3((((t * 0.1) + (_e110 * 0.02)) + (float(_e116) * 0.01))));
    out_f_color = vec4(clamp(rgb, vec3(0.0), vec3(1.0)), 1.0);
    vec4 _e132 = out_f_color;
    loose_fs_out _tmp_return = loose_fs_out(_e132);
    f_color = _tmp_return.f_color;
    return;
}

