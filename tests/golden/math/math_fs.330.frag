#version 330 core
struct math_fs_out {
    vec4 f_color;
};
const vec2 OFFSETS[4] = vec2[4](vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(0.0, -1.0), vec2(0.0, 1.0));
const float TAU = 6.2831855;

layout(std140) uniform u_time_block { float u_time; };

vec2 v_uv = vec2(0.0);

int v_id = 0;

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
flat in int _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

mat2x2 rotate(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat2x2(vec2(c, s), vec2(-(s), c));
}

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    int in_v_id = _vs2fs_location1;
    vec2 p = vec2(0.0);
    vec3 col = vec3(0.0);
    vec2 sum = vec2(0.0);
    int i = 0;
    v_uv = in_v_uv;
    v_id = in_v_id;
    vec2 _e6 = v_uv;
    p = ((_e6 * 2.0) - vec2(1.0));
    float _e14 = u_time;
    mat2x2 _e15 = rotate(_e14);
    vec2 _e17 = p;
    p = (_e15 * _e17);
    col = vec3(0.0);
    vec3 _e23 = col;
    vec2 _e25 = p;
    vec2 _e26 = abs(_e25);
    col = vec3(_e26.x, _e26.y, _e23.z);
    float _e34 = u_time;
    float _e41 = -(7.5);
    col.z = ((_e34 - (1.0 * floor((_e34 / 1.0)))) + ((_e41 - (2.0 * floor((_e41 / 2.0)))) * 0.0));
    sum = vec2(0.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e66 = i;
            i = (_e66 + 1);
        }
        loop_init = false;
        int _e56 = i;
        if (!((_e56 < 4))) {
            break;
        }
        int _e62 = i;
        vec2 _e64 = sum;
        sum = (_e64 + OFFSETS[_e62]);
    }
    mat3x3 m = mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
    vec3 _e77 = col;
    vec2 _e80 = sum;
    col = ((m * _e77) + vec3(_e80, 0.0));
    int _e85 = v_id;
    int _e89 = v_id;
    int bits = ((_e85 & 7) ^ (_e89 >> uint(1)));
    float _e96 = p.y;
    float _e99 = p.x;
    float angle = ((atan(_e96, _e99) / TAU) + 0.5);
    float _e109 = col.x;
    col.x = clamp(mix(_e109, angle, 0.5), 0.0, 1.0);
    vec2 _e120 = p;
    col.y = (smoothstep(0.2, 0.8, length(_e120)) * step(0.5, float((bits - (3 * (bits / 3))))));
    vec3 _e133 = col;
    f_color = vec4(pow(_e133, vec3((1.0 / 2.2))), 1.0);
    vec4 _e142 = f_color;
    math_fs_out _tmp_return = math_fs_out(_e142);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

