#version 330 core
struct sky_fs_out {
    vec4 f_color;
};
uniform float u_exposure;

uniform samplerCube sky;

in vec3 v_dir;
out vec4 f_color;

void main() {
    vec3 in_v_dir = v_dir;
    vec4 out_f_color = vec4(0.0);
    vec4 _e4 = texture(sky, vec3(normalize(in_v_dir)));
    float _e7 = u_exposure;
    vec3 hdr = (_e4.xyz * _e7);
    vec3 mapped = (hdr / (hdr + vec3(1.0)));
    out_f_color = vec4(pow(mapped, vec3((1.0 / 2.2))), 1.0);
    vec4 _e19 = out_f_color;
    sky_fs_out _tmp_return = sky_fs_out(_e19);
    f_color = _tmp_return.f_color;
    return;
}

