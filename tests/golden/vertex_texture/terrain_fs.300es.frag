#version 300 es

precision highp float;
precision highp int;

struct terrain_fs_out {
    vec4 f_color;
};
uniform highp sampler2D heightmap;

smooth in vec2 _vs2fs_location0;
smooth in float _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

float height_at(vec2 uv) {
    vec4 _e3 = texture(heightmap, vec2(uv));
    return (_e3.x * 2.0);
}

void main() {
    vec2 v_uv = _vs2fs_location0;
    float v_height = _vs2fs_location1;
    vec4 f_color = vec4(0.0);
    float _e2 = height_at(v_uv);
    vec2 _e3 = dFdx(v_uv);
    vec2 _e4 = dFdy(v_uv);
    vec4 _e7 = textureGrad(heightmap, vec2(v_uv), _e3, _e4);
    float dx = _e7.x;
    f_color = vec4(vec3(((_e2 * 0.5) + (dx * 0.1)), v_height, 0.0), 1.0);
    vec4 _e20 = f_color;
    terrain_fs_out _tmp_return = terrain_fs_out(_e20);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

