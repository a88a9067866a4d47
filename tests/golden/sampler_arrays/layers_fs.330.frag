#version 330 core
struct layers_fs_out {
    vec4 f_color;
};
uniform sampler2D layers_0;

uniform sampler2D layers_1;

uniform sampler2D layers_2;

uniform sampler2DShadow shadows_0;

uniform sampler2DShadow shadows_1;

layout(std140) uniform u_pick_block { int u_pick; };

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

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
    vec2 in_v_uv = _vs2fs_location0;
    vec4 c = vec4(0.0);
    ivec2 texel = ivec2(0);
    float lit = 0.0;
    int i = 0;
    float texel_1 = 0.0;
    v_uv = in_v_uv;
    vec2 _e4 = v_uv;
    vec4 _e7 = texture(layers_0, vec2(_e4));
    c = (_e7 * 0.5);
    vec2 _e12 = v_uv;
    vec4 _e18 = textureLod(layers_2, vec2((_e12 * 4.0)), 0.0);
    vec4 _e19 = c;
    c = (_e19 + _e18);
    int _e23 = u_pick;
    vec2 _e25 = v_uv;
    vec4 _e26 = layer(_e23, _e25);
    vec4 _e27 = c;
    c = (_e27 + _e26);
    int _e31 = u_pick;
    switch(min(max((_e31 + 1), 0), 2)) {
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
            int _e80 = i;
            i = (_e80 + 1);
        }
        loop_init = false;
        int _e56 = i;
        if (!((_e56 < 2))) {
            break;
        }
        vec2 _e61 = v_uv;
        int _e64 = i;
        switch(min(max(_e64, 0), 1)) {
            case 0: {
                float _e70 = texture(shadows_0, vec3(_e61, 0.5));
                texel_1 = _e70;
                break;
            }
            default: {
                float _e74 = texture(shadows_1, vec3(_e61, 0.5));
                texel_1 = _e74;
                break;
            }
        }
        float _e77 = texel_1;
        float _e78 = lit;
        lit = (_e78 + _e77);
    }
    vec4 _e85 = c;
    float _e87 = lit;
    f_color = ((_e85 * _e87) + vec4((float(size.x) * 0.0)));
    vec4 _e96 = f_color;
    layers_fs_out _tmp_return = layers_fs_out(_e96);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

