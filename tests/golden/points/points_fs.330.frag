#version 330 core
struct points_fs_out {
    vec4 f_color;
};
out vec4 f_color;

void main() {
    vec2 PointCoord = gl_PointCoord;
    vec4 out_f_color = vec4(0.0);
    vec2 d = (PointCoord - vec2(0.5));
    if ((dot(d, d) > 0.25)) {
        discard;
    }
    out_f_color = vec4(PointCoord, 1.0, 1.0);
    vec4 _e10 = out_f_color;
    points_fs_out _tmp_return = points_fs_out(_e10);
    f_color = _tmp_return.f_color;
    return;
}

