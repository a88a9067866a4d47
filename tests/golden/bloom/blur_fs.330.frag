#version 330 core
struct blur_fs_out {
    vec4 f_color;
};
const float WEIGHTS[5] = float[5](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);

layout(std140) uniform u_direction_block { vec2 u_direction; };

uniform sampler2D bloom_src;

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    vec3 sum = vec3(0.0);
    int i = 0;
    v_uv = in_v_uv;
    vec2 _e3 = u_direction;
    vec2 texel = (_e3 / vec2(ivec2(uvec2(textureSize(bloom_src, 0).xy))));
    vec2 _e12 = v_uv;
    vec4 _e15 = texture(bloom_src, vec2(_e12));
    sum = (_e15.xyz * WEIGHTS[0]);
    i = 1;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e60 = i;
            i = (_e60 + 1);
        }
        loop_init = false;
        int _e23 = i;
        if (!((_e23 < 5))) {
            break;
        }
        int _e27 = i;
        vec2 off = (texel * float(_e27));
        vec2 _e32 = v_uv;
        vec4 _e36 = texture(bloom_src, vec2((_e32 + off)));
        int _e40 = i;
        vec3 _e43 = sum;
        sum = (_e43 + (_e36.xyz * WEIGHTS[_e40]));
        vec2 _e47 = v_uv;
        vec4 _e51 = texture(bloom_src, vec2((_e47 - off)));
        int _e55 = i;
        vec3 _e58 = sum;
        sum = (_e58 + (_e51.xyz * WEIGHTS[_e55]));
    }
    vec3 _e65 = sum;
    f_color = vec4(_e65, 1.0);
    vec4 _e69 = f_color;
    blur_fs_out _tmp_return = blur_fs_out(_e69);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

