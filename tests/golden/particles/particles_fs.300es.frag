#version 300 es

precision highp float;
precision highp int;

struct particles_fs_out {
    vec4 f_color;
};
uniform highp sampler2D sprite;

in vec4 v_color;
out vec4 f_color;

void main() {
    vec4 in_v_color = v_color;
    vec2 PointCoord = gl_PointCoord;
    vec4 out_f_color = vec4(0.0);
    vec2 d = ((PointCoord * 2.0) - vec2(1.0));
    float r2_ = dot(d, d);
    if ((r2_ > 1.0)) {
        discard;
    }
    vec4 tex = texture(sprite, vec2(PointCoord));
    float alpha = ((in_v_color.w * tex.w) * (1.0 - r2_));
    if ((alpha < 0.01)) {
        discard;
    }
    out_f_color = vec4((in_v_color.xyz * tex.xyz), alpha);
    vec4 _e24 = out_f_color;
    particles_fs_out _tmp_return = particles_fs_out(_e24);
    f_color = _tmp_return.f_color;
    return;
}

