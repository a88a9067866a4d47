#version 330 core
struct bright_fs_out {
    vec4 f_color;
};
uniform vec4 u_threshold;

uniform sampler2D hdr_scene;

smooth in vec2 v_uv;
out vec4 f_color;

float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    float soft = 0.0;
    vec4 _e3 = texture(hdr_scene, vec2(in_v_uv));
    vec3 c_1 = _e3.xyz;
    float _e7 = u_threshold.x;
    float _e10 = u_threshold.y;
    float knee = (_e7 * _e10);
    float _e12 = luminance(c_1);
    float _e16 = u_threshold.x;
    soft = clamp(((_e12 - _e16) + knee), 0.0, (2.0 * knee));
    float _e25 = soft;
    float _e27 = soft;
    soft = ((_e25 * _e27) / ((4.0 * knee) + 1e-5));
    float _e35 = soft;
    float _e38 = u_threshold.x;
    float contribution = (max(_e35, (_e12 - _e38)) / max(_e12, 1e-5));
    out_f_color = vec4((c_1 * contribution), 1.0);
    vec4 _e49 = out_f_color;
    bright_fs_out _tmp_return = bright_fs_out(_e49);
    f_color = _tmp_return.f_color;
    return;
}

