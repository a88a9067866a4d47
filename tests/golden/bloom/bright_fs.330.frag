#version 330 core
struct bright_fs_out {
    vec4 f_color;
};
uniform vec4 u_threshold;

uniform sampler2D hdr_scene;

in vec2 v_uv;
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
    float _e9 = u_threshold.y;
    float knee = (_e7 * _e9);
    float _e11 = luminance(c_1);
    float _e14 = u_threshold.x;
    soft = clamp(((_e11 - _e14) + knee), 0.0, (2.0 * knee));
    float _e21 = soft;
    float _e22 = soft;
    soft = ((_e21 * _e22) / ((4.0 * knee) + 1e-5));
    float _e29 = soft;
    float _e31 = u_threshold.x;
    float contribution = (max(_e29, (_e11 - _e31)) / max(_e11, 1e-5));
    out_f_color = vec4((c_1 * contribution), 1.0);
    vec4 _e40 = out_f_color;
    bright_fs_out _tmp_return = bright_fs_out(_e40);
    f_color = _tmp_return.f_color;
    return;
}

