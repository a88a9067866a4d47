#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct nonuniform_fs_out {
    vec4 f_color;
};
uniform highp sampler2D albedo;

uniform highp sampler2D mask;

uniform highp sampler2DShadow depth;

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

float march(vec2 uv) {
    float t = 0.0;
    vec2 p = vec2(0.0);
    t = 0.0;
    p = uv;
    while(true) {
        float _e5 = t;
        if (!((_e5 < 1.0))) {
            break;
        }
        vec2 _e10 = p;
        vec4 _e13 = texture(mask, vec2(_e10));
        float m = _e13.x;
        if ((m > 0.9)) {
            break;
        }
        float _e20 = t;
        t = (_e20 + (0.1 + m));
        vec2 _e25 = p;
        p = (_e25 + vec2(0.01));
    }
    float _e28 = t;
    return _e28;
}

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    vec4 c = vec4(0.0);
    int i = 0;
    v_uv = in_v_uv;
    float _e4 = v_uv.x;
    if ((_e4 < 0.1)) {
        f_color = vec4(0.0);
        vec4 _e11 = f_color;
        nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e11);
        _fs2p_location0 = _tmp_return.f_color;
        return;
    }
    vec2 _e14 = v_uv;
    vec4 m_1 = texture(mask, vec2(_e14));
    if ((m_1.w < 0.5)) {
        discard;
    }
    vec2 _e23 = v_uv;
    vec4 _e26 = texture(albedo, vec2(_e23));
    c = _e26;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e55 = i;
            i = (_e55 + 1);
        }
        loop_init = false;
        int _e30 = i;
        if (!((_e30 < 8))) {
            break;
        }
        float _e35 = c.x;
        if ((_e35 > 0.95)) {
            break;
        }
        vec2 _e40 = v_uv;
        int _e42 = i;
        vec4 _e50 = texture(albedo, vec2((_e40 + vec2((float(_e42) * 0.01)))));
        vec4 _e53 = c;
        c = (_e53 + (_e50 * 0.1));
    }
    vec2 _e62 = v_uv;
    float _e66 = texture(depth, vec3(_e62, 0.5));
    float lit = ((m_1.y > 0.5) ? _e66 : 1.0);
    vec4 _e71 = c;
    vec2 _e75 = v_uv;
    float _e76 = march(_e75);
    f_color = vec4(((_e71.xyz * lit) * _e76), 1.0);
    vec4 _e81 = f_color;
    nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e81);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

