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

in vec2 v_uv;
out vec4 f_color;

float march(vec2 uv) {
    float t = 0.0;
    vec2 p = vec2(0.0);
    t = 0.0;
    p = uv;
    while(true) {
        float _e4 = t;
        if (!((_e4 < 1.0))) {
            break;
        }
        vec2 _e8 = p;
        vec4 _e11 = texture(mask, vec2(_e8));
        float m = _e11.x;
        if ((m > 0.9)) {
            break;
        }
        float _e17 = t;
        t = (_e17 + (0.1 + m));
        vec2 _e21 = p;
        p = (_e21 + vec2(0.01));
    }
    float _e23 = t;
    return _e23;
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    int i = 0;
    if ((in_v_uv.x < 0.1)) {
        out_f_color = vec4(0.0);
        vec4 _e7 = out_f_color;
        nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e7);
        f_color = _tmp_return.f_color;
        return;
    }
    vec4 m_1 = texture(mask, vec2(in_v_uv));
    if ((m_1.w < 0.5)) {
        discard;
    }
    vec4 _e18 = texture(albedo, vec2(in_v_uv));
    c = _e18;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e39 = i;
            i = (_e39 + 1);
        }
        loop_init = false;
        int _e22 = i;
        if (!((_e22 < 8))) {
            break;
        }
        float _e26 = c.x;
        if ((_e26 > 0.95)) {
            break;
        }
        int _e29 = i;
        vec4 _e35 = texture(albedo, vec2((in_v_uv + vec2((float(_e29) * 0.01)))));
        vec4 _e37 = c;
        c = (_e37 + (_e35 * 0.1));
    }
    float _e46 = texture(depth, vec3(in_v_uv, 0.5));
    float lit = ((m_1.y > 0.5) ? _e46 : 1.0);
    vec4 _e49 = c;
    float _e52 = march(in_v_uv);
    out_f_color = vec4(((_e49.xyz * lit) * _e52), 1.0);
    vec4 _e55 = out_f_color;
    nonuniform_fs_out _tmp_return = nonuniform_fs_out(_e55);
    f_color = _tmp_return.f_color;
    return;
}

