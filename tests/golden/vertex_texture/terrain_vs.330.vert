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
out vec2 v_uv;
out float v_height;

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
    vec2 _e6 = out_v_uv;
    float _e7 = height_at_vertex(_e6);
    vec2 _e8 = out_v_uv;
    vec4 _e12 = textureLod(heightmap, vec2(_e8), 1.0);
    float h = (_e7 + _e12.y);
    vec2 _e16 = out_v_uv;
    float _e19 = textureLod(shadow, vec3(_e16, 0.5), 0.0);
    vec2 _e21 = out_v_uv;
    vec3 _e22 = vec3(_e21, 1.0);
    vec4 _e27 = textureLod(heightmap, vec2((_e22.xy / vec2(_e22.z))), 0.0);
    out_v_height = ((h * _e19) + _e27.z);
    mat4x4 _e32 = u_mvp;
    gen_gl_Position = (_e32 * vec4(in_a_pos.x, h, in_a_pos.y, 1.0));
    vec4 _e37 = gen_gl_Position;
    vec2 _e38 = out_v_uv;
    float _e39 = out_v_height;
    terrain_vs_out _tmp_return = terrain_vs_out(_e37, _e38, _e39);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_height = _tmp_return.v_height;
    return;
}

