#version 330 core
struct math_fs_out {
    vec4 f_color;
};
const vec2 OFFSETS[4] = vec2[4](vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(0.0, -1.0), vec2(0.0, 1.0));
const float TAU = 6.2831855;

uniform float u_time;

smooth in vec2 v_uv;
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
    float _e10 = u_time;
    mat2x2 _e11 = rotate(_e10);
    vec2 _e13 = p;
    p = (_e11 * _e13);
    col = vec3(0.0);
    vec3 _e19 = col;
    vec2 _e21 = p;
    vec2 _e22 = abs(_e21);
    col = vec3(_e22.x, _e22.y, _e19.z);
    float _e30 = u_time;
    float _e37 = -(7.5);
    col.z = ((_e30 - (1.0 * floor((_e30 / 1.0)))) + ((_e37 - (2.0 * floor((_e37 / 2.0)))) * 0.0));
    sum = vec2(0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e62 = i;
            i = (_e62 + 1);
        }
        loop_init = false;
        int _e52 = i;
        if (!((_e52 < 4))) {
            break;
        }
        int _e58 = i;
        vec2 _e60 = sum;
        sum = (_e60 + OFFSETS[_e58]);
    }
    mat3x3 m = mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
    vec3 _e73 = col;
    vec2 _e76 = sum;
    col = ((m * _e73) + vec3(_e76, 0.0));
    int bits = ((in_v_id & 7) ^ (in_v_id >> uint(1)));
    float _e88 = p.y;
    float _e91 = p.x;
    float angle = ((atan(_e88, _e91) / TAU) + 0.5);
    float _e101 = col.x;
    col.x = clamp(mix(_e101, angle, 0.5), 0.0, 1.0);
    vec2 _e112 = p;
    col.y = (smoothstep(0.2, 0.8, length(_e112)) * step(0.5, float((bits - (3 * (bits / 3))))));
    vec3 _e125 = col;
    out_f_color = vec4(pow(_e125, vec3((1.0 / 2.2))), 1.0);
    vec4 _e134 = out_f_color;
    math_fs_out _tmp_return = math_fs_out(_e134);
    f_color = _tmp_return.f_color;
    return;
}

