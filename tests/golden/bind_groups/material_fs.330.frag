#version 330 core
struct material_fs_out {
    vec4 f_color;
};
uniform vec4 u_tint;

uniform sampler2D albedo;

in vec2 v_uv;
out vec4 f_color;

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    vec4 _e4 = texture(albedo, vec2(in_v_uv));
    vec4 _e6 = u_tint;
    out_f_color = (_e4 * _e6);
    vec4 _e8 = out_f_color;
    material_fs_out _tmp_return = material_fs_out(_e8);
    f_color = _tmp_return.f_color;
    return;
}

