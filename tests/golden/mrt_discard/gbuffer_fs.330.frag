#version 330 core
struct gbuffer_fs_out {
    vec4 g_albedo;
    vec4 g_normal;
    vec4 g_depth;
};
in vec3 v_normal;
in vec2 v_uv;
in float v_depth;
layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_depth;

void main() {
    vec3 in_v_normal = v_normal;
    vec2 in_v_uv = v_uv;
    float in_v_depth = v_depth;
    bool FrontFacing = gl_FrontFacing;
    vec4 FragCoord = gl_FragCoord;
    vec4 out_g_albedo = vec4(0.0);
    vec4 out_g_normal = vec4(0.0);
    vec4 out_g_depth = vec4(0.0);
    vec3 n = vec3(0.0);
    if ((fract((in_v_uv.x * 8.0)) < 0.1)) {
        discard;
    }
    n = normalize(in_v_normal);
    if (!(FrontFacing)) {
        vec3 _e14 = n;
        n = -(_e14);
    }
    out_g_albedo = vec4(in_v_uv, 0.5, 1.0);
    vec3 _e21 = n;
    out_g_normal = vec4(((_e21 * 0.5) + vec3(0.5)), 1.0);
    float _e27 = fwidth(in_v_depth);
    out_g_depth = vec4(in_v_depth, _e27, FragCoord.z, 1.0);
    vec4 _e30 = out_g_albedo;
    vec4 _e31 = out_g_normal;
    vec4 _e32 = out_g_depth;
    gbuffer_fs_out _tmp_return = gbuffer_fs_out(_e30, _e31, _e32);
    g_albedo = _tmp_return.g_albedo;
    g_normal = _tmp_return.g_normal;
    g_depth = _tmp_return.g_depth;
    return;
}

