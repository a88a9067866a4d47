#version 300 es

precision highp float;
precision highp int;

struct flow_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_steps_block { int u_steps; };

layout(std140) uniform u_threshold_block { float u_threshold; };

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

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
    vec2 in_v_uv = _vs2fs_location0;
    float acc = 0.0;
    int i = 0;
    uint count = 0u;
    int k = 0;
    float level = 0.0;
    v_uv = in_v_uv;
    acc = 0.0;
    i = 0;
    while(true) {
        int _e7 = i;
        int _e9 = u_steps;
        if (!((_e7 < _e9))) {
            break;
        }
        int _e14 = i;
        i = (_e14 + 1);
        int _e17 = i;
        if (((_e17 % 2) == 0)) {
            continue;
        }
        int _e25 = i;
        float _e28 = acc;
        acc = (_e28 + (1.0 / float(_e25)));
        float _e31 = acc;
        float _e33 = u_threshold;
        if ((_e31 > _e33)) {
            break;
        }
    }
    count = 0u;
    k = 2;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e49 = k;
            k = (_e49 + 1);
        }
        loop_init = false;
        int _e40 = k;
        if (!((_e40 < 7))) {
            break;
        }
        int _e45 = k;
        uint _e47 = count;
        count = (_e47 + uint(_e45));
    }
    float _e55 = v_uv.x;
    int _e56 = band(_e55);
    level = (float(_e56) / 3.0);
    float _e63 = v_uv.y;
    float _e69 = level;
    level = (_e69 * ((_e63 > 0.5) ? 1.0 : 0.5));
    float _e73 = acc;
    float _e75 = level;
    uint _e77 = count;
    f_color = vec4(_e73, _e75, (float(_e77) / 20.0), 1.0);
    vec4 _e84 = f_color;
    flow_fs_out _tmp_return = flow_fs_out(_e84);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

