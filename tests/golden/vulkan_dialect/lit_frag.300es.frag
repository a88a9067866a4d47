#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct Frame {
    mat4x4 view_proj;
    vec4 tint;
};
struct lit_frag_out {
    vec4 o_color;
};
layout(std140) uniform frame_ubo {
    mat4x4 view_proj;
    vec4 tint;
} frame;

uniform highp sampler2D albedo;

uniform highp sampler2DShadow shadow;

in vec2 vk_location0;
in float vk_location1;
flat in int vk_location2;
flat in float vk_location3;
layout(location = 0) out vec4 o_color;

void main() {
    vec2 in_f_uv = vk_location0;
    float in_f_depth = vk_location1;
    int in_f_layer = vk_location2;
    float in_f_weight = vk_location3;
    vec4 out_o_color = vec4(0.0);
    float lit = texture(shadow, vec3(in_f_uv, in_f_depth));
    vec4 _e9 = texture(albedo, vec2(in_f_uv));
    vec4 _e12 = frame.tint;
    vec4 c = (_e9 * _e12);
    out_o_color = vec4(((c.xyz * lit) * in_f_weight), float(in_f_layer));
    vec4 _e20 = out_o_color;
    lit_frag_out _tmp_return = lit_frag_out(_e20);
    o_color = _tmp_return.o_color;
    return;
}

