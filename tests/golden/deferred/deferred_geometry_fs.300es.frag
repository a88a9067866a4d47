#version 300 es

precision highp float;
precision highp int;

struct deferred_geometry_fs_out {
    vec4 g_albedo;
    vec4 g_normal;
    vec4 g_position;
};
const float POSITION_RANGE = 8.0;

uniform vec3 u_albedo;

in vec3 v_world;
in vec3 v_normal;
layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_position;

void main() {
    vec3 in_v_world = v_world;
    vec3 in_v_normal = v_normal;
    vec4 out_g_albedo = vec4(0.0);
    vec4 out_g_normal = vec4(0.0);
    vec4 out_g_position = vec4(0.0);
    vec3 _e4 = u_albedo;
    out_g_albedo = vec4(_e4, 1.0);
    out_g_normal = vec4(((normalize(in_v_normal) * 0.5) + vec3(0.5)), 1.0);
    out_g_position = vec4(((in_v_world / vec3(POSITION_RANGE)) + vec3(0.5)), 1.0);
    vec4 _e21 = out_g_albedo;
    vec4 _e22 = out_g_normal;
    vec4 _e23 = out_g_position;
    deferred_geometry_fs_out _tmp_return = deferred_geometry_fs_out(_e21, _e22, _e23);
    g_albedo = _tmp_return.g_albedo;
    g_normal = _tmp_return.g_normal;
    g_position = _tmp_return.g_position;
    return;
}

