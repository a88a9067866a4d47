#version 300 es

precision highp float;
precision highp int;

struct material_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_tint_block { vec4 u_tint; };

uniform highp sampler2D albedo;

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 v_uv = _vs2fs_location0;
    vec4 f_color = vec4(0.0);
    vec4 _e4 = texture(albedo, vec2(v_uv));
    vec4 _e6 = u_tint;
    f_color = (_e4 * _e6);
    vec4 _e9 = f_color;
    material_fs_out _tmp_return = material_fs_out(_e9);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

