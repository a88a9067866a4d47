#version 330 core
struct Ray {
    vec3 origin;
    vec3 dir;
};
struct Material {
    vec3 albedo;
    float roughness;
    float metallic;
    vec3 emissive;
};
struct struct_init_fs_out {
    vec4 f_color;
};
uniform vec3 u_light_dir;

in vec2 v_uv;
out vec4 f_color;

Ray Ray_1(vec3 from, vec3 to) {
    return Ray(from, normalize((to - from)));
}

vec3 shade(Material m, vec3 n, vec3 l) {
    vec3 c_1 = vec3(0.0);
    c_1 = vec3(0.0);
    {
        vec3 diffuse = ((m.albedo * (1.0 - m.metallic)) * max(dot(n, l), 0.0));
        c_1 = ((diffuse * (1.0 - (m.roughness * 0.5))) + m.emissive);
    }
    vec3 _e21 = c_1;
    return _e21;
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    Material glow = Material(vec3(0.0), 0.0, 0.0, vec3(0.0));
    vec3 c = vec3(0.0);
    Material base = Material(vec3(0.8), 0.5, 0.0, vec3(0.0));
    Material metal = Material(vec3(0.8), 0.2, 1.0, vec3(0.0));
    glow = Material(vec3(0.8), 0.5, 0.0, vec3(0.1, 0.05, 0.0));
    {
        vec3 _e19 = glow.albedo;
        glow.albedo = (_e19 * 0.5);
    }
    Ray _e23 = Ray_1(vec3(in_v_uv, 1.0), vec3(0.5, 0.5, 0.0));
    vec3 n_1 = -(_e23.dir);
    int m_1 = ((in_v_uv.x < 0.33) ? 0 : ((in_v_uv.x < 0.66) ? 1 : 2));
    Material _e38 = glow;
    vec3 _e40 = u_light_dir;
    vec3 _e41 = shade(_e38, n_1, _e40);
    c = _e41;
    if ((m_1 == 0)) {
        vec3 _e43 = u_light_dir;
        vec3 _e44 = shade(base, n_1, _e43);
        c = _e44;
    } else {
        if ((m_1 == 1)) {
            vec3 _e46 = u_light_dir;
            vec3 _e47 = shade(metal, n_1, _e46);
            c = _e47;
        }
    }
    vec3 _e49 = c;
    out_f_color = vec4(_e49, 1.0);
    vec4 _e51 = out_f_color;
    struct_init_fs_out _tmp_return = struct_init_fs_out(_e51);
    f_color = _tmp_return.f_color;
    return;
}

