#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct cascades_main_fs_out {
    vec4 f_FragColor;
};
const int CASCADES = 3;

uniform vec3 u_cam_pos;

uniform float u_is_floor;

vec3 io_v_world_pos = vec3(0.0);

vec3 io_v_world_normal = vec3(0.0);

uniform vec3 u_light_dir;

uniform mat4x4 u_cascade_vp[3];

uniform highp sampler2DShadow cascade_maps_0;

uniform highp sampler2DShadow cascade_maps_1;

uniform highp sampler2DShadow cascade_maps_2;

in vec3 v_world_pos;
in vec3 v_world_normal;
out vec4 f_FragColor;

vec3 to_map(vec4 clip) {
    return (((clip.xyz / vec3(max(clip.w, 0.0001))) * 0.5) + vec3(0.5));
}

int pick_cascade(vec4 p) {
    int i = 0;
    float margin = (2.0 / float(ivec2(uvec2(textureSize(cascade_maps_0, 0).xy)).x));
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e40 = i;
            i = (_e40 + 1);
        }
        loop_init = false;
        int _e13 = i;
        if (!((_e13 < (CASCADES - 1)))) {
            break;
        }
        int _e17 = i;
        mat4x4 _e19 = u_cascade_vp[_e17];
        vec3 _e21 = to_map((_e19 * p));
        if ((((((_e21.x > margin) && (_e21.y > margin)) && (_e21.x < (1.0 - margin))) && (_e21.y < (1.0 - margin))) && (_e21.z < 1.0))) {
            int _e39 = i;
            return _e39;
        }
    }
    return (CASCADES - 1);
}

float sun_ndotl() {
    vec3 _e1 = io_v_world_normal;
    vec3 _e4 = u_light_dir;
    return max(dot(normalize(_e1), normalize(_e4)), 0.0);
}

float slope_bias(float ndotl) {
    return max((0.0025 * (1.0 - ndotl)), 0.0008);
}

float surface_gloss() {
    float _e1 = u_is_floor;
    return ((_e1 > 0.5) ? 0.15 : 0.5);
}

vec3 checker(vec3 p_1) {
    float cell = (floor(((p_1.x * 0.5) + 100.0)) + floor(((p_1.z * 0.5) + 100.0)));
    float odd = (cell - (2.0 * floor((cell * 0.5))));
    return (vec3(((odd < 0.5) ? 0.85 : 0.3)) * vec3(0.8, 0.82, 0.88));
}

vec3 surface_albedo() {
    float _e1 = u_is_floor;
    if ((_e1 > 0.5)) {
        vec3 _e5 = io_v_world_pos;
        vec3 _e6 = checker(_e5);
        return _e6;
    }
    return vec3(0.85, 0.45, 0.3);
}

vec3 hemisphere(vec3 n) {
    return mix(vec3(0.1, 0.09, 0.08), vec3(0.3, 0.34, 0.42), vec3(((n.y * 0.5) + 0.5)));
}

vec3 sun_shade(float visibility) {
    vec3 _e2 = io_v_world_normal;
    vec3 n_1 = normalize(_e2);
    vec3 _e5 = u_light_dir;
    vec3 l = normalize(_e5);
    vec3 _e8 = u_cam_pos;
    vec3 _e10 = io_v_world_pos;
    vec3 v = normalize((_e8 - _e10));
    float ndotl_1 = max(dot(n_1, l), 0.0);
    float lit = ((ndotl_1 < 0.05) ? 0.0 : visibility);
    vec3 h = normalize((l + v));
    float _e26 = surface_gloss();
    float spec = ((pow(max(dot(n_1, h), 0.0), 48.0) * lit) * _e26);
    vec3 sun = vec3(1.3, 1.15, 0.9);
    vec3 _e32 = surface_albedo();
    vec3 _e33 = hemisphere(n_1);
    return ((_e32 * (_e33 + (sun * (ndotl_1 * lit)))) + vec3(spec));
}

void main() {
    vec3 in_v_world_pos = v_world_pos;
    vec3 in_v_world_normal = v_world_normal;
    vec4 out_f_FragColor = vec4(0.0);
    float texel = 0.0;
    io_v_world_pos = in_v_world_pos;
    io_v_world_normal = in_v_world_normal;
    vec3 _e4 = io_v_world_pos;
    vec4 p_2 = vec4(_e4, 1.0);
    int _e7 = pick_cascade(p_2);
    mat4x4 _e10 = u_cascade_vp[_e7];
    vec3 _e12 = to_map((_e10 * p_2));
    float _e13 = sun_ndotl();
    float _e14 = slope_bias(_e13);
    float bias = (_e14 * float((1 << uint(_e7))));
    vec2 _e20 = _e12.xy;
    float _e22 = (_e12.z - bias);
    switch(min(max(_e7, 0), 2)) {
        case 0: {
            float _e28 = texture(cascade_maps_0, vec3(_e20, _e22));
            texel = _e28;
            break;
        }
        case 1: {
            float _e32 = texture(cascade_maps_1, vec3(_e20, _e22));
            texel = _e32;
            break;
        }
        default: {
            float _e35 = texture(cascade_maps_2, vec3(_e20, _e22));
            texel = _e35;
            break;
        }
    }
    float visibility_1 = texel;
    vec3 _e38 = sun_shade(visibility_1);
    out_f_FragColor = vec4(_e38, 1.0);
    vec4 _e40 = out_f_FragColor;
    cascades_main_fs_out _tmp_return = cascades_main_fs_out(_e40);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

