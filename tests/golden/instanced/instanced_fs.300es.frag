#version 300 es

precision highp float;
precision highp int;

struct instanced_fs_out {
    vec4 f_color;
};
smooth in vec4 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
smooth in vec3 _vs2fs_location2;
flat in int _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec4 v_color = _vs2fs_location0;
    vec3 v_normal = _vs2fs_location1;
    vec3 v_bary = _vs2fs_location2;
    int v_instance = _vs2fs_location3;
    vec4 f_color = vec4(0.0);
    float light = ((max(dot(normalize(v_normal), normalize(vec3(0.3, 1.0, 0.5))), 0.0) * 0.8) + 0.2);
    float edge = min(min(v_bary.x, v_bary.y), v_bary.z);
    float _e24 = fwidth(edge);
    float wire = (1.0 - smoothstep(0.0, (_e24 * 1.5), edge));
    float stripe = (((v_instance & 1) == 0) ? 1.0 : 0.85);
    f_color = vec4(mix(((v_color.xyz * light) * stripe), vec3(0.0), vec3(wire)), v_color.w);
    vec4 _e47 = f_color;
    instanced_fs_out _tmp_return = instanced_fs_out(_e47);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

