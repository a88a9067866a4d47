#version 330 core
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
        if (((_e17 - (2 * (_e17 / 2))) == 0)) {
            continue;
        }
        int _e27 = i;
        float _e30 = acc;
        acc = (_e30 + (1.0 / float(_e27)));
        float _e33 = acc;
        float _e35 = u_threshold;
        if ((_e33 > _e35)) {
            break;
        }
    }
    count = 0u;
    k = 2;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e51 = k;
            k = (_e51 + 1);
        }
        loop_init = false;
        int _e42 = k;
        if (!((_e42 < 7))) {
            break;
        }
        int _e47 = k;
        uint _e49 = count;
        count = (_e49 + uint(_e47));
    }
    float _e57 = v_uv.x;
    int _e58 = band(_e57);
    level = (float(_e58) / 3.0);
    float _e65 = v_uv.y;
    float _e71 = level;
    level = (_e71 * ((_e65 > 0.5) ? 1.0 : 0.5));
    float _e75 = acc;
    float _e77 = level;
    uint _e79 = count;
    f_color = vec4(_e75, _e77, (float(_e79) / 20.0), 1.0);
    vec4 _e86 = f_color;
    flow_fs_out _tmp_return = flow_fs_out(_e86);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

