#version 330 core
struct flow_fs_out {
    vec4 f_color;
};
uniform int u_steps;

uniform float u_threshold;

in vec2 v_uv;
out vec4 f_color;

int band(float x) {
    if ((x < 0.25)) {
        return 0;
    } else {
        if ((x < 0.5)) {
            return 1;
        } else {
            if ((x < 0.75)) {
                return 2;
            } else {
                return 3;
            }
        }
    }
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    float acc = 0.0;
    int i = 0;
    uint count = 0u;
    int k = 0;
    float level = 0.0;
    acc = 0.0;
    i = 0;
    while(true) {
        int _e5 = i;
        int _e7 = u_steps;
        if (!((_e5 < _e7))) {
            break;
        }
        int _e11 = i;
        i = (_e11 + 1);
        int _e13 = i;
        if (((_e13 - (2 * (_e13 / 2))) == 0)) {
            continue;
        }
        int _e20 = i;
        float _e23 = acc;
        acc = (_e23 + (1.0 / float(_e20)));
        float _e25 = acc;
        float _e27 = u_threshold;
        if ((_e25 > _e27)) {
            break;
        }
    }
    count = 0u;
    k = 2;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e40 = k;
            k = (_e40 + 1);
        }
        loop_init = false;
        int _e33 = k;
        if (!((_e33 < 7))) {
            break;
        }
        int _e36 = k;
        uint _e38 = count;
        count = (_e38 + uint(_e36));
    }
    int _e44 = band(in_v_uv.x);
    level = (float(_e44) / 3.0);
    float _e52 = level;
    level = (_e52 * ((in_v_uv.y > 0.5) ? 1.0 : 0.5));
    float _e55 = acc;
    float _e56 = level;
    uint _e57 = count;
    out_f_color = vec4(_e55, _e56, (float(_e57) / 20.0), 1.0);
    vec4 _e62 = out_f_color;
    flow_fs_out _tmp_return = flow_fs_out(_e62);
    f_color = _tmp_return.f_color;
    return;
}

