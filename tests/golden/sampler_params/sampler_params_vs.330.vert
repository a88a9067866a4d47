#version 330 core
struct sampler_params_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_height;
};
uniform sampler2D detail;

layout(location = 0) in vec2 a_pos;
out vec2 v_uv;
out float v_height;

vec4 tap_detail_vertex(vec2 uv) {
    vec4 _e3 = textureLod(detail, vec2(uv), 0.0);
    return _e3;
}

void main() {
    vec2 in_a_pos = a_pos;
    vec2 out_v_uv = vec2(0.0);
    float out_v_height = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    out_v_uv = ((in_a_pos * 0.5) + vec2(0.5));
    vec2 _e7 = out_v_uv;
    vec4 _e8 = tap_detail_vertex(_e7);
    out_v_height = _e8.x;
    float _e11 = out_v_height;
    gen_gl_Position = vec4(in_a_pos, _e11, 1.0);
    vec4 _e14 = gen_gl_Position;
    vec2 _e15 = out_v_uv;
    float _e16 = out_v_height;
    sampler_params_vs_out _tmp_return = sampler_params_vs_out(_e14, _e15, _e16);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    v_height = _tmp_return.v_height;
    return;
}

