#version 300 es

precision highp float;
precision highp int;
precision highp sampler2DShadow;

struct terrain_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_height;
};
uniform highp sampler2D heightmap;

uniform highp sampler2DShadow shadow;

layout(std140) uniform u_mvp_block { mat4x4 u_mvp; };

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
smooth out float _vs2fs_location1;

float height_at_vertex(vec2 uv) {
    vec4 _e3 = textureLod(heightmap, vec2(uv), 0.0);
    return (_e3.x * 2.0);
}

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    float v_height = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    vec2 _e8 = v_uv;
    float _e9 = height_at_vertex(_e8);
    vec2 _e11 = v_uv;
    vec4 _e15 = textureLod(heightmap, vec2(_e11), 1.0);
    float h = (_e9 + _e15.y);
    vec2 _e20 = v_uv;
    float _e24 = textureLod(shadow, vec3(_e20, 0.5), 0.0);
    vec2 _e27 = v_uv;
    vec3 _e29 = vec3(_e27, 1.0);
    vec4 _e36 = textureLod(heightmap, vec2((_e29.xy / vec2(_e29.z))), 0.0);
    v_height = ((h * _e24) + _e36.z);
    mat4x4 _e41 = u_mvp;
    gen_gl_Position = (_e41 * vec4(a_pos.x, h, a_pos.y, 1.0));
    vec4 _e48 = gen_gl_Position;
    vec2 _e50 = v_uv;
    float _e52 = v_height;
    terrain_vs_out _tmp_return = terrain_vs_out(_e48, _e50, _e52);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_height;
    return;
}

