#version 300 es

precision highp float;
precision highp int;

struct Frame {
    mat4x4 view;
    mat4x4 proj;
    vec4 near_far;
};
struct Surface {
    vec4 base_color;
    float roughness;
    float metalness;
    float normal_scale;
    float alpha_cutoff;
};
struct gbuffer_fs_out {
    vec4 g_albedo;
    vec4 g_normal;
    vec4 g_position;
};
layout(std140) uniform frame_block { Frame frame; };

layout(std140) uniform surface_block { Surface surface; };

uniform highp sampler2D albedo_map;

uniform highp sampler2D normal_map;

uniform highp sampler2D orm_map;

vec3 v_view_pos = vec3(0.0);

vec3 v_normal = vec3(0.0);

vec4 v_tangent = vec4(0.0);

vec2 v_uv = vec2(0.0);

vec4 g_albedo = vec4(0.0);

vec4 g_normal = vec4(0.0);

vec4 g_position = vec4(0.0);

smooth in vec3 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
smooth in vec4 _vs2fs_location2;
smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out vec4 _fs2p_location1;
layout(location = 2) out vec4 _fs2p_location2;

void main() {
    vec3 in_v_view_pos = _vs2fs_location0;
    vec3 in_v_normal = _vs2fs_location1;
    vec4 in_v_tangent = _vs2fs_location2;
    vec2 in_v_uv = _vs2fs_location3;
    vec3 tn = vec3(0.0);
    v_view_pos = in_v_view_pos;
    v_normal = in_v_normal;
    v_tangent = in_v_tangent;
    v_uv = in_v_uv;
    vec2 _e9 = v_uv;
    vec4 _e12 = texture(albedo_map, vec2(_e9));
    vec4 _e15 = surface.base_color;
    vec4 base = (_e12 * _e15);
    float _e20 = surface.alpha_cutoff;
    if ((base.w < _e20)) {
        discard;
    }
    vec3 _e23 = v_normal;
    vec3 n = normalize(_e23);
    vec4 _e26 = v_tangent;
    vec4 _e29 = v_tangent;
    vec3 t = normalize((_e26.xyz - (n * dot(n, _e29.xyz))));
    float _e38 = v_tangent.w;
    vec3 b = (cross(n, t) * _e38);
    vec2 _e42 = v_uv;
    vec4 _e45 = texture(normal_map, vec2(_e42));
    tn = ((_e45.xyz * 2.0) - vec3(1.0));
    vec3 _e53 = tn;
    float _e56 = surface.normal_scale;
    vec2 _e58 = (_e53.xy * _e56);
    tn = vec3(_e58.x, _e58.y, _e53.z);
    vec3 _e65 = tn;
    vec3 mapped = normalize((mat3x3(t, b, n) * _e65));
    vec2 _e69 = v_uv;
    vec4 orm = texture(orm_map, vec2(_e69));
    float _e75 = v_view_pos.z;
    float _e80 = frame.near_far.x;
    float _e85 = frame.near_far.y;
    float _e89 = frame.near_far.x;
    float linear_depth = ((-(_e75) - _e80) / (_e85 - _e89));
    float _e97 = surface.roughness;
    g_albedo = vec4(base.xyz, (orm.y * _e97));
    float _e109 = surface.metalness;
    g_normal = vec4(((mapped * 0.5) + vec3(0.5)), (orm.z * _e109));
    vec3 _e114 = v_view_pos;
    g_position = vec4(_e114, linear_depth);
    vec4 _e117 = g_albedo;
    vec4 _e119 = g_normal;
    vec4 _e121 = g_position;
    gbuffer_fs_out _tmp_return = gbuffer_fs_out(_e117, _e119, _e121);
    _fs2p_location0 = _tmp_return.g_albedo;
    _fs2p_location1 = _tmp_return.g_normal;
    _fs2p_location2 = _tmp_return.g_position;
    return;
}

