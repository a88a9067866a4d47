#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct layers_fs_out {
    vec4 f_color;
};
uniform highp sampler2D layers_0;

uniform highp sampler2D layers_1;

uniform highp sampler2D layers_2;

uniform highp sampler2DShadow shadows_0;

uniform highp sampler2DShadow shadows_1;

uniform int u_pick;

in vec2 v_uv;
out vec4 f_color;

vec4 layer(int i_1, vec2 uv) {
    vec4 texel_2 = vec4(0.0);
    switch(min(max(i_1, 0), 2)) {
        case 0: {
            vec4 _e7 = texture(layers_0, vec2(uv));
            texel_2 = _e7;
            break;
        }
        case 1: {
            vec4 _e11 = texture(layers_1, vec2(uv));
            texel_2 = _e11;
            break;
        }
        default: {
            vec4 _e14 = texture(layers_2, vec2(uv));
            texel_2 = _e14;
            break;
        }
    }
    vec4 _e15 = texel_2;
    return _e15;
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 c = vec4(0.0);
    ivec2 texel = ivec2(0);
    float lit = 0.0;
    int i = 0;
    float texel_1 = 0.0;
    vec4 _e4 = texture(layers_0, vec2(in_v_uv));
    c = (_e4 * 0.5);
    vec4 _e12 = textureLod(layers_2, vec2((in_v_uv * 4.0)), 0.0);
    vec4 _e13 = c;
    c = (_e13 + _e12);
    int _e16 = u_pick;
    vec4 _e17 = layer(_e16, in_v_uv);
    vec4 _e18 = c;
    c = (_e18 + _e17);
    int _e21 = u_pick;
    switch(min(max((_e21 + 1), 0), 2)) {
        case 0: {
            texel = ivec2(uvec2(textureSize(layers_0, 0).xy));
            break;
        }
        case 1: {
            texel = ivec2(uvec2(textureSize(layers_1, 0).xy));
            break;
        }
        default: {
            texel = ivec2(uvec2(textureSize(layers_2, 0).xy));
            break;
        }
    }
    ivec2 size = texel;
    lit = 0.0;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e52 = i;
            i = (_e52 + 1);
        }
        loop_init = false;
        int _e37 = i;
        if (!((_e37 < 2))) {
            break;
        }
        int _e40 = i;
        switch(min(max(_e40, 0), 1)) {
            case 0: {
                float _e44 = texture(shadows_0, vec3(in_v_uv, 0.5));
                texel_1 = _e44;
                break;
            }
            default: {
                float _e48 = texture(shadows_1, vec3(in_v_uv, 0.5));
                texel_1 = _e48;
                break;
            }
        }
        float _e49 = texel_1;
        float _e50 = lit;
        lit = (_e50 + _e49);
    }
    vec4 _e55 = c;
    float _e56 = lit;
    out_f_color = ((_e55 * _e56) + vec4((float(size.x) * 0.0)));
    vec4 _e63 = out_f_color;
    layers_fs_out _tmp_return = layers_fs_out(_e63);
    f_color = _tmp_return.f_color;
    return;
}

