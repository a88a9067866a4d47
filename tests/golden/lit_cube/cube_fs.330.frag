#version 330 core
struct Camera {
    mat4x4 view_proj;
    vec3 position;
    float time;
};
struct Material {
    vec3 specular;
    float shininess;
    vec4 tint;
};
struct Lighting {
    vec3 sun_dir;
    float ambient;
    vec4 sun_color;
    vec3 point_pos;
    float point_range;
    vec4 point_color;
};
struct cube_fs_out {
    vec4 f_color;
};
layout(std140) uniform camera_ubo {
    mat4x4 view_proj;
    vec3 position;
    float time;
} camera;

layout(std140) uniform material_ubo {
    vec3 specular;
    float shininess;
    vec4 tint;
} material;

layout(std140) uniform lighting_ubo {
    vec3 sun_dir;
    float ambient;
    vec4 sun_color;
    vec3 point_pos;
    float point_range;
    vec4 point_color;
} lighting;

uniform sampler2D diffuse_map;

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
out vec4 f_color;

vec3 blinn(vec3 n, vec3 l, vec3 v, vec3 color) {
    vec3 h = normalize((l + v));
    float diffuse = max(dot(n, l), 0.0);
    float _e14 = material.shininess;
    float spec = ((diffuse > 0.0) ? pow(max(dot(n, h), 0.0), _e14) : 0.0);
    vec3 _e19 = material.specular;
    return ((color * diffuse) + ((_e19 * color) * spec));
}

void main() {
    vec3 in_v_world = v_world;
    vec3 in_v_normal = v_normal;
    vec2 in_v_uv = v_uv;
    bool FrontFacing = gl_FrontFacing;
    vec4 out_f_color = vec4(0.0);
    vec3 c = vec3(0.0);
    vec4 _e6 = texture(diffuse_map, vec2(in_v_uv));
    vec4 _e9 = material.tint;
    vec4 albedo = (_e6 * _e9);
    vec3 n_1 = normalize((FrontFacing ? in_v_normal : -(in_v_normal)));
    vec3 _e16 = camera.position;
    vec3 v_1 = normalize((_e16 - in_v_world));
    float _e23 = lighting.ambient;
    c = (albedo.xyz * _e23);
    vec3 _e27 = lighting.sun_dir;
    vec4 _e31 = lighting.sun_color;
    vec3 _e33 = blinn(n_1, normalize(-(_e27)), v_1, _e31.xyz);
    vec3 _e35 = c;
    c = (_e35 + (albedo.xyz * _e33));
    vec3 _e38 = lighting.point_pos;
    vec3 to_point = (_e38 - in_v_world);
    float dist = length(to_point);
    float _e43 = lighting.point_range;
    float falloff = clamp((1.0 - (dist / _e43)), 0.0, 1.0);
    vec4 _e51 = lighting.point_color;
    vec3 _e53 = blinn(n_1, (to_point / vec3(dist)), v_1, _e51.xyz);
    vec3 _e57 = c;
    c = (_e57 + ((albedo.xyz * _e53) * (falloff * falloff)));
    vec3 _e60 = c;
    out_f_color = vec4(_e60, albedo.w);
    vec4 _e63 = out_f_color;
    cube_fs_out _tmp_return = cube_fs_out(_e63);
    f_color = _tmp_return.f_color;
    return;
}

