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
layout(std140) uniform scene_block { Scene scene; };

layout(std140) uniform u_kernel_block { vec4 u_kernel[8]; };

layout(std140) uniform u_lights_block { Light u_lights[2]; };

vec3 v_pos = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec4 f_color = vec4(0.0);

smooth in vec3 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

vec3 light_at(Light l, vec3 p, vec3 n) {
    vec3 d = (l.position - p);
    float att = clamp((1.0 - (length(d) / l.radius)), 0.0, 1.0);
    return ((l.color.xyz * max(dot(n, normalize(d)), 0.0)) * att);
}

void main() {
    vec3 in_v_pos = _vs2fs_location0;
    vec3 in_v_normal = _vs2fs_location1;
    vec3 c = vec3(0.0);
    int i = 0;
    int i_1 = 0;
    float k = 0.0;
    int i_2 = 0;
    v_pos = in_v_pos;
    v_normal = in_v_normal;
    vec3 _e5 = v_normal;
    vec3 n_1 = normalize(_e5);
    c = vec3(0.0);
    i = 0;
    int _e14 = scene.light_count;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e30 = i;
            i = (_e30 + 1);
        }
        loop_init = false;
        int _e15 = i;
        if (!((_e15 < _e14))) {
            break;
        }
        int _e22 = i;
        Light _e24 = scene.lights[_e22];
        vec3 _e26 = v_pos;
        vec3 _e27 = light_at(_e24, _e26, n_1);
        vec3 _e28 = c;
        c = (_e28 + _e27);
    }
    i_1 = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e50 = i_1;
            i_1 = (_e50 + 1);
        }
        loop_init_1 = false;
        int _e36 = i_1;
        if (!((_e36 < 2))) {
            break;
        }
        int _e42 = i_1;
        Light _e44 = u_lights[_e42];
        vec3 _e46 = v_pos;
        vec3 _e47 = light_at(_e44, _e46, n_1);
        vec3 _e48 = c;
        c = (_e48 + _e47);
    }
    k = 0.0;
    i_2 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e77 = i_2;
            i_2 = (_e77 + 1);
        }
        loop_init_2 = false;
        int _e58 = i_2;
        if (!((_e58 < 8))) {
            break;
        }
        int _e64 = i_2;
        float _e67 = u_kernel[_e64].x;
        int _e70 = i_2;
        float _e73 = u_kernel[_e70].w;
        float _e75 = k;
        k = (_e75 + (_e67 + _e73));
    }
    float _e83 = scene.fog.density;
    vec3 _e86 = v_pos;
    float f = exp((-(_e83) * length(_e86)));
    vec3 _e94 = scene.fog.color;
    vec3 _e96 = c;
    float _e99 = scene.exposure;
    c = mix(_e94, (_e96 * _e99), vec3(f));
    vec3 _e105 = c;
    vec2 _e108 = scene.tint;
    float _e113 = k;
    f_color = vec4(((_e105 * vec3(_e108, 1.0)) + vec3((_e113 * 0.001))), 1.0);
    vec4 _e121 = f_color;
    layout_fs_out _tmp_return = layout_fs_out(_e121);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

