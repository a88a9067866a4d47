#version 300 es

precision highp float;
precision highp int;

struct sky_fs_out {
    vec4 f_color;
};
layout(std140) uniform u_exposure_block { float u_exposure; };

uniform highp samplerCube sky;

smooth in vec3 _vs2fs_location0;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec3 v_dir = _vs2fs_location0;
    vec4 f_color = vec4(0.0);
    vec4 _e4 = texture(sky, vec3(normalize(v_dir)));
    float _e7 = u_exposure;
    vec3 hdr = (_e4.xyz * _e7);
    vec3 mapped = (hdr / (hdr + vec3(1.0)));
    f_color = vec4(pow(mapped, vec3((1.0 / 2.2))), 1.0);
    vec4 _e22 = f_color;
    sky_fs_out _tmp_return = sky_fs_out(_e22);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

