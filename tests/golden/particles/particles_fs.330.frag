#version 330 core
struct particles_fs_out {
    vec4 f_color;
};
uniform sampler2D sprite;

smooth in vec4 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec4 v_color = _vs2fs_location1;
    vec2 PointCoord = gl_PointCoord;
    vec4 f_color = vec4(0.0);
    vec2 d = ((PointCoord * 2.0) - vec2(1.0));
    float r2_ = dot(d, d);
    if ((r2_ > 1.0)) {
        discard;
    }
    vec4 tex = texture(sprite, vec2(PointCoord));
    float alpha = ((v_color.w * tex.w) * (1.0 - r2_));
    if ((alpha < 0.01)) {
        discard;
    }
    f_color = vec4((v_color.xyz * tex.xyz), alpha);
    vec4 _e27 = f_color;
    particles_fs_out _tmp_return = particles_fs_out(_e27);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

