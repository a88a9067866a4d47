#version 330 core
struct deferred_lighting_fs_out {
    vec4 f_color;
};
const float POSITION_RANGE = 8.0;

uniform vec3 u_light_pos;

uniform vec3 u_cam_pos;

uniform sampler2D gbuf_albedo;

uniform sampler2D gbuf_normal;

uniform sampler2D gbuf_position;

in vec2 v_uv;
layout(location = 0) out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 albedo = texture(gbuf_albedo, vec2(in_v_uv));
    vec4 _e6 = texture(gbuf_normal, vec2(in_v_uv));
    vec3 n = normalize(((_e6.xyz * 2.0) - vec3(1.0)));
    vec4 _e16 = texture(gbuf_position, vec2(in_v_uv));
    vec3 p = ((_e16.xyz - vec3(0.5)) * POSITION_RANGE);
    vec3 _e24 = u_light_pos;
    vec3 to_light = (_e24 - p);
    float d = max(length(to_light), 0.001);
    vec3 l = (to_light / vec3(d));
    float diffuse = ((max(dot(n, l), 0.0) * 20.0) / (1.0 + (d * d)));
    vec3 _e40 = u_cam_pos;
    vec3 h = normalize((l + normalize((_e40 - p))));
    float specular = (pow(max(dot(n, h), 0.0), 32.0) * 0.5);
    vec3 lit = ((albedo.xyz * (0.1 + diffuse)) + vec3(specular));
    out_f_color = vec4(mix(vec3(0.05, 0.06, 0.1), lit, vec3(albedo.w)), 1.0);
    vec4 _e64 = out_f_color;
    deferred_lighting_fs_out _tmp_return = deferred_lighting_fs_out(_e64);
    f_color = _tmp_return.f_color;
    return;
}

