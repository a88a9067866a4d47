#version 330 core
struct main_fs_out {
    vec4 f_FragColor;
};
const float SHADOW_MAP_SIZE = 1024.0;
const int PCF_RADIUS = 1;

uniform vec3 u_light_dir;

uniform vec3 u_cam_pos;

uniform float u_is_floor;

uniform sampler2DShadow shadow_map;

in vec3 v_world_pos;
in vec3 v_world_normal;
in vec4 v_light_space;
out vec4 f_FragColor;

float sun_visibility(vec2 uv, float depth) {
    float lit_1 = 0.0;
    float taps = 0.0;
    int y = 0;
    int x = 0;
    float step_ = (1.0 / SHADOW_MAP_SIZE);
    lit_1 = 0.0;
    taps = 0.0;
    y = -(PCF_RADIUS);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e38 = y;
            y = (_e38 + 1);
        }
        loop_init = false;
        int _e13 = y;
        if (!((_e13 < (PCF_RADIUS + 1)))) {
            break;
        }
        x = -(PCF_RADIUS);
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                int _e36 = x;
                x = (_e36 + 1);
            }
            loop_init_1 = false;
            int _e19 = x;
            if (!((_e19 < (PCF_RADIUS + 1)))) {
                break;
            }
            int _e22 = x;
            int _e23 = y;
            float _e31 = texture(shadow_map, vec3((uv + (vec2(float(_e22), float(_e23)) * step_)), depth));
            float _e32 = lit_1;
            lit_1 = (_e32 + _e31);
            float _e34 = taps;
            taps = (_e34 + 1.0);
        }
    }
    float _e40 = lit_1;
    float _e41 = taps;
    return (_e40 / _e41);
}

vec3 floor_albedo(vec3 p) {
    float cell = (floor(((p.x * 0.5) + 100.0)) + floor(((p.z * 0.5) + 100.0)));
    float odd = (cell - (2.0 * floor((cell * 0.5))));
    float shade = ((odd < 0.5) ? 0.85 : 0.3);
    return (vec3(shade) * vec3(0.8, 0.82, 0.88));
}

void main() {
    vec3 in_v_world_pos = v_world_pos;
    vec3 in_v_world_normal = v_world_normal;
    vec4 in_v_light_space = v_light_space;
    vec4 out_f_FragColor = vec4(0.0);
    float lit = 0.0;
    vec3 albedo = vec3(0.0);
    float gloss = 0.0;
    vec3 n = normalize(in_v_world_normal);
    vec3 _e5 = u_light_dir;
    vec3 l = normalize(_e5);
    vec3 _e8 = u_cam_pos;
    vec3 v = normalize((_e8 - in_v_world_pos));
    float ndotl = max(dot(n, l), 0.0);
    float clip_w = max(in_v_light_space.w, 0.0001);
    vec3 ndc = (in_v_light_space.xyz / vec3(clip_w));
    vec2 uv_1 = ((ndc.xy * 0.5) + vec2(0.5));
    float depth_1 = ((ndc.z * 0.5) + 0.5);
    float bias = max((0.0025 * (1.0 - ndotl)), 0.0008);
    float _e36 = sun_visibility(uv_1, (depth_1 - bias));
    lit = _e36;
    if ((ndotl < 0.05)) {
        lit = 0.0;
    }
    float up = ((n.y * 0.5) + 0.5);
    vec3 ambient = mix(vec3(0.1, 0.09, 0.08), vec3(0.3, 0.34, 0.42), vec3(up));
    vec3 sun_color = vec3(1.3, 1.15, 0.9);
    albedo = vec3(0.85, 0.45, 0.3);
    gloss = 0.5;
    float _e62 = u_is_floor;
    if ((_e62 > 0.5)) {
        vec3 _e64 = floor_albedo(in_v_world_pos);
        albedo = _e64;
        gloss = 0.15;
    }
    vec3 h = normalize((l + v));
    float _e72 = lit;
    float _e74 = gloss;
    float spec = ((pow(max(dot(n, h), 0.0), 48.0) * _e72) * _e74);
    vec3 _e76 = albedo;
    float _e77 = lit;
    vec3 color = ((_e76 * (ambient + (sun_color * (ndotl * _e77)))) + vec3(spec));
    out_f_FragColor = vec4(color, 1.0);
    vec4 _e86 = out_f_FragColor;
    main_fs_out _tmp_return = main_fs_out(_e86);
    f_FragColor = _tmp_return.f_FragColor;
    return;
}

