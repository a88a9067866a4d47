#version 330 core
struct rgba8_main_fs_out {
    vec4 f_FragColor;
};
const float DEPTH_BIAS = 0.0015;

uniform mat4x4 u_light_vp;

uniform vec3 u_cam_pos;

uniform float u_is_floor;

vec3 io_v_world_pos = vec3(0.0);

vec3 io_v_world_normal = vec3(0.0);

uniform vec3 u_light_dir;

uniform sampler2D shadow_rgba;

in vec3 v_world_pos;
in vec3 v_world_normal;
out vec4 f_FragColor;

vec3 to_map(vec4 clip) {
    return (((clip.xyz / vec3(max(clip.w, 0.0001))) * 0.5) + vec3(0.5));
}

float decode_depth(vec4 rgba) {
    return dot(rgba, vec4(1.0, (1.0 / 255.0), (1.0 / 65025.0), (1.0 / 16581375.0)));
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
    vec4 out_f_FragColor = vec4(0.0);
    io_v_world_pos = in_v_world_pos;
    io_v_world_normal = in_v_world_normal;
    mat4x4 _e5 = u_light_vp;
    vec3 _e6 = io_v_world_pos;
    vec3 _e10 = to_map((_e5 * vec4(_e6, 1.0)));
    vec4 _e14 = texture(shadow_rgba, vec2(_e10.xy));
    float _e15 = decode_depth(_e14);
    float _e19 = sun_ndotl();
    float _e20 = slope_bias(_e19);
    float visibility_1 = ((((_e10.z - DEPTH_BIAS) - _e20) > _e15) ? 0.0 : 1.0);
    vec3 _e26 = sun_shade(visibility_1);
    out_f_FragColor = vec4(_e26, 1.0);
    vec4 _e28 = out_f_FragColor;
    rgba8_main_fs_out _tmp_return = rgba8_main_fs_out(_e28);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

