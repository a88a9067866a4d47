#version 300 es

precision highp float;
precision highp int;

struct bright_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_threshold_block { vec4 u_threshold; };

uniform highp sampler2D hdr_scene;

vec2 v_uv = vec2(0.0);

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    float soft = 0.0;
    v_uv = in_v_uv;
    vec2 _e3 = v_uv;
    vec4 _e6 = texture(hdr_scene, vec2(_e3));
    vec3 c_1 = _e6.xyz;
    float _e10 = u_threshold.x;
    float _e13 = u_threshold.y;
    float knee = (_e10 * _e13);
    float _e15 = luminance(c_1);
    float _e19 = u_threshold.x;
    soft = clamp(((_e15 - _e19) + knee), 0.0, (2.0 * knee));
    float _e28 = soft;
    float _e30 = soft;
    soft = ((_e28 * _e30) / ((4.0 * knee) + 1e-5));
    float _e38 = soft;
    float _e41 = u_threshold.x;
    float contribution = (max(_e38, (_e15 - _e41)) / max(_e15, 1e-5));
    f_color = vec4((c_1 * contribution), 1.0);
    vec4 _e52 = f_color;
    bright_fs_out _tmp_return = bright_fs_out(_e52);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

