#version 300 es

precision highp float;
precision highp int;

struct texel_offsets_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
uniform highp sampler2D albedo;

layout(location = 0) in vec2 a_pos;
out vec2 v_uv;

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    vec2 _e6 = out_v_uv;
    vec4 _e12 = textureLodOffset(albedo, vec2(_e6), 0.0, ivec2(-1, 0));
    float h = _e12.x;
    gen_gl_Position = vec4(in_a_pos, h, 1.0);
    vec4 _e17 = gen_gl_Position;
    vec2 _e18 = out_v_uv;
    texel_offsets_vs_out _tmp_return = texel_offsets_vs_out(_e17, _e18);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

