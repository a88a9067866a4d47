#version 300 es

precision highp float;
precision highp int;

struct legacy_texture_fs_out {
    vec4 f_color;
};
uniform highp sampler2D u_tex;

uniform highp samplerCube u_env;

in vec2 v_uv;
in vec3 v_dir;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec3 in_v_dir = v_dir;
    vec4 out_f_color = vec4(0.0);
    vec4 _e5 = texture(u_tex, vec2(in_v_uv));
    vec4 _e8 = texture(u_env, vec3(in_v_dir));
    out_f_color = (_e5 * _e8);
    vec4 _e10 = out_f_color;
    legacy_texture_fs_out _tmp_return = legacy_texture_fs_out(_e10);
    f_color = _tmp_return.f_color;
    return;
}

