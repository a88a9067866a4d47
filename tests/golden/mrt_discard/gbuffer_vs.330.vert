#version 330 core
uniform uint naga_vs_first_instance;

struct gbuffer_vs_out {
    vec4 gen_gl_Position;
    vec3 v_normal;
    vec2 v_uv;
    float v_depth;
};
layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

vec3 a_pos = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec2 a_uv = vec2(0.0);

vec3 v_normal = vec3(0.0);

vec2 v_uv = vec2(0.0);

float v_depth = 0.0;

int gen_gl_VertexID = 0;

int gen_gl_InstanceID = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec2 _p2vs_location2;
smooth out vec3 _vs2fs_location0;
smooth out vec2 _vs2fs_location1;
smooth out float _vs2fs_location2;

void main() {
    vec3 in_a_pos = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    vec2 in_a_uv = _p2vs_location2;
    uint in_VertexID = uint(gl_VertexID);
    uint in_InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    a_uv = in_a_uv;
    gen_gl_VertexID = int(in_VertexID);
    gen_gl_InstanceID = int(in_InstanceID);
    mat4x4 _e13 = u_view_proj;
    vec3 _e15 = a_pos;
    vec4 p = (_e13 * vec4(_e15, 1.0));
    vec3 _e21 = a_normal;
    v_normal = _e21;
    vec2 _e24 = a_uv;
    int _e26 = gen_gl_VertexID;
    int _e31 = gen_gl_InstanceID;
    v_uv = (_e24 + vec2((float(_e26) * 0.0), (float(_e31) * 0.0)));
    v_depth = (p.z / p.w);
    gen_gl_Position = p;
    vec4 _e43 = gen_gl_Position;
    vec3 _e45 = v_normal;
    vec2 _e47 = v_uv;
    float _e49 = v_depth;
    gbuffer_vs_out _tmp_return = gbuffer_vs_out(_e43, _e45, _e47, _e49);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_normal;
    _vs2fs_location1 = _tmp_return.v_uv;
    _vs2fs_location2 = _tmp_return.v_depth;
    return;
}

