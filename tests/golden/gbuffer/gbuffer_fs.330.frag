#version 330 core
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
layout(std140) uniform frame_ubo {
    mat4x4 view;
    mat4x4 proj;
    vec4 near_far;
} frame;

layout(std140) uniform surface_ubo {
    vec4 base_color;
    float roughness;
    float metalness;
    float normal_scale;
    float alpha_cutoff;
} surface;

uniform sampler2D albedo_map;

uniform sampler2D normal_map;

uniform sampler2D orm_map;

in vec3 v_view_pos;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;
layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_position;

void main() {
    vec3 in_v_view_pos = v_view_pos;
    vec3 in_v_normal = v_normal;
    vec4 in_v_tangent = v_tangent;
    vec2 in_v_uv = v_uv;
    vec4 out_g_albedo = vec4(0.0);
    vec4 out_g_normal = vec4(0.0);
    vec4 out_g_position = vec4(0.0);
    vec3 tn = vec3(0.0);
    vec4 _e6 = texture(albedo_map, vec2(in_v_uv));
    vec4 _e9 = surface.base_color;
    vec4 base = (_e6 * _e9);
    float _e13 = surface.alpha_cutoff;
    if ((base.w < _e13)) {
        discard;
    }
    vec3 n = normalize(in_v_normal);
    vec3 t = normalize((in_v_tangent.xyz - (n * dot(n, in_v_tangent.xyz))));
    vec3 b = (cross(n, t) * in_v_tangent.w);
    vec4 _e28 = texture(normal_map, vec2(in_v_uv));
    tn = ((_e28.xyz * 2.0) - vec3(1.0));
    vec3 _e35 = tn;
    float _e37 = surface.normal_scale;
    vec2 _e39 = (_e35.xy * _e37);
    tn = vec3(_e39.x, _e39.y, _e35.z);
    vec3 _e45 = tn;
    vec3 mapped = normalize((mat3x3(t, b, n) * _e45));
    vec4 orm = texture(orm_map, vec2(in_v_uv));
    float _e56 = frame.near_far.x;
    float _e60 = frame.near_far.y;
    float _e63 = frame.near_far.x;
    float linear_depth = ((-(in_v_view_pos.z) - _e56) / (_e60 - _e63));
    float _e70 = surface.roughness;
    out_g_albedo = vec4(base.xyz, (orm.y * _e70));
    float _e80 = surface.metalness;
    out_g_normal = vec4(((mapped * 0.5) + vec3(0.5)), (orm.z * _e80));
    out_g_position = vec4(in_v_view_pos, linear_depth);
    vec4 _e85 = out_g_albedo;
    vec4 _e86 = out_g_normal;
    vec4 _e87 = out_g_position;
    gbuffer_fs_out _tmp_return = gbuffer_fs_out(_e85, _e86, _e87);
    g_albedo = _tmp_return.g_albedo;
    g_normal = _tmp_return.g_normal;
    g_position = _tmp_return.g_position;
    return;
}

