#version 330 core
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
layout(std140) uniform scene_ubo {
    mat3x3 normal_matrix;
    Light lights[4];
    Fog fog;
    int light_count;
    float exposure;
    vec2 tint;
} scene;

uniform vec4 u_kernel[8];

uniform Light u_lights[2];

in vec3 v_pos;
in vec3 v_normal;
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
            int _e21 = i;
            i = (_e21 + 1);
        }
        loop_init = false;
        int _e11 = i;
        if (!((_e11 < _e10))) {
            break;
        }
        int _e15 = i;
        Light _e17 = scene.lights[_e15];
        vec3 _e18 = light_at(_e17, in_v_pos, n_1);
        vec3 _e19 = c;
        c = (_e19 + _e18);
    }
    i_1 = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e36 = i_1;
            i_1 = (_e36 + 1);
        }
        loop_init_1 = false;
        int _e26 = i_1;
        if (!((_e26 < 2))) {
            break;
        }
        int _e30 = i_1;
        Light _e32 = u_lights[_e30];
        vec3 _e33 = light_at(_e32, in_v_pos, n_1);
        vec3 _e34 = c;
        c = (_e34 + _e33);
    }
    k = 0.0;
    i_2 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e56 = i_2;
            i_2 = (_e56 + 1);
        }
        loop_init_2 = false;
        int _e41 = i_2;
        if (!((_e41 < 8))) {
            break;
        }
        int _e45 = i_2;
        float _e48 = u_kernel[_e45].x;
        int _e49 = i_2;
        float _e52 = u_kernel[_e49].w;
        float _e54 = k;
        k = (_e54 + (_e48 + _e52));
    }
    float _e60 = scene.fog.density;
    float f = exp((-(_e60) * length(in_v_pos)));
    vec3 _e67 = scene.fog.color;
    vec3 _e68 = c;
    float _e70 = scene.exposure;
    c = mix(_e67, (_e68 * _e70), vec3(f));
    vec3 _e75 = c;
    vec2 _e77 = scene.tint;
    float _e81 = k;
    out_f_color = vec4(((_e75 * vec3(_e77, 1.0)) + vec3((_e81 * 0.001))), 1.0);
    vec4 _e87 = out_f_color;
    layout_fs_out _tmp_return = layout_fs_out(_e87);
    f_color = _tmp_return.f_color;
    return;
}

