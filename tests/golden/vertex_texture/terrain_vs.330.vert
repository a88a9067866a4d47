#version 330 core
struct terrain_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_height;
};
uniform sampler2D heightmap;

uniform sampler2DShadow shadow;

layout(std140) uniform u_mvp_block { mat4x4 u_mvp; };

vec2 a_pos = vec2(0.0);

vec2 v_uv = vec2(0.0);

float v_height = 0.0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
smooth out float _vs2fs_location1;

float height_at_vertex(vec2 uv) {
    vec4 _e3 = textureLod(heightmap, vec2(uv), 0.0);
    return (_e3.x * 2.0);
}

void main() {
    vec2 in_a_pos = _p2vs_location0;
    a_pos = in_a_pos;
    vec2 _e4 = a_pos;
    v_uv = ((_e4 * 0.5) + vec2(0.5));
    vec2 _e11 = v_uv;
    float _e12 = height_at_vertex(_e11);
    vec2 _e14 = v_uv;
    vec4 _e18 = textureLod(heightmap, vec2(_e14), 1.0);
    float h = (_e12 + _e18.y);
    vec2 _e23 = v_uv;
    float _e27 = textureLod(shadow, vec3(_e23, 0.5), 0.0);
    vec2 _e30 = v_uv;
    vec3 _e32 = vec3(_e30, 1.0);
    vec4 _e39 = textureLod(heightmap, vec2((_e32.xy / vec2(_e32.z))), 0.0);
    v_height = ((h * _e27) + _e39.z);
    mat4x4 _e44 = u_mvp;
    float _e47 = a_pos.x;
    float _e50 = a_pos.y;
    gen_gl_Position = (_e44 * vec4(_e47, h, _e50, 1.0));
    vec4 _e55 = gen_gl_Position;
    vec2 _e57 = v_uv;
    float _e59 = v_height;
    terrain_vs_out _tmp_return = terrain_vs_out(_e55, _e57, _e59);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_height;
    return;
}

