#version 330 core
struct terrain_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_height;
};
uniform sampler2D heightmap;

uniform sampler2DShadow shadow;

uniform mat4x4 u_mvp;

layout(location = 0) in vec2 a_pos;
smooth out vec2 v_uv;
smooth out float v_height;

float height_at_vertex(vec2 uv) {
    vec4 _e3 = textureLod(heightmap, vec2(uv), 0.0);
    return (_e3.x * 2.0);
}

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    float out_v_height = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    vec2 _e8 = out_v_uv;
    float _e9 = height_at_vertex(_e8);
    vec2 _e11 = out_v_uv;
    vec4 _e15 = textureLod(heightmap, vec2(_e11), 1.0);
    float h = (_e9 + _e15.y);
    vec2 _e20 = out_v_uv;
    float _e24 = textureLod(shadow, vec3(_e20, 0.5), 0.0);
    vec2 _e27 = out_v_uv;
    vec3 _e29 = vec3(_e27, 1.0);
    vec4 _e36 = textureLod(heightmap, vec2((_e29.xy / vec2(_e29.z))), 0.0);
    out_v_height = ((h * _e24) + _e36.z);
    mat4x4 _e41 = u_mvp;
    gen_gl_Position = (_e41 * vec4(in_a_pos.x, h, in_a_pos.y, 1.0));
    vec4 _e48 = gen_gl_Position;
    vec2 _e50 = out_v_uv;
    float _e52 = out_v_height;
    terrain_vs_out _tmp_return = terrain_vs_out(_e48, _e50, _e52);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_height = _tmp_return.v_height;
    return;
}

