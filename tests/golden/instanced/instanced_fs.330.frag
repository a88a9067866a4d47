#version 330 core
struct instanced_fs_out {
    vec4 f_color;
};
vec4 v_color = vec4(0.0);

vec3 v_normal = vec3(0.0);

vec3 v_bary = vec3(0.0);

int v_instance = 0;

vec4 f_color = vec4(0.0);

smooth in vec4 _vs2fs_location0;
smooth in vec3 _vs2fs_location1;
smooth in vec3 _vs2fs_location2;
flat in int _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

void main() {
    vec4 in_v_color = _vs2fs_location0;
    vec3 in_v_normal = _vs2fs_location1;
    vec3 in_v_bary = _vs2fs_location2;
    int in_v_instance = _vs2fs_location3;
    v_color = in_v_color;
    v_normal = in_v_normal;
    v_bary = in_v_bary;
    v_instance = in_v_instance;
    vec3 _e9 = v_normal;
    float light = ((max(dot(normalize(_e9), normalize(vec3(0.3, 1.0, 0.5))), 0.0) * 0.8) + 0.2);
    float _e25 = v_bary.x;
    float _e28 = v_bary.y;
    float _e32 = v_bary.z;
    float edge = min(min(_e25, _e28), _e32);
    float _e36 = fwidth(edge);
    float wire = (1.0 - smoothstep(0.0, (_e36 * 1.5), edge));
    int _e42 = v_instance;
    float stripe = (((_e42 & 1) == 0) ? 1.0 : 0.85);
    vec4 _e52 = v_color;
    float _e62 = v_color.w;
    f_color = vec4(mix(((_e52.xyz * light) * stripe), vec3(0.0), vec3(wire)), _e62);
    vec4 _e65 = f_color;
    instanced_fs_out _tmp_return = instanced_fs_out(_e65);
    _fs2p_location0 = _tmp_return.f_color;
    return;
}

