#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct pcf_fs_out {
    vec4 f_color;
};
const int PCF_RADIUS = 2;

uniform vec3 u_light_dir;

uniform vec4 u_color;

uniform highp sampler2DShadow shadow_map;

in vec3 v_normal;
in vec4 v_light_pos;
out vec4 f_color;

float pcf_5x5_(vec3 coord, float bias) {
    float lit = 0.0;
    int y = 0;
    int x = 0;
    vec2 texel = (vec2(1.0) / vec2(ivec2(uvec2(textureSize(shadow_map, 0).xy))));
    lit = 0.0;
    y = -(PCF_RADIUS);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e42 = y;
            y = (_e42 + 1);
        }
        loop_init = false;
        int _e17 = y;
        if (!((_e17 < (PCF_RADIUS + 1)))) {
            break;
        }
        x = -(PCF_RADIUS);
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                int _e40 = x;
                x = (_e40 + 1);
            }
            loop_init_1 = false;
            int _e23 = x;
            if (!((_e23 < (PCF_RADIUS + 1)))) {
                break;
            }
            int _e26 = x;
            int _e28 = y;
            vec2 offset = (vec2(float(_e26), float(_e28)) * texel);
            float _e37 = texture(shadow_map, vec3((coord.xy + offset), (coord.z - bias)));
            float _e38 = lit;
            lit = (_e38 + _e37);
        }
    }
    int n = ((2 * PCF_RADIUS) + 1);
    float _e47 = lit;
    return (_e47 / float((n * n)));
}

void main() {
    vec3 in_v_normal = v_normal;
    vec4 in_v_light_pos = v_light_pos;
    vec4 out_f_color = vec4(0.0);
    float shadow = 0.0;
    vec3 n_1 = normalize(in_v_normal);
    vec3 _e4 = u_light_dir;
    vec3 l = normalize(-(_e4));
    float ndotl = max(dot(n_1, l), 0.0);
    vec3 coord_1 = (((in_v_light_pos.xyz / vec3(in_v_light_pos.w)) * 0.5) + vec3(0.5));
    shadow = 1.0;
    if ((coord_1.z <= 1.0)) {
        float bias_1 = max((0.005 * (1.0 - ndotl)), 0.0005);
        float edge = min(min(coord_1.x, coord_1.y), min((1.0 - coord_1.x), (1.0 - coord_1.y)));
        float _e36 = pcf_5x5_(coord_1, bias_1);
        shadow = mix(1.0, _e36, clamp((edge * 20.0), 0.0, 1.0));
    }
    vec4 _e43 = u_color;
    float _e48 = shadow;
    float _e53 = u_color.w;
    out_f_color = vec4((_e43.xyz * (0.15 + ((0.85 * ndotl) * _e48))), _e53);
    vec4 _e55 = out_f_color;
    pcf_fs_out _tmp_return = pcf_fs_out(_e55);
    f_color = _tmp_return.f_color;
    return;
}

