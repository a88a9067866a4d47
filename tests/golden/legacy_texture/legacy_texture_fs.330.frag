#version 330 core
struct legacy_texture_fs_out {
    vec4 f_color;
};
uniform sampler2D u_tex;

uniform samplerCube u_env;

smooth in vec2 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec2 v_uv = _vs2fs_location0;
    vec3 v_dir = _vs2fs_location1;
    vec4 f_color = vec4(0.0);
    vec4 _e5 = texture(u_tex, vec2(v_uv));
    vec4 _e8 = texture(u_env, vec3(v_dir));
    f_color = (_e5 * _e8);
    vec4 _e11 = f_color;
    legacy_texture_fs_out _tmp_return = legacy_texture_fs_out(_e11);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

