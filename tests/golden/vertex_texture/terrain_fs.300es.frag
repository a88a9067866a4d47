#version 300 es

precision highp float;
precision highp int;

struct terrain_fs_out {
    vec4 f_color;
};
uniform highp sampler2D heightmap;

in vec2 v_uv;
in float v_height;
out vec4 f_color;

float height_at(vec2 uv) {
    vec4 _e3 = texture(heightmap, vec2(uv));
    return (_e3.x * 2.0);
}

void main() {
    vec2 in_v_uv = v_uv;
    float in_v_height = v_height;
    vec4 out_f_color = vec4(0.0);
    float _e2 = height_at(in_v_uv);
    vec2 _e3 = dFdx(in_v_uv);
    vec2 _e4 = dFdy(in_v_uv);
    vec4 _e7 = textureGrad(heightmap, vec2(in_v_uv), _e3, _e4);
    float dx = _e7.x;
    out_f_color = vec4(vec3(((_e2 * 0.5) + (dx * 0.1)), in_v_height, 0.0), 1.0);
    vec4 _e19 = out_f_color;
    terrain_fs_out _tmp_return = terrain_fs_out(_e19);
    f_color = _tmp_return.f_color;
    return;
}

