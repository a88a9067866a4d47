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

smooth in vec2 v_uv;
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
            vec4 _e15 = texture(layers_2, vec2(uv));
            texel_2 = _e15;
            break;
        }
    }
    vec4 _e18 = texel_2;
    return _e18;
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
    vec4 _e13 = textureLod(layers_2, vec2((in_v_uv * 4.0)), 0.0);
    vec4 _e14 = c;
    c = (_e14 + _e13);
    int _e18 = u_pick;
    vec4 _e19 = layer(_e18, in_v_uv);
    vec4 _e20 = c;
    c = (_e20 + _e19);
    int _e24 = u_pick;
    switch(min(max((_e24 + 1), 0), 2)) {
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
            int _e71 = i;
            i = (_e71 + 1);
        }
        loop_init = false;
        int _e49 = i;
        if (!((_e49 < 2))) {
            break;
        }
        int _e55 = i;
        switch(min(max(_e55, 0), 1)) {
            case 0: {
                float _e61 = texture(shadows_0, vec3(in_v_uv, 0.5));
                texel_1 = _e61;
                break;
            }
            default: {
                float _e65 = texture(shadows_1, vec3(in_v_uv, 0.5));
                texel_1 = _e65;
                break;
            }
        }
        float _e68 = texel_1;
        float _e69 = lit;
        lit = (_e69 + _e68);
    }
    vec4 _e76 = c;
    float _e78 = lit;
    out_f_color = ((_e76 * _e78) + vec4((float(size.x) * 0.0)));
    vec4 _e87 = out_f_color;
    layers_fs_out _tmp_return = layers_fs_out(_e87);
    f_color = _tmp_return.f_color;
    return;
}

