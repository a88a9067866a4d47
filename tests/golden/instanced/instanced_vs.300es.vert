#version 300 es

precision highp float;
precision highp int;

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
    vec3 a_position = _p2vs_location0;
    vec3 a_normal = _p2vs_location1;
    uint InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    uint VertexID = uint(gl_VertexID);
    vec4 v_color = vec4(0.0);
    vec3 v_normal = vec3(0.0);
    vec3 v_bary = vec3(0.0);
    int v_instance = 0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e3 = int(InstanceID);
    int _e5 = int(VertexID);
    Instance inst = u_instances[(_e3 - (MAX_INSTANCES * (_e3 / MAX_INSTANCES)))];
    float _e14 = u_time;
    float angle_1 = (_e14 + (float(_e3) * 0.37));
    vec3 _e19 = spin(a_position, angle_1);
    vec3 p_1 = ((_e19 * inst.offset_scale.w) + inst.offset_scale.xyz);
    vec3 _e27 = spin(a_normal, angle_1);
    v_normal = _e27;
    v_color = inst.color;
    int corner = (_e5 - (3 * (_e5 / 3)));
    v_bary = vec3(((corner == 0) ? 1.0 : 0.0), ((corner == 1) ? 1.0 : 0.0), ((corner == 2) ? 1.0 : 0.0));
    v_instance = _e3;
    mat4x4 _e54 = u_view_proj;
    gen_gl_Position = (_e54 * vec4(p_1, 1.0));
    vec4 _e59 = gen_gl_Position;
    vec4 _e61 = v_color;
    vec3 _e63 = v_normal;
    vec3 _e65 = v_bary;
    int _e67 = v_instance;
    instanced_vs_out _tmp_return = instanced_vs_out(_e59, _e61, _e63, _e65, _e67);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_color;
    _vs2fs_location1 = _tmp_return.v_normal;
    _vs2fs_location2 = _tmp_return.v_bary;
    _vs2fs_location3 = _tmp_return.v_instance;
    return;
}

