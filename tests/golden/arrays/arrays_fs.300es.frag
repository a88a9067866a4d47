#version 300 es

precision highp float;
precision highp int;

struct arrays_fs_out {
    vec4 f_color;
};
const float WEIGHTS[5] = float[5](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);
const vec3 COLORS[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));

uniform int u_count;

flat in int v_id;
out vec4 f_color;

float sum_first(int n) {
    float acc[5] = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
    int i = 0;
    float s = 0.0;
    int i_1 = 0;
    acc = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e19 = i;
            i = (_e19 + 1);
        }
        loop_init = false;
        int _e6 = i;
        if (!((_e6 < 5))) {
            break;
        }
        int _e9 = i;
        int _e12 = i;
        int _e14 = i;
        acc[_e9] = (WEIGHTS[_e12] * float((_e14 + 1)));
    }
    s = 0.0;
    i_1 = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e33 = i_1;
            i_1 = (_e33 + 1);
        }
        loop_init_1 = false;
        int _e25 = i_1;
        if (!((_e25 < min(n, 5)))) {
            break;
        }
        int _e28 = i_1;
        float _e30 = acc[_e28];
        float _e31 = s;
        s = (_e31 + _e30);
    }
    float _e35 = s;
    return _e35;
}

void main() {
    int in_v_id = v_id;
    vec4 out_f_color = vec4(0.0);
    mat3x3 local = mat3x3(0.0);
    ivec2 grid[2] = ivec2[2](ivec2(0), ivec2(0));
    mat2x2 m = mat2x2(0.0);
    mat3x3 basis = mat3x3(COLORS[0], COLORS[1], COLORS[2]);
    local = basis;
    vec3 col = local[(in_v_id - (3 * (in_v_id / 3)))];
    grid = ivec2[2](ivec2(0), ivec2(0));
    grid[(in_v_id & 1)] = ivec2(in_v_id, -(in_v_id));
    ivec2 g = grid[1];
    m = mat2x2(vec2(1.0, 0.0), vec2(0.0, 1.0));
    int _e29 = u_count;
    m[(_e29 & 1)] = vec2(0.5);
    int _e35 = u_count;
    float _e36 = sum_first(_e35);
    vec2 _e41 = m[1];
    out_f_color = vec4(((col * _e36) + vec3(float(g.x), _e41)), 1.0);
    vec4 _e45 = out_f_color;
    arrays_fs_out _tmp_return = arrays_fs_out(_e45);
    f_color = _tmp_return.f_color;
    return;
}

