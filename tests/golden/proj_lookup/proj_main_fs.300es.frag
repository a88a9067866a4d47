#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct proj_main_fs_out {
    vec4 f_FragColor;
};
uniform vec3 u_cam_pos;

uniform float u_is_floor;

vec3 io_v_world_pos = vec3(0.0);

vec3 io_v_world_normal = vec3(0.0);

uniform vec3 u_light_dir;

uniform highp sampler2DShadow shadow_map;

in vec3 v_world_pos;
in vec3 v_world_normal;
in vec4 v_shadow_coord;
out vec4 f_FragColor;

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
    vec4 in_v_shadow_coord = v_shadow_coord;
    vec4 out_f_FragColor = vec4(0.0);
    io_v_world_pos = in_v_world_pos;
    io_v_world_normal = in_v_world_normal;
    float _e7 = sun_ndotl();
    float _e8 = slope_bias(_e7);
    vec4 biased = vec4(in_v_shadow_coord.xy, (in_v_shadow_coord.z - (_e8 * in_v_shadow_coord.w)), in_v_shadow_coord.w);
    float _e23 = texture(shadow_map, vec3((biased.xy / vec2(biased.w)), (biased.z / biased.w)));
    vec3 _e24 = sun_shade(_e23);
    out_f_FragColor = vec4(_e24, 1.0);
    vec4 _e27 = out_f_FragColor;
    proj_main_fs_out _tmp_return = proj_main_fs_out(_e27);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

