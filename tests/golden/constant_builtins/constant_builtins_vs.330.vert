#version 330 core
struct constant_builtins_vs_out {
    vec4 gen_gl_Position;
    vec3 v_dir;
};
const mat3x3 TILT = mat3x3(vec3(0.5, 0.0, 0.0), vec3(0.0, 0.5, 0.0), vec3(0.0, 0.0, 0.5));

layout(location = 0) in vec3 _p2vs_location0;
smooth out vec3 _vs2fs_location0;

void main() {
    vec3 a_pos = _p2vs_location0;
    vec3 v_dir = vec3(0.0);
    vec4 gen_gl_Position = vec4(0.0);
    v_dir = (TILT * a_pos);
    gen_gl_Position = vec4(a_pos, 1.0);
    vec4 _e8 = gen_gl_Position;
    vec3 _e10 = v_dir;
    constant_builtins_vs_out _tmp_return = constant_builtins_vs_out(_e8, _e10);
    gl_Position = _tmp_return.gen_gl_Position;
    _vs2fs_location0 = _tmp_return.v_dir;
    return;
}

