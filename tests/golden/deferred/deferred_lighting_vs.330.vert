#version 330 core
struct deferred_lighting_vs_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
};
out vec2 v_uv;

void main() {
    uint VertexID = uint(gl_VertexID);
    vec2 out_v_uv = vec2(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    int _e1 = int(VertexID);
    vec2 corner = vec2(float(((_e1 << uint(1)) & 2)), float((_e1 & 2)));
    out_v_uv = corner;
    gen_gl_Position = vec4(((corner * 2.0) - vec2(1.0)), 0.0, 1.0);
    vec4 _e20 = gen_gl_Position;
    vec2 _e21 = out_v_uv;
    deferred_lighting_vs_out _tmp_return = deferred_lighting_vs_out(_e20, _e21);
    gl_Position = _tmp_return.gen_gl_Position;
    v_uv = _tmp_return.v_uv;
    return;
}

