#version 330 core
struct points_fs_out {
    vec4 f_color;
};
vec4 f_color = vec4(0.0);

vec2 gen_gl_PointCoord = vec2(0.0);

layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 in_PointCoord = gl_PointCoord;
    gen_gl_PointCoord = in_PointCoord;
    vec2 _e3 = gen_gl_PointCoord;
    vec2 d = (_e3 - vec2(0.5));
    if ((dot(d, d) > 0.25)) {
        discard;
    }
    vec2 _e12 = gen_gl_PointCoord;
    f_color = vec4(_e12, 1.0, 1.0);
    vec4 _e17 = f_color;
    points_fs_out _tmp_return = points_fs_out(_e17);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

