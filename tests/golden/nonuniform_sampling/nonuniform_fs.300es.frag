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

smooth in vec2 v_uv;
out vec4 f_color;

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
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    int i = 0;
    if ((in_v_uv.x < 0.1)) {
        out_f_color = vec4(0.0);
        vec4 _e8 = out_f_color;
        nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e8);
        f_color = _tmp_return.f_color;
        return;
    }
    vec4 m_1 = texture(mask, vec2(in_v_uv));
    if ((m_1.w < 0.5)) {
        discard;
    }
    vec4 _e19 = texture(albedo, vec2(in_v_uv));
    c = _e19;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e46 = i;
            i = (_e46 + 1);
        }
        loop_init = false;
        int _e23 = i;
        if (!((_e23 < 8))) {
            break;
        }
        float _e28 = c.x;
        if ((_e28 > 0.95)) {
            break;
        }
        int _e33 = i;
        vec4 _e41 = texture(albedo, vec2((in_v_uv + vec2((float(_e33) * 0.01)))));
        vec4 _e44 = c;
        c = (_e44 + (_e41 * 0.1));
    }
    float _e55 = texture(depth, vec3(in_v_uv, 0.5));
    float lit = ((m_1.y > 0.5) ? _e55 : 1.0);
    vec4 _e60 = c;
    float _e63 = march(in_v_uv);
    out_f_color = vec4(((_e60.xyz * lit) * _e63), 1.0);
    vec4 _e68 = out_f_color;
    nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e68);
    f_color = _tmp_return.f_color;
    return;
}

