#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct variants_fs_out {
    vec4 f_color;
};
uniform vec3 u_light_dir;

uniform vec3 u_eye;

uniform vec4 u_color;

uniform highp sampler2DShadow shadow_map;

vec4 io_v_light_pos = vec4(0.0);

in vec3 v_normal;
in vec3 v_world;
in vec4 v_light_pos;
out vec4 f_color;

float shadow_lookup(vec3 coord, float bias) {
    float _e7 = texture(shadow_map, vec3(coord.xy, (coord.z - bias)));
    return _e7;
}

float shadow_factor(float ndotl) {
    vec4 _e2 = io_v_light_pos;
    float _e5 = io_v_light_pos.w;
    vec3 coord_1 = (((_e2.xyz / vec3(_e5)) * 0.5) + vec3(0.5));
    if ((coord_1.z > 1.0)) {
        return 1.0;
    }
    float _e16 = shadow_lookup(coord_1, 0.002);
    return _e16;
}

void main() {
    vec3 in_v_normal = v_normal;
    vec3 in_v_world = v_world;
    vec4 in_v_light_pos = v_light_pos;
    vec4 out_f_color = vec4(0.0);
    vec3 color = vec3(0.0);
    io_v_light_pos = in_v_light_pos;
    vec3 n = normalize(in_v_normal);
    vec3 _e6 = u_light_dir;
    vec3 l = normalize(-(_e6));
    vec3 _e10 = u_eye;
    vec3 v = normalize((_e10 - in_v_world));
    float ndotl_1 = max(dot(n, l), 0.0);
    float _e16 = shadow_factor(ndotl_1);
    vec4 _e19 = u_color;
    color = (_e19.xyz * (0.15 + ((0.85 * ndotl_1) * _e16)));
    vec3 _e28 = color;
    float _e30 = u_color.w;
    out_f_color = vec4(_e28, _e30);
    vec4 _e32 = out_f_color;
    variants_fs_out _tmp_return = variants_fs_out(_e32);
    f_color = _tmp_return.f_color;
    return;
}

