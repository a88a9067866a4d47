#version 300 es

precision highp float;
precision highp int;

struct constant_builtins_fs_out {
    vec4 f_color;
};
const vec3 SUN_DIR = vec3(0.4061643, 0.49642307, 0.7671993);
const float HALF_ANGLE = 0.976296;
const ivec3 MASK = ivec3(16, 32, 48);
const uint SEED = 3205652812u;
const vec3 SKY = vec3(0.35500002, 0.39499998, 0.6375);
const float GOLDEN = 2.3999631;
const uint WHITE = 4294967295u;

in vec3 v_dir;
out vec4 f_color;

void main() {
    vec3 in_v_dir = v_dir;
    vec4 out_f_color = vec4(0.0);
    float d = dot(normalize(in_v_dir), SUN_DIR);
    float sun = smoothstep(HALF_ANGLE, 1.0, d);
    float bits = (float((((MASK.x | MASK.y) | MASK.z) & int((SEED & 63u)))) / 64.0);
    out_f_color = vec4(((SKY + vec3(sun)) + vec3(((bits * GOLDEN) * 0.0))), (float((WHITE >> 24u)) / 255.0));
    vec4 _e38 = out_f_color;
    constant_builtins_fs_out _tmp_return = constant_builtins_fs_out(_e38);
    f_color = _tmp_return.f_color;
    return;
}

