#version 330 core
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

smooth in vec2 v_uv;
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
            int _e39 = i;
            i = (_e39 + 1);
        }
        loop_init = false;
        int _e8 = i;
        if (!((_e8 < _e7))) {
            break;
        }
        int _e12 = i;
        if ((uint(_e12) >= 4u)) {
            break;
        }
        int _e18 = i;
        Light l = u_lights[_e18];
        float d = distance(in_v_uv, l.pos.xy);
        int _e30 = i;
        vec3 _e37 = c;
        c = (_e37 + (l.color.xyz * (1.0 / ((1.0 + float(_e30)) + (d * d)))));
    }
    taps = float[3](0.0, 0.0, 0.0);
    t_index = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e60 = t_index;
            t_index = (_e60 + 1);
        }
        loop_init_1 = false;
        int _e47 = t_index;
        if (!((_e47 < 3))) {
            break;
        }
        int _e52 = t_index;
        float k = KERNEL[_e52];
        int _e56 = t_index;
        taps[_e56] = (k * in_v_uv.y);
    }
    blur = 0.0;
    t_index_1 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e79 = t_index_1;
            t_index_1 = (_e79 + 1);
        }
        loop_init_2 = false;
        int _e68 = t_index_1;
        if (!((_e68 < 3))) {
            break;
        }
        int _e74 = t_index_1;
        float _e76 = taps[_e74];
        float _e77 = blur;
        blur = (_e77 + _e76);
    }
    i_1 = 0;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            int _e105 = i_1;
            i_1 = (_e105 + 1);
        }
        loop_init_3 = false;
        int _e85 = i_1;
        if (!((_e85 < 3))) {
            break;
        }
        int _e91 = i_1;
        float _e93 = taps[_e91];
        int _e99 = i_1;
        float _e103 = blur;
        blur = (_e103 + (_e93 * KERNEL[((TAPS - 1) - _e99)]));
    }
    ramp = 0.0;
    {
        uint j_count = ((8 > 5) ? (uint(8) - uint(5)) : 0u);
        i_2 = 1;
        bool loop_init_4 = true;
        while(true) {
            if (!loop_init_4) {
                int _e149 = i_2;
                i_2 = (_e149 + 1);
            }
            loop_init_4 = false;
            int _e123 = i_2;
            if (!((_e123 < 10))) {
                break;
            }
            int _e127 = i_2;
            uint i_step = (uint(_e127) - uint(1));
            if ((i_step >= j_count)) {
                break;
            }
            if ((i_step >= 3u)) {
                break;
            }
            int j = (5 + int(i_step));
            float k_1 = KERNEL[int(i_step)];
            int _e143 = i_2;
            float _e147 = ramp;
            ramp = (_e147 + (float((_e143 * j)) * k_1));
        }
    }
    vec3 _e154 = c;
    float _e156 = blur;
    float _e160 = ramp;
    out_f_color = vec4((_e154 + vec3(_e156)), (_e160 / 50.0));
    vec4 _e165 = out_f_color;
    for_arrays_fs_out _tmp_return = for_arrays_fs_out(_e165);
    f_color = _tmp_return.f_color;
    return;
}

