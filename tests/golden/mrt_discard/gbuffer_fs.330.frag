#version 330 core
struct gbuffer_fs_out {
    vec4 g_albedo;
    vec4 g_normal;
    vec4 g_depth;
};
smooth in vec3 _vs2fs_location0;
smooth in vec2 _vs2fs_location1;
smooth in float _vs2fs_location2;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out vec4 _fs2p_location1;
layout(location = 2) out vec4 _fs2p_location2;

void main() {
    vec3 v_normal = _vs2fs_location0;
    vec2 v_uv = _vs2fs_location1;
    float v_depth = _vs2fs_location2;
    bool FrontFacing = gl_FrontFacing;
    vec4 FragCoord = gl_FragCoord;
    vec4 g_albedo = vec4(0.0);
    vec4 g_normal = vec4(0.0);
    vec4 g_depth = vec4(0.0);
    vec3 n = vec3(0.0);
    if ((fract((v_uv.x * 8.0)) < 0.1)) {
        discard;
    }
    n = normalize(v_normal);
    if (!(FrontFacing)) {
        vec3 _e16 = n;
        n = -(_e16);
    }
    g_albedo = vec4(v_uv, 0.5, 1.0);
    vec3 _e24 = n;
    g_normal = vec4(((_e24 * 0.5) + vec3(0.5)), 1.0);
    float _e33 = fwidth(v_depth);
    g_depth = vec4(v_depth, _e33, FragCoord.z, 1.0);
    vec4 _e38 = g_albedo;
    vec4 _e40 = g_normal;
    vec4 _e42 = g_depth;
    gbuffer_fs_out _tmp_return = gbuffer_fs_out(_e38, _e40, _e42);
    _fs2p_location0 = _tmp_return.g_albedo;
    _fs2p_location1 = _tmp_return.g_normal;
    _fs2p_location2 = _tmp_return.g_depth;
    return;
}

