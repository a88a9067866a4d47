#version 300 es

precision highp float;
precision highp int;

struct math_fs_out {
    vec4 f_color;
};
const vec2 OFFSETS[4] = vec2[4](vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(0.0, -1.0), vec2(0.0, 1.0));
const float TAU = 6.2831855;

uniform float u_time;

in vec2 v_uv;
flat in int v_id;
out vec4 f_color;

mat2x2 rotate(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat2x2(vec2(c, s), vec2(-(s), c));
}

void main() {
    vec2 in_v_uv = v_uv;
    int in_v_id = v_id;
    vec4 out_f_color = vec4(0.0);
    vec2 p = vec2(0.0);
    vec3 col = vec3(0.0);
    vec2 sum = vec2(0.0);
    int i = 0;
    p = ((in_v_uv * 2.0) - vec2(1.0));
    float _e9 = u_time;
    mat2x2 _e10 = rotate(_e9);
    vec2 _e11 = p;
    p = (_e10 * _e11);
    col = vec3(0.0);
    vec3 _e16 = col;
    vec2 _e17 = p;
    vec2 _e18 = abs(_e17);
    col = vec3(_e18.x, _e18.y, _e16.z);
    float _e24 = u_time;
    float _e30 = -(7.5);
    col.z = ((_e24 - (1.0 * floor((_e24 / 1.0)))) + ((_e30 - (2.0 * floor((_e30 / 2.0)))) * 0.0));
    sum = vec2(0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e50 = i;
            i = (_e50 + 1);
        }
        loop_init = false;
        int _e42 = i;
        if (!((_e42 < 4))) {
            break;
        }
        int _e46 = i;
        vec2 _e48 = sum;
        sum = (_e48 + OFFSETS[_e46]);
    }
    mat3x3 m = mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
    vec3 _e57 = col;
    vec2 _e59 = sum;
    col = ((m * _e57) + vec3(_e59, 0.0));
    int bits = ((in_v_id & 7) ^ (in_v_id >> uint(1)));
    float _e68 = p.y;
    float _e70 = p.x;
    float angle = ((atan(_e68, _e70) / TAU) + 0.5);
    float _e78 = col.x;
    col.x = clamp(mix(_e78, angle, 0.5), 0.0, 1.0);
    vec2 _e84 = p;
    col.y = (smoothstep(0.2, 0.8, length(_e84)) * step(0.5, float((bits - (3 * (bits / 3))))));
    vec3 _e95 = col;
    out_f_color = vec4(pow(_e95, vec3((1.0 / 2.2))), 1.0);
    vec4 _e101 = out_f_color;
    math_fs_out _tmp_return = math_fs_out(_e101);
    f_color = _tmp_return.f_color;
    return;
}

