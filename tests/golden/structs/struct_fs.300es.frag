#version 300 es

precision highp float;
precision highp int;

struct Light {
    vec3 dir;
    float intensity;
    vec4 color;
};
struct Material {
    vec3 albedo;
    float roughness;
};
struct struct_fs_out {
    vec4 f_color;
};
layout(std140) uniform light_ubo {
    vec3 dir;
    float intensity;
    vec4 color;
} light;

in vec3 v_normal;
out vec4 f_color;

vec3 shade(Material m_1, vec3 n, Light l) {
    float ndotl = clamp(dot(n, -(l.dir)), 0.0, 1.0);
    return ((m_1.albedo * l.color.xyz) * (ndotl * l.intensity));
}

void main() {
    vec3 in_v_normal = v_normal;
    vec4 out_f_color = vec4(0.0);
    Material m = Material(vec3(0.0), 0.0);
    m = Material(vec3(0.0), 0.0);
    m.albedo = vec3(0.8, 0.6, 0.4);
    m.roughness = 0.5;
    Material _e10 = m;
    vec3 _e14 = light.dir;
    float _e16 = light.intensity;
    vec4 _e18 = light.color;
    vec3 _e20 = shade(_e10, normalize(in_v_normal), Light(_e14, _e16, _e18));
    float _e23 = m.roughness;
    out_f_color = vec4((_e20 + vec3((_e23 * 0.1))), 1.0);
    vec4 _e30 = out_f_color;
    struct_fs_out _tmp_return = struct_fs_out(_e30);
    f_color = _tmp_return.f_color;
    return;
}

