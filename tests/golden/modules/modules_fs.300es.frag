#version 300 es

precision highp float;
precision highp int;

struct modules_fs_out {
    vec4 f_color;
};
const vec3 RAMP_LO = vec3(0.02, 0.03, 0.1);
const vec3 RAMP_HI = vec3(3.0, 2.2, 1.4);

uniform float u_exposure;

in vec2 v_uv;
out vec4 f_color;

vec3 palette_ramp(float t) {
    return mix(RAMP_LO, RAMP_HI, vec3((t * t)));
}

vec3 aces(vec3 x) {
    return clamp(((x * ((2.51 * x) + vec3(0.03))) / ((x * ((2.43 * x) + vec3(0.59))) + vec3(0.14))), vec3(0.0), vec3(1.0));
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec3 _e2 = palette_ramp(in_v_uv.x);
    float _e4 = u_exposure;
    vec3 hdr = (_e2 * _e4);
    vec3 _e7 = aces(hdr);
    out_f_color = vec4(_e7, 1.0);
    vec4 _e10 = out_f_color;
    modules_fs_out _tmp_return = modules_fs_out(_e10);
    f_color = _tmp_return.f_color;
    return;
}

