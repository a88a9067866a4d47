#version 330 core
struct blur_fs_out {
    vec4 f_color;
};
const float WEIGHTS[5] = float[5](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);

uniform vec2 u_direction;

uniform sampler2D bloom_src;

in vec2 v_uv;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec3 sum = vec3(0.0);
    int i = 0;
    vec2 _e2 = u_direction;
    vec2 texel = (_e2 / vec2(ivec2(uvec2(textureSize(bloom_src, 0).xy))));
    vec4 _e11 = texture(bloom_src, vec2(in_v_uv));
    sum = (_e11.xyz * WEIGHTS[0]);
    i = 1;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e41 = i;
            i = (_e41 + 1);
        }
        loop_init = false;
        int _e19 = i;
        if (!((_e19 < 5))) {
            break;
        }
        int _e22 = i;
        vec2 off = (texel * float(_e22));
        vec4 _e26 = texture(bloom_src, vec2((in_v_uv + off)));
        int _e28 = i;
        vec3 _e31 = sum;
        sum = (_e31 + (_e26.xyz * WEIGHTS[_e28]));
        vec4 _e34 = texture(bloom_src, vec2((in_v_uv - off)));
        int _e36 = i;
        vec3 _e39 = sum;
        sum = (_e39 + (_e34.xyz * WEIGHTS[_e36]));
    }
    vec3 _e44 = sum;
    out_f_color = vec4(_e44, 1.0);
    vec4 _e47 = out_f_color;
    blur_fs_out _tmp_return = blur_fs_out(_e47);
    f_color = _tmp_return.f_color;
    return;
}

