#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct cull_main_fs_out {
    vec4 f_FragColor;
};
const int PCF_TAPS = 4;
const vec2 PCF_OFFSETS[4] = vec2[4](vec2(-0.5, -0.5), vec2(0.5, -0.5), vec2(-0.5, 0.5), vec2(0.5, 0.5));

uniform mat4x4 u_light_vp;

uniform vec3 u_cam_pos;

uniform float u_is_floor;

vec3 io_v_world_pos = vec3(0.0);

vec3 io_v_world_normal = vec3(0.0);

uniform vec3 u_light_dir;

uniform highp sampler2DShadow shadow_map;

in vec3 v_world_pos;
in vec3 v_world_normal;
out vec4 f_FragColor;

vec3 to_map(vec4 clip) {
    return (((clip.xyz / vec3(max(clip.w, 0.0001))) * 0.5) + vec3(0.5));
}

float pcf_visibility(vec3 coord, float bias) {
    float seen = 0.0;
    int i = 0;
    vec2 texel = (vec2(1.0) / vec2(ivec2(uvec2(textureSize(shadow_map, 0).xy))));
    seen = 0.0;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e29 = i;
            i = (_e29 + 1);
        }
        loop_init = false;
        int _e14 = i;
        if (!((_e14 < PCF_TAPS))) {
            break;
        }
        int _e19 = i;
        float _e26 = texture(shadow_map, vec3((coord.xy + (PCF_OFFSETS[_e19] * texel)), (coord.z - bias)));
        float _e27 = seen;
        seen = (_e27 + _e26);
    }
    float _e32 = seen;
    return (_e32 / float(PCF_TAPS));
}

float surface_gloss() {
    float _e1 = u_is_floor;
    return ((_e1 > 0.5) ? 0.15 : 0.5);
}

vec3 checker(vec3 p) {
    float cell = (floor(((p.x * 0.5) + 100.0)) + floor(((p.z * 0.5) + 100.0)));
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
    float ndotl = max(dot(n_1, l), 0.0);
    float lit = ((ndotl < 0.05) ? 0.0 : visibility);
    vec3 h = normalize((l + v));
    float _e26 = surface_gloss();
    float spec = ((pow(max(dot(n_1, h), 0.0), 48.0) * lit) * _e26);
    vec3 sun = vec3(1.3, 1.15, 0.9);
    vec3 _e32 = surface_albedo();
    vec3 _e33 = hemisphere(n_1);
    return ((_e32 * (_e33 + (sun * (ndotl * lit)))) + vec3(spec));
}

void main() {
    vec3 in_v_world_pos = v_world_pos;
    vec3 in_v_world_normal = v_world_normal;
    vec4 out_f_FragColor = vec4(0.0);
    io_v_world_pos = in_v_world_pos;
    io_v_world_normal = in_v_world_normal;
    mat4x4 _e5 = u_light_vp;
    vec3 _e6 = io_v_world_pos;
    vec3 _e10 = to_map((_e5 * vec4(_e6, 1.0)));
    float _e13 = pcf_visibility(_e10, 0.0);
    vec3 _e14 = sun_shade(_e13);
    out_f_FragColor = vec4(_e14, 1.0);
    vec4 _e16 = out_f_FragColor;
    cull_main_fs_out _tmp_return = cull_main_fs_out(_e16);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

