#version 330 core
struct fullscreen_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
vec2 v_uv = vec2(0.0);

int gen_gl_VertexID = 0;

vec4 gen_gl_Position = vec4(0.0);

smooth out vec2 _vs2fs_location0;

void main() {
    uint in_VertexID = uint(gl_VertexID);
    gen_gl_VertexID = int(in_VertexID);
    int _e4 = gen_gl_VertexID;
    int _e12 = gen_gl_VertexID;
    vec2 corner = vec2(float(((_e4 << uint(1)) & 2)), float((_e12 & 2)));
    v_uv = corner;
    gen_gl_Position = vec4(((corner * 2.0) - vec2(1.0)), 0.0, 1.0);
    vec4 _e28 = gen_gl_Position;
    vec2 _e30 = v_uv;
    fullscreen_vs_out _tmp_return = fullscreen_vs_out(_e28, _e30);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_uv;
    return;
}

