#version 300 es

precision highp float;
precision highp int;

struct entry_io_fs_out {
    vec4 f_color;
    vec4 f_extra;
};
float io_v_shade = 0.0;

in vec2 v_uv;
in vec3 v_tint;
in float v_shade;
layout(location = 0) out vec4 f_color;
layout(location = 1) out vec4 f_extra;

void main() {
    vec2 in_v_uv = v_uv;
    vec3 in_v_tint = v_tint;
    float in_v_shade = v_shade;
    vec4 FragCoord = gl_FragCoord;
    vec4 out_f_color = vec4(0.0);
    vec4 out_f_extra = vec4(0.0);
    io_v_shade = in_v_shade;
    float _e5 = io_v_shade;
    io_v_shade = clamp(_e5, 0.0, 1.0);
    if ((FragCoord.x > 10.0)) {
        float _e13 = io_v_shade;
        io_v_shade = (_e13 * 0.5);
        out_f_extra = vec4(in_v_uv, 0.0, 1.0);
    }
    float _e18 = io_v_shade;
    out_f_color = vec4((in_v_tint * _e18), 1.0);
    vec4 _e21 = out_f_color;
    vec4 _e22 = out_f_extra;
    entry_io_fs_out _tmp_return = entry_io_fs_out(_e21, _e22);
    f_color = _tmp_return.f_color;
    f_extra = _tmp_return.f_extra;
    return;
}

