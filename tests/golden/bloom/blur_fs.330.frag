#version 330 core
struct blur_fs_out {
    vec4 f_color;
};
const float WEIGHTS[5] = float[5](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);

uniform vec2 u_direction;

uniform sampler2D bloom_src;

smooth in vec2 v_uv;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec3 sum = vec3(0.0);
    int i = 0;
    vec2 _e2 = u_direction;
    vec2 texel = (_e2 / vec2(ivec2(uvec2(textureSize(bloom_src, 0).xy))));
    vec4 _e12 = texture(bloom_src, vec2(in_v_uv));
    sum = (_e12.xyz * WEIGHTS[0]);
    i = 1;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e53 = i;
            i = (_e53 + 1);
        }
        loop_init = false;
        int _e20 = i;
        if (!((_e20 < 5))) {
            break;
        }
        int _e24 = i;
        vec2 off = (texel * float(_e24));
        vec4 _e31 = texture(bloom_src, vec2((in_v_uv + off)));
        int _e35 = i;
        vec3 _e38 = sum;
        sum = (_e38 + (_e31.xyz * WEIGHTS[_e35]));
        vec4 _e44 = texture(bloom_src, vec2((in_v_uv - off)));
        int _e48 = i;
        vec3 _e51 = sum;
        sum = (_e51 + (_e44.xyz * WEIGHTS[_e48]));
    }
    vec3 _e58 = sum;
    out_f_color = vec4(_e58, 1.0);
    vec4 _e62 = out_f_color;
    blur_fs_out _tmp_return = blur_fs_out(_e62);
    f_color = _tmp_return.f_color;
    return;
}

