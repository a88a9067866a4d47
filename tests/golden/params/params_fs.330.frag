#version 330 core
struct Ray {
    vec3 origin;
    vec3 dir;
};
struct params_fs_out {
    vec4 f_color;
};
in vec2 v_uv;
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
        int _e7 = i;
        if (!((_e7 < n))) {
            break;
        }
        int _e10 = i;
        float _e12 = s;
        s = (_e12 + xs[_e10]);
        int _e15 = i;
        i = (_e15 + 1);
        int _e17 = j;
        j = (_e17 - 1);
    }
    float _e19 = s;
    int _e20 = j;
    return (_e19 + (float(_e20) * 0.0));
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
    float _e18 = total(xs_1, 3);
    vec3 _e19 = blend(_e14, vec3(1.0, 0.5, 0.0), _e18, in_v_uv);
    out_f_color = vec4(_e19, 1.0);
    vec4 _e22 = out_f_color;
    params_fs_out _tmp_return = params_fs_out(_e22);
    f_color = _tmp_return.f_color;
    return;
}

