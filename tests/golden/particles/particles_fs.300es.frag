#version 300 es

precision highp float;
precision highp int;

struct particles_fs_out {
    vec4 f_color;
};
uniform highp sampler2D sprite;

vec4 v_color = vec4(0.0);

vec4 f_color = vec4(0.0);

vec2 gen_gl_PointCoord = vec2(0.0);

smooth in vec4 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec4 in_v_color = _vs2fs_location1;
    vec2 in_PointCoord = gl_PointCoord;
    v_color = in_v_color;
    gen_gl_PointCoord = in_PointCoord;
    vec2 _e5 = gen_gl_PointCoord;
    vec2 d = ((_e5 * 2.0) - vec2(1.0));
    float r2_ = dot(d, d);
    if ((r2_ > 1.0)) {
        discard;
    }
    vec2 _e15 = gen_gl_PointCoord;
    vec4 tex = texture(sprite, vec2(_e15));
    float _e21 = v_color.w;
    float alpha = ((_e21 * tex.w) * (1.0 - r2_));
    if ((alpha < 0.01)) {
        discard;
    }
    vec4 _e31 = v_color;
    f_color = vec4((_e31.xyz * tex.xyz), alpha);
    vec4 _e37 = f_color;
    particles_fs_out _tmp_return = particles_fs_out(_e37);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

