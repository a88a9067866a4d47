#version 300 es

precision highp float;
precision highp int;

uniform uint naga_vs_first_instance;

struct gbuffer_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec2 v_uv;
    float v_depth;
};
layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec2 _p2vs_location2;
smooth out vec3 _vs2fs_location0;
smooth out vec2 _vs2fs_location1;
smooth out float _vs2fs_location2;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    vec2 a_uv = _p2vs_location2;
    uint VertexID = uint(gl_VertexID);
    uint InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    vec3 v_normal = vec3(0.0);
    vec2 v_uv = vec2(0.0);
    float v_depth = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e8 = u_view_proj;
    vec4 p = (_e8 * vec4(a_pos, 1.0));
    v_normal = a_normal;
    v_uv = (a_uv + vec2((float(int(VertexID)) * 0.0), (float(int(InstanceID)) * 0.0)));
    v_depth = (p.z / p.w);
    gen_gl_Position = p;
    vec4 _e28 = gen_gl_Position;
    vec3 _e30 = v_normal;
    vec2 _e32 = v_uv;
    float _e34 = v_depth;
    gbuffer_vs_out _tmp_return = gbuffer_vs_out(_e28, _e30, _e32, _e34);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    _vs2fs_location1 = _tmp_return.v_uv;
    _vs2fs_location2 = _tmp_return.v_depth;
    return;
}

