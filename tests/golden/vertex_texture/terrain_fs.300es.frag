#version 300 es

precision highp float;
precision highp int;

struct terrain_fs_out {
    vec4 f_color;
};
uniform highp sampler2D heightmap;

vec2 v_uv = vec2(0.0);

float v_height = 0.0;

vec4 f_color = vec4(0.0);

smooth in vec2 _vs2fs_location0;
smooth in float _vs2fs_location1;
layout(location = 0) out vec4 _fs2p_location0;

float height_at(vec2 uv) {
    vec4 _e3 = texture(heightmap, vec2(uv));
    return (_e3.x * 2.0);
}

void main() {
    vec2 in_v_uv = _vs2fs_location0;
    float in_v_height = _vs2fs_location1;
    v_uv = in_v_uv;
    v_height = in_v_height;
    vec2 _e5 = v_uv;
    float _e6 = height_at(_e5);
    vec2 _e8 = v_uv;
    vec2 _e10 = v_uv;
    vec2 _e11 = dFdx(_e10);
    vec2 _e13 = v_uv;
    vec2 _e14 = dFdy(_e13);
    vec4 _e17 = textureGrad(heightmap, vec2(_e8), _e11, _e14);
    float dx = _e17.x;
    float _e26 = v_height;
    f_color = vec4(vec3(((_e6 * 0.5) + (dx * 0.1)), _e26, 0.0), 1.0);
    vec4 _e32 = f_color;
    terrain_fs_out _tmp_return = terrain_fs_out(_e32);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

