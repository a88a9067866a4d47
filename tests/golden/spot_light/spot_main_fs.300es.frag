#version 300 es

precision highp float;
precision highp int;

struct spot_main_fs_out {
    vec4 f_FragColor;
};
const float SPOT_COS_OUTER = 0.848;
const float SPOT_COS_INNER = 0.9063;
const float DEPTH_BIAS = 0.0006;
const float SHADOW_FACTOR = 0.5;

uniform mat4x4 u_light_vp;

uniform vec3 u_cam_pos;

uniform float u_is_floor;

vec3 io_v_world_pos = vec3(0.0);

uniform vec3 u_light_pos;

uniform vec3 u_spot_dir;

uniform highp sampler2D shadow_map;

in vec3 v_world_pos;
in vec3 v_world_normal;
out vec4 f_FragColor;

float cone(vec3 to_light) {
    vec3 _e5 = u_spot_dir;
    return smoothstep(SPOT_COS_OUTER, SPOT_COS_INNER, dot(-(to_light), normalize(_e5)));
}

vec3 to_map(vec4 clip) {
    return (((clip.xyz / vec3(max(clip.w, 0.0001))) * 0.5) + vec3(0.5));
}

float spot_shadow(vec3 world) {
    mat4x4 _e2 = u_light_vp;
    vec3 _e6 = to_map((_e2 * vec4(world, 1.0)));
    vec4 _e10 = texture(shadow_map, vec2(_e6.xy));
    float stored = _e10.x;
    return (((_e6.z - DEPTH_BIAS) > stored) ? SHADOW_FACTOR : 1.0);
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

void main() {
    vec3 in_v_world_pos = v_world_pos;
    vec3 in_v_world_normal = v_world_normal;
    vec4 out_f_FragColor = vec4(0.0);
    io_v_world_pos = in_v_world_pos;
    vec3 n_1 = normalize(in_v_world_normal);
    vec3 _e5 = u_light_pos;
    vec3 _e6 = io_v_world_pos;
    vec3 l = normalize((_e5 - _e6));
    vec3 _e10 = u_cam_pos;
    vec3 _e11 = io_v_world_pos;
    vec3 v = normalize((_e10 - _e11));
    float ndotl = max(dot(n_1, l), 0.0);
    float _e17 = cone(l);
    vec3 _e18 = io_v_world_pos;
    float _e19 = spot_shadow(_e18);
    float light = (_e17 * _e19);
    vec3 h = normalize((l + v));
    float _e28 = surface_gloss();
    float spec = ((ndotl > 0.0) ? (pow(max(dot(n_1, h), 0.0), 48.0) * _e28) : 0.0);
    vec3 color = vec3(1.25, 1.15, 0.95);
    vec3 _e35 = surface_albedo();
    vec3 _e36 = hemisphere(n_1);
    vec3 rgb = ((_e35 * (_e36 + (color * (ndotl * light)))) + vec3((spec * light)));
    out_f_FragColor = vec4(rgb, 1.0);
    vec4 _e47 = out_f_FragColor;
    spot_main_fs_out _tmp_return = spot_main_fs_out(_e47);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

