#version 330 core
uniform uint naga_vs_first_instance;

struct Instance {
    vec4 offset_scale;
    vec4 color;
};
struct instanced_vs_out {
    vec4 gen_gl_Position;
    vec4 v_color;
    vec3 v_normal;
    vec3 v_bary;
    int v_instance;
};
const int MAX_INSTANCES = 64;

layout(std140) uniform u_view_proj_block { mat4x4 u_view_proj; };

layout(std140) uniform u_instances_block { Instance u_instances[64]; };

layout(std140) uniform u_time_block { float u_time; };

vec3 a_position = vec3(0.0);

vec3 a_normal = vec3(0.0);

vec4 v_color = vec4(0.0);

vec3 v_normal = vec3(0.0);

vec3 v_bary = vec3(0.0);

int v_instance = 0;

int gen_gl_InstanceID = 0;

int gen_gl_VertexID = 0;

vec4 gen_gl_Position = vec4(0.0);

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
smooth out vec4 _vs2fs_location0;
smooth out vec3 _vs2fs_location1;
smooth out vec3 _vs2fs_location2;
flat out int _vs2fs_location3;

vec3 spin(vec3 p, float angle) {
    float c = cos(angle);
    float s = sin(angle);
    return vec3(((c * p.x) + (s * p.z)), p.y, ((-(s) * p.x) + (c * p.z)));
}

void main() {
    vec3 in_a_position = _p2vs_location0;
    vec3 in_a_normal = _p2vs_location1;
    uint in_InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    uint in_VertexID = uint(gl_VertexID);
    a_position = in_a_position;
    a_normal = in_a_normal;
    gen_gl_InstanceID = int(in_InstanceID);
    gen_gl_VertexID = int(in_VertexID);
    int _e12 = gen_gl_InstanceID;
    Instance inst = u_instances[(_e12 - (MAX_INSTANCES * (_e12 / MAX_INSTANCES)))];
    float _e20 = u_time;
    int _e22 = gen_gl_InstanceID;
    float angle_1 = (_e20 + (float(_e22) * 0.37));
    vec3 _e28 = a_position;
    vec3 _e29 = spin(_e28, angle_1);
    vec3 p_1 = ((_e29 * inst.offset_scale.w) + inst.offset_scale.xyz);
    vec3 _e38 = a_normal;
    vec3 _e39 = spin(_e38, angle_1);
    v_normal = _e39;
    v_color = inst.color;
    int _e43 = gen_gl_VertexID;
    int corner = (_e43 - (3 * (_e43 / 3)));
    v_bary = vec3(((corner == 0) ? 1.0 : 0.0), ((corner == 1) ? 1.0 : 0.0), ((corner == 2) ? 1.0 : 0.0));
    int _e67 = gen_gl_InstanceID;
    v_instance = _e67;
    mat4x4 _e70 = u_view_proj;
    gen_gl_Position = (_e70 * vec4(p_1, 1.0));
    vec4 _e75 = gen_gl_Position;
    vec4 _e77 = v_color;
    vec3 _e79 = v_normal;
    vec3 _e81 = v_bary;
    int _e83 = v_instance;
    instanced_vs_out _tmp_return = instanced_vs_out(_e75, _e77, _e79, _e81, _e83);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_color;
    _vs2fs_location1 = _tmp_return.v_normal;
    _vs2fs_location2 = _tmp_return.v_bary;
    _vs2fs_location3 = _tmp_return.v_instance;
    return;
}

