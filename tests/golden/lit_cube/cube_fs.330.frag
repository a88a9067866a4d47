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
layout(std140) uniform camera_block { Camera camera; };

layout(std140) uniform material_block { Material material; };

layout(std140) uniform lighting_block { Lighting lighting; };

uniform sampler2D diffuse_map;

vec3 v_world = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

bool gen_gl_FrontFacing = false;

smooth in vec3 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
smooth in vec2 _vs2fs_location2;
layout(location = 0) out vec4 _fs2p_location0;

vec3 blinn(vec3 n, vec3 l, vec3 v, vec3 color) {
    vec3 h = normalize((l + v));
    float diffuse = max(dot(n, l), 0.0);
    float _e16 = material.shininess;
    float spec = ((diffuse > 0.0) ? pow(max(dot(n, h), 0.0), _e16) : 0.0);
    vec3 _e23 = material.specular;
    return ((color * diffuse) + ((_e23 * color) * spec));
}

void main() {
    vec3 in_v_world = _vs2fs_location0;
    vec3 in_v_normal = _vs2fs_location1;
    vec2 in_v_uv = _vs2fs_location2;
    bool in_FrontFacing = gl_FrontFacing;
    vec3 c = vec3(0.0);
    v_world = in_v_world;
    v_normal = in_v_normal;
    v_uv = in_v_uv;
    gen_gl_FrontFacing = in_FrontFacing;
    vec2 _e9 = v_uv;
    vec4 _e12 = texture(diffuse_map, vec2(_e9));
    vec4 _e15 = material.tint;
    vec4 albedo = (_e12 * _e15);
    bool _e18 = gen_gl_FrontFacing;
    vec3 _e20 = v_normal;
    vec3 _e22 = v_normal;
    vec3 n_1 = normalize((_e18 ? _e20 : -(_e22)));
    vec3 _e28 = camera.position;
    vec3 _e30 = v_world;
    vec3 v_1 = normalize((_e28 - _e30));
    float _e37 = lighting.ambient;
    c = (albedo.xyz * _e37);
    vec3 _e43 = lighting.sun_dir;
    vec4 _e48 = lighting.sun_color;
    vec3 _e50 = blinn(n_1, normalize(-(_e43)), v_1, _e48.xyz);
    vec3 _e52 = c;
    c = (_e52 + (albedo.xyz * _e50));
    vec3 _e56 = lighting.point_pos;
    vec3 _e58 = v_world;
    vec3 to_point = (_e56 - _e58);
    float dist = length(to_point);
    float _e64 = lighting.point_range;
    float falloff = clamp((1.0 - (dist / _e64)), 0.0, 1.0);
    vec4 _e74 = lighting.point_color;
    vec3 _e76 = blinn(n_1, (to_point / vec3(dist)), v_1, _e74.xyz);
    vec3 _e80 = c;
    c = (_e80 + ((albedo.xyz * _e76) * (falloff * falloff)));
    vec3 _e84 = c;
    f_color = vec4(_e84, albedo.w);
    vec4 _e88 = f_color;
    cube_fs_out _tmp_return = cube_fs_out(_e88);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

