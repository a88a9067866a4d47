#version 300 es

precision highp float;
precision highp int;

struct Light {
    vec4 pos;
    vec4 color;
};
struct for_arrays_fs_out {
    vec4 f_color;
};
const float KERNEL[3] = float[3](0.25, 0.5, 0.25);
const int TAPS = 3;

uniform Light u_lights[4];

uniform int u_count;

in vec2 v_uv;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec3 c = vec3(0.0);
    int i = 0;
    float taps[3] = float[3](0.0, 0.0, 0.0);
    int t_index = 0;
    float blur = 0.0;
    int t_index_1 = 0;
    int i_1 = 0;
    float ramp = 0.0;
    int i_2 = 0;
    c = vec3(0.0);
    i = 0;
    int _e7 = u_count;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e34 = i;
            i = (_e34 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < _e7))) {
            break;
        }
        int _e11 = i;
        if ((uint(_e11) >= 4u)) {
            break;
        }
        int _e16 = i;
        Light l = u_lights[_e16];
        float d = distance(in_v_uv, l.pos.xy);
        int _e25 = i;
        vec3 _e32 = c;
        c = (_e32 + (l.color.xyz * (1.0 / ((1.0 + float(_e25)) + (d * d)))));
    }
    taps = float[3](0.0, 0.0, 0.0);
    t_index = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e51 = t_index;
            t_index = (_e51 + 1);
        }
        loop_init_1 = false;
        int _e41 = t_index;
        if (!((_e41 < 3))) {
            break;
        }
        int _e45 = t_index;
        float k = KERNEL[_e45];
        int _e47 = t_index;
        taps[_e47] = (k * in_v_uv.y);
    }
    blur = 0.0;
    t_index_1 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e63 = t_index_1;
            t_index_1 = (_e63 + 1);
        }
        loop_init_2 = false;
        int _e55 = t_index_1;
        if (!((_e55 < 3))) {
            break;
        }
        int _e58 = t_index_1;
        float _e60 = taps[_e58];
        float _e61 = blur;
        blur = (_e61 + _e60);
    }
    i_1 = 0;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            int _e80 = i_1;
            i_1 = (_e80 + 1);
        }
        loop_init_3 = false;
        int _e66 = i_1;
        if (!((_e66 < 3))) {
            break;
        }
        int _e69 = i_1;
        float _e71 = taps[_e69];
        int _e74 = i_1;
        float _e78 = blur;
        blur = (_e78 + (_e71 * KERNEL[((TAPS - 1) - _e74)]));
    }
    ramp = 0.0;
    {
        uint j_count = ((8 > 5) ? (uint(8) - uint(5)) : 0u);
        i_2 = 1;
        bool loop_init_4 = true;
        while(true) {
            if (!loop_init_4) {
                int _e113 = i_2;
                i_2 = (_e113 + 1);
            }
            loop_init_4 = false;
            int _e93 = i_2;
            if (!((_e93 < 10))) {
                break;
            }
            int _e96 = i_2;
            uint i_step = (uint(_e96) - uint(1));
            if ((i_step >= j_count)) {
                break;
            }
            if ((i_step >= 3u)) {
                break;
            }
            int j = (5 + int(i_step));
            float k_1 = KERNEL[int(i_step)];
            int _e107 = i_2;
            float _e111 = ramp;
            ramp = (_e111 + (float((_e107 * j)) * k_1));
        }
    }
    vec3 _e116 = c;
    float _e117 = blur;
    float _e120 = ramp;
    out_f_color = vec4((_e116 + vec3(_e117)), (_e120 / 50.0));
    vec4 _e124 = out_f_color;
    for_arrays_fs_out _tmp_return = for_arrays_fs_out(_e124);
    f_color = _tmp_return.f_color;
    return;
}

