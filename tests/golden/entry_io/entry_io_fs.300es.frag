#version 300 es

precision highp float;
precision highp int;

struct entry_io_fs_out {
    vec4 f_color;
    vec4 f_extra;
};
float v_shade = 0.0;

smooth in vec2 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
smooth in float _vs2fs_location2;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out vec4 _fs2p_location1;

void main() {
    vec2 v_uv = _vs2fs_location0;
    vec3 v_tint = _vs2fs_location1;
    float in_v_shade = _vs2fs_location2;
    vec4 FragCoord = gl_FragCoord;
    vec4 f_color = vec4(0.0);
    vec4 f_extra = vec4(0.0);
    v_shade = in_v_shade;
    float _e7 = v_shade;
    v_shade = clamp(_e7, 0.0, 1.0);
    if ((FragCoord.x > 10.0)) {
        float _e16 = v_shade;
        v_shade = (_e16 * 0.5);
        f_extra = vec4(v_uv, 0.0, 1.0);
    }
    float _e24 = v_shade;
    f_color = vec4((v_tint * _e24), 1.0);
    vec4 _e29 = f_color;
    vec4 _e31 = f_extra;
    entry_io_fs_out _tmp_return = entry_io_fs_out(_e29, _e31);
    _fs2p_location0 = _tmp_return.f_color;
    _fs2p_location1 = _tmp_return.f_extra;
    return;
}

