#version 330 core
struct shadow_vs_out {
    vec4 gen_gl_Position;
};
struct shadow_fs_out {
    vec4 f_FragColor;
};
struct main_vs_out {
    vec4 gen_gl_Position;
    vec3 v_world_pos;
    vec3 v_world_normal;
    vec4 v_light_space;
};
struct main_fs_out {
    vec4 f_FragColor;
};
const float SHADOW_MAP_SIZE = 1024.0;
const int PCF_RADIUS = 1;

vec4 f_FragColor = vec4(0.0);

layout(location = 0) out vec4 _fs2p_location0;

vec3 floor_albedo(vec3 p) {
    float cell = (floor(((p.x * 0.5) + 100.0)) + floor(((p.z * 0.5) + 100.0)));
    float odd = (cell - (2.0 * floor((cell * 0.5))));
    float shade = ((odd < 0.5) ? 0.85 : 0.3);
    return (vec3(shade) * vec3(0.8, 0.82, 0.88));
}

void main() {
    f_FragColor = vec4(1.0);
    vec4 _e4 = f_FragColor;
    shadow_fs_out _tmp_return = shadow_fs_out(_e4);
    _fs2p_location0 = _tmp_return.f_FragColor;
    return;
}

