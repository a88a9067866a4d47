#version 330 core
struct sampler_params_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_height;
};
uniform sampler2D detail;

layout(location = 0) in vec2 _p2vs_location0;
smooth out vec2 _vs2fs_location0;
smooth out float _vs2fs_location1;

vec4 tap_detail_vertex(vec2 uv) {
    vec4 _e3 = textureLod(detail, vec2(uv), 0.0);
    return _e3;
}

void main() {
    vec2 a_pos = _p2vs_location0;
    vec2 v_uv = vec2(0.0);
    float v_height = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    v_uv = ((a_pos * 0.5) + vec2(0.5));
    vec2 _e9 = v_uv;
    vec4 _e10 = tap_detail_vertex(_e9);
    v_height = _e10.x;
    float _e14 = v_height;
    gen_gl_Position = vec4(a_pos, _e14, 1.0);
    vec4 _e18 = gen_gl_Position;
    vec2 _e20 = v_uv;
    float _e22 = v_height;
    sampler_params_vs_out _tmp_return = sampler_params_vs_out(_e18, _e20, _e22);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    _vs2fs_location1 = _tmp_return.v_height;
    return;
}

