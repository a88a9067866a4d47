#version 330 core
struct Accum {
    vec3 sum;
    float weight;
};
struct references_fs_out {
    vec4 f_color;
};
uniform vec4 u_taps[4];

in vec2 v_uv;
out vec4 f_color;

float falloff(float d, float k) {
    float d_1 = 0.0;
    d_1 = d;
    float _e3 = d_1;
    d_1 = max(_e3, 0.0);
    float _e6 = d_1;
    d_1 = (_e6 * k);
    float _e9 = d_1;
    float _e10 = d_1;
    return (1.0 / (1.0 + (_e9 * _e10)));
}

void add_tap(inout Accum acc_1, vec3 c_1, float w) {
    vec3 _e5 = acc_1.sum;
    acc_1.sum = (_e5 + (c_1 * w));
    float _e8 = acc_1.weight;
    acc_1.weight = (_e8 + w);
    return;
}

void clamp_into(inout float x_2, float lo, float hi) {
    float _e3 = x_2;
    x_2 = clamp(_e3, lo, hi);
    return;
}

void settle(inout Accum acc_2) {
    float _e3 = acc_2.weight;
    vec3 _e7 = acc_2.sum;
    float _e9 = acc_2.weight;
    acc_2.sum = ((_e3 > 0.0) ? (_e7 / vec3(_e9)) : vec3(0.0));
    acc_2.weight = 1.0;
    return;
}

vec3 mean(Accum acc_3) {
    return ((acc_3.weight > 0.0) ? (acc_3.sum / vec3(acc_3.weight)) : vec3(0.0));
}

void saturate2_(inout vec2 v_1) {
    vec2 _e1 = v_1;
    v_1 = clamp(_e1, vec2(0.0), vec2(1.0));
    return;
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    Accum acc = Accum(vec3(0.0), 0.0);
    float weights[4] = float[4](0.0, 0.0, 0.0, 0.0);
    int i = 0;
    float x = 0.0;
    vec3 c = vec3(0.0);
    float x_1 = 0.0;
    vec2 v = vec2(0.0);
    acc = Accum(vec3(0.0), 0.0);
    weights = float[4](0.0, 0.0, 0.0, 0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e32 = i;
            i = (_e32 + 1);
        }
        loop_init = false;
        int _e10 = i;
        if (!((_e10 < 4))) {
            break;
        }
        int _e14 = i;
        vec4 tap = u_taps[_e14];
        int _e17 = i;
        float _e22 = falloff(distance(in_v_uv, tap.xy), 4.0);
        weights[_e17] = _e22;
        int _e29 = i;
        float _e31 = weights[_e29];
        add_tap(acc, vec3(tap.z, tap.w, (1.0 - tap.z)), _e31);
    }
    float _e36 = weights[3];
    x = _e36;
    clamp_into(x, 0.0, 0.5);
    float _e39 = x;
    weights[3] = _e39;
    settle(acc);
    Accum _e41 = acc;
    vec3 _e42 = mean(_e41);
    c = _e42;
    float _e44 = c.y;
    x_1 = _e44;
    clamp_into(x_1, 0.1, 0.9);
    float _e48 = x_1;
    c.y = _e48;
    vec3 _e49 = c;
    v = _e49.xz;
    saturate2_(v);
    vec2 _e52 = v;
    vec3 _e53 = c;
    c = vec3(_e52.x, _e53.y, _e52.y);
    vec3 _e59 = c;
    float _e61 = weights[3];
    out_f_color = vec4(_e59, _e61);
    vec4 _e63 = out_f_color;
    references_fs_out _tmp_return = references_fs_out(_e63);
    f_color = _tmp_return.f_color;
    return;
}

