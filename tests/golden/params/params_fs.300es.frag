#version 300 es

precision highp float;
precision highp int;

struct Ray {
    vec3 origin;
    vec3 dir;
};
struct params_fs_out {
    vec4 f_color;
};
smooth in vec2 v_uv;
out vec4 f_color;

vec3 along(Ray r, float t) {
    return (r.origin + (r.dir * t));
}

float total(float xs[4], int n) {
    float s = 0.0;
    int i = 0;
    int j = 0;
    s = 0.0;
    i = 0;
    j = 0;
    while(true) {
        int _e9 = i;
        if (!((_e9 < n))) {
            break;
        }
        int _e14 = i;
        float _e16 = s;
        s = (_e16 + xs[_e14]);
        int _e20 = i;
        i = (_e20 + 1);
        int _e24 = j;
        j = (_e24 - 1);
    }
    float _e27 = s;
    int _e29 = j;
    return (_e27 + (float(_e29) * 0.0));
}

vec3 blend(vec3 a, vec3 b, float t_1, vec2 uv) {
    return (mix(a, b, vec3(t_1)) * vec3(uv, 1.0));
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    Ray r_1 = Ray(vec3(0.0), normalize(vec3(in_v_uv, -(1.0))));
    float xs_1[4] = float[4](0.1, 0.2, 0.3, 0.4);
    vec3 _e14 = along(r_1, 2.0);
    float _e20 = total(xs_1, 3);
    vec3 _e21 = blend(_e14, vec3(1.0, 0.5, 0.0), _e20, in_v_uv);
    out_f_color = vec4(_e21, 1.0);
    vec4 _e26 = out_f_color;
    params_fs_out _tmp_return = params_fs_out(_e26);
    f_color = _tmp_return.f_color;
    return;
}

