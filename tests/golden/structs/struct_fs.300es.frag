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
layout(std140) uniform light_ubo { Light light; };

smooth in vec3 v_normal;
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
    Light _e13 = light;
    vec3 _e14 = shade(_e10, normalize(in_v_normal), _e13);
    float _e17 = m.roughness;
    out_f_color = vec4((_e14 + vec3((_e17 * 0.1))), 1.0);
    vec4 _e24 = out_f_color;
    struct_fs_out _tmp_return = struct_fs_out(_e24);
    f_color = _tmp_return.f_color;
    return;
}

