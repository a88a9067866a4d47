#version 330 core
struct math_module_fs_out {
    vec4 f_color;
};
uniform uint u_seed;

in vec2 v_pos;
out vec4 f_color;

float falloff(vec3 p, vec3 light) {
    vec3 _e2 = (p - light);
    vec3 _e8 = normalize(light);
    return (min((1.0 / dot(_e2, _e2)), 4.0) * dot(_e8, _e8));
}

void main() {
    vec2 in_v_pos = v_pos;
    vec4 out_f_color = vec4(0.0);
    ivec2 cell = ivec2(floor((in_v_pos * 8.0)));
    uint _e6 = u_seed;
    uvec2 _e7 = uvec2(cell);
    uint _e15 = (((_e7.x + (198491317u * _e7.y)) * 1759714724u) + _e6);
    uint _e20 = ((_e15 ^ (_e15 >> 8u)) + 3039394381u);
    uint _e24 = ((_e20 ^ (_e20 << 8u)) * 458671337u);
    float grain = (float(((_e24 ^ (_e24 >> 8u)) & 255u)) / 255.0);
    float ring = fract(((1.0 / length(vec2(in_v_pos.x, 1.0))) + (1.0 / (1.0 + dot(in_v_pos, in_v_pos)))));
    float steps = float(((int(ceil((ring * 4.0))) + int(roundEven(grain))) - int(trunc(-(1.5)))));
    uint _e57 = (uint(cell.x) * 1759714724u);
    uint _e60 = ((_e57 ^ (_e57 >> 8u)) + 3039394381u);
    uint _e63 = ((_e60 ^ (_e60 << 8u)) * 458671337u);
    float hash = (float(((_e63 ^ (_e63 >> 8u)) >> 24u)) / 255.0);
    vec3 p_1 = vec3(in_v_pos, 0.0);
    float _e73 = falloff(p_1, vec3(0.0, 0.0, 1.0));
    vec3 _e75 = (p_1 - vec3(0.0));
    float lit = (_e73 * clamp(dot(_e75, _e75), 0.0, 1.0));
    vec3 m = (mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0)) * vec3(grain, ring, hash));
    out_f_color = vec4(((m * vec3(lit)) + vec3((steps * 1.1920929e-7))), 1.0);
    vec4 _e93 = out_f_color;
    math_module_fs_out _tmp_return = math_module_fs_out(_e93);
    f_color = _tmp_return.f_color;
    return;
}

