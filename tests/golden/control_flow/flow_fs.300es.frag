#version 300 es

precision highp float;
precision highp int;

struct flow_fs_out {
    vec4 f_color;
};
uniform int u_steps;

uniform float u_threshold;

smooth in vec2 v_uv;
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
        int _e6 = i;
        int _e8 = u_steps;
        if (!((_e6 < _e8))) {
            break;
        }
        int _e13 = i;
        i = (_e13 + 1);
        int _e16 = i;
        if (((_e16 - (2 * (_e16 / 2))) == 0)) {
            continue;
        }
        int _e26 = i;
        float _e29 = acc;
        acc = (_e29 + (1.0 / float(_e26)));
        float _e32 = acc;
        float _e34 = u_threshold;
        if ((_e32 > _e34)) {
            break;
        }
    }
    count = 0u;
    k = 2;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e50 = k;
            k = (_e50 + 1);
        }
        loop_init = false;
        int _e41 = k;
        if (!((_e41 < 7))) {
            break;
        }
        int _e46 = k;
        uint _e48 = count;
        count = (_e48 + uint(_e46));
    }
    int _e55 = band(in_v_uv.x);
    level = (float(_e55) / 3.0);
    float _e66 = level;
    level = (_e66 * ((in_v_uv.y > 0.5) ? 1.0 : 0.5));
    float _e70 = acc;
    float _e72 = level;
    uint _e74 = count;
    out_f_color = vec4(_e70, _e72, (float(_e74) / 20.0), 1.0);
    vec4 _e81 = out_f_color;
    flow_fs_out _tmp_return = flow_fs_out(_e81);
    f_color = _tmp_return.f_color;
    return;
}

