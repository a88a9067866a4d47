#version 300 es

precision highp float;
precision highp int;

struct Light {
    vec3 position;
    float radius;
    vec4 color;
};
struct Fog {
    vec3 color;
    float density;
};
struct Scene {
    mat3x3 normal_matrix;
    Light lights[4];
    Fog fog;
    int light_count;
    float exposure;
    vec2 tint;
};
struct layout_fs_out {
    vec4 f_color;
};
layout(std140) uniform scene_ubo { Scene scene; };

uniform vec4 u_kernel[8];

uniform Light u_lights[2];

smooth in vec3 v_pos;
smooth in vec3 v_normal;
out vec4 f_color;

vec3 light_at(Light l, vec3 p, vec3 n) {
    vec3 d = (l.position - p);
    float att = clamp((1.0 - (length(d) / l.radius)), 0.0, 1.0);
    return ((l.color.xyz * max(dot(n, normalize(d)), 0.0)) * att);
}

void main() {
    vec3 in_v_pos = v_pos;
    vec3 in_v_normal = v_normal;
    vec4 out_f_color = vec4(0.0);
    vec3 c = vec3(0.0);
    int i = 0;
    int i_1 = 0;
    float k = 0.0;
    int i_2 = 0;
    vec3 n_1 = normalize(in_v_normal);
    c = vec3(0.0);
    i = 0;
    int _e10 = scene.light_count;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e24 = i;
            i = (_e24 + 1);
        }
        loop_init = false;
        int _e11 = i;
        if (!((_e11 < _e10))) {
            break;
        }
        int _e18 = i;
        Light _e20 = scene.lights[_e18];
        vec3 _e21 = light_at(_e20, in_v_pos, n_1);
        vec3 _e22 = c;
        c = (_e22 + _e21);
    }
    i_1 = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e42 = i_1;
            i_1 = (_e42 + 1);
        }
        loop_init_1 = false;
        int _e30 = i_1;
        if (!((_e30 < 2))) {
            break;
        }
        int _e36 = i_1;
        Light _e38 = u_lights[_e36];
        vec3 _e39 = light_at(_e38, in_v_pos, n_1);
        vec3 _e40 = c;
        c = (_e40 + _e39);
    }
    k = 0.0;
    i_2 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e69 = i_2;
            i_2 = (_e69 + 1);
        }
        loop_init_2 = false;
        int _e50 = i_2;
        if (!((_e50 < 8))) {
            break;
        }
        int _e56 = i_2;
        float _e59 = u_kernel[_e56].x;
        int _e62 = i_2;
        float _e65 = u_kernel[_e62].w;
        float _e67 = k;
        k = (_e67 + (_e59 + _e65));
    }
    float _e75 = scene.fog.density;
    float f = exp((-(_e75) * length(in_v_pos)));
    vec3 _e84 = scene.fog.color;
    vec3 _e86 = c;
    float _e89 = scene.exposure;
    c = mix(_e84, (_e86 * _e89), vec3(f));
    vec3 _e95 = c;
    vec2 _e98 = scene.tint;
    float _e103 = k;
    out_f_color = vec4(((_e95 * vec3(_e98, 1.0)) + vec3((_e103 * 0.001))), 1.0);
    vec4 _e111 = out_f_color;
    layout_fs_out _tmp_return = layout_fs_out(_e111);
    f_color = _tmp_return.f_color;
    return;
}

