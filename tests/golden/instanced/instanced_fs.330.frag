#version 330 core
struct instanced_fs_out {
    vec4 f_color;
};
in vec4 v_color;
in vec3 v_normal;
in vec3 v_bary;
flat in int v_instance;
out vec4 f_color;

void main() {
    vec4 in_v_color = v_color;
    vec3 in_v_normal = v_normal;
    vec3 in_v_bary = v_bary;
    int in_v_instance = v_instance;
    vec4 out_f_color = vec4(0.0);
    float light = ((max(dot(normalize(in_v_normal), normalize(vec3(0.3, 1.0, 0.5))), 0.0) * 0.8) + 0.2);
    float edge = min(min(in_v_bary.x, in_v_bary.y), in_v_bary.z);
    float _e22 = fwidth(edge);
    float wire = (1.0 - smoothstep(0.0, (_e22 * 1.5), edge));
    float stripe = (((in_v_instance & 1) == 0) ? 1.0 : 0.85);
    out_f_color = vec4(mix(((in_v_color.xyz * light) * stripe), vec3(0.0), vec3(wire)), in_v_color.w);
    vec4 _e42 = out_f_color;
    instanced_fs_out _tmp_return = instanced_fs_out(_e42);
    f_color = _tmp_return.f_color;
    return;
}

