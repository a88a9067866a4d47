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

uniform mat4x4 u_view_proj;

uniform Instance u_instances[64];

uniform float u_time;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec4 v_color;
out vec3 v_normal;
out vec3 v_bary;
flat out int v_instance;

vec3 spin(vec3 p, float angle) {
    float c = cos(angle);
    float s = sin(angle);
    return vec3(((c * p.x) + (s * p.z)), p.y, ((-(s) * p.x) + (c * p.z)));
}

void main() {
    vec3 in_a_position = a_position;
    vec3 in_a_normal = a_normal;
    uint InstanceID = (uint(gl_InstanceID) + naga_vs_first_instance);
    uint VertexID = uint(gl_VertexID);
    vec4 out_v_color = vec4(0.0);
    vec3 out_v_normal = vec3(0.0);
    vec3 out_v_bary = vec3(0.0);
    int out_v_instance = 0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e3 = int(InstanceID);
    int _e5 = int(VertexID);
    Instance inst = u_instances[(_e3 - (MAX_INSTANCES * (_e3 / MAX_INSTANCES)))];
    float _e14 = u_time;
    float angle_1 = (_e14 + (float(_e3) * 0.37));
    vec3 _e19 = spin(in_a_position, angle_1);
    vec3 p_1 = ((_e19 * inst.offset_scale.w) + inst.offset_scale.xyz);
    vec3 _e27 = spin(in_a_normal, angle_1);
    out_v_normal = _e27;
    out_v_color = inst.color;
    int corner = (_e5 - (3 * (_e5 / 3)));
    out_v_bary = vec3(((corner == 0) ? 1.0 : 0.0), ((corner == 1) ? 1.0 : 0.0), ((corner == 2) ? 1.0 : 0.0));
    out_v_instance = _e3;
    mat4x4 _e50 = u_view_proj;
    gen_gl_Position = (_e50 * vec4(p_1, 1.0));
    vec4 _e53 = gen_gl_Position;
    vec4 _e54 = out_v_color;
    vec3 _e55 = out_v_normal;
    vec3 _e56 = out_v_bary;
    int _e57 = out_v_instance;
    instanced_vs_out _tmp_return = instanced_vs_out(_e53, _e54, _e55, _e56, _e57);
    gl_Position = _tmp_return.gen_gl_Position;
    v_color = _tmp_return.v_color;
    v_normal = _tmp_return.v_normal;
    v_bary = _tmp_return.v_bary;
    v_instance = _tmp_return.v_instance;
    return;
}

