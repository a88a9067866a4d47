#version 330 core
struct gbuffer_fs_out {
    vec4 g_albedo;
    vec4 g_normal;
    vec4 g_depth;
};
vec3 v_normal = vec3(0.0);

vec2 v_uv = vec2(0.0);

float v_depth = 0.0;

vec4 g_albedo = vec4(0.0);

vec4 g_normal = vec4(0.0);

vec4 g_depth = vec4(0.0);

bool gen_gl_FrontFacing = false;

vec4 gen_gl_FragCoord = vec4(0.0);

smooth in vec3 _vs2fs_location0;
smooth in vec2 _vs2fs_location1;
smooth in float _vs2fs_location2;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out vec4 _fs2p_location1;
layout(location = 2) out vec4 _fs2p_location2;

void main() {
    vec3 in_v_normal = _vs2fs_location0;
    vec2 in_v_uv = _vs2fs_location1;
    float in_v_depth = _vs2fs_location2;
    bool in_FrontFacing = gl_FrontFacing;
    vec4 in_FragCoord = gl_FragCoord;
    vec3 n = vec3(0.0);
    v_normal = in_v_normal;
    v_uv = in_v_uv;
    v_depth = in_v_depth;
    gen_gl_FrontFacing = in_FrontFacing;
    gen_gl_FragCoord = in_FragCoord;
    float _e12 = v_uv.x;
    if ((fract((_e12 * 8.0)) < 0.1)) {
        discard;
    }
    vec3 _e20 = v_normal;
    n = normalize(_e20);
    bool _e23 = gen_gl_FrontFacing;
    if (!(_e23)) {
        vec3 _e27 = n;
        n = -(_e27);
    }
    vec2 _e31 = v_uv;
    g_albedo = vec4(_e31, 0.5, 1.0);
    vec3 _e37 = n;
    g_normal = vec4(((_e37 * 0.5) + vec3(0.5)), 1.0);
    float _e47 = v_depth;
    float _e49 = v_depth;
    float _e50 = fwidth(_e49);
    float _e53 = gen_gl_FragCoord.z;
    g_depth = vec4(_e47, _e50, _e53, 1.0);
    vec4 _e57 = g_albedo;
    vec4 _e59 = g_normal;
    vec4 _e61 = g_depth;
    gbuffer_fs_out _tmp_return = gbuffer_fs_out(_e57, _e59, _e61);
    _fs2p_location0 = _tmp_return.g_albedo;
    _fs2p_location1 = _tmp_return.g_normal;
    _fs2p_location2 = _tmp_return.g_depth;
    return;
}

