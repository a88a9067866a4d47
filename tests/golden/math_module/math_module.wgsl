diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_time: f32,
    u_seed: u32,
}

struct math_module_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_pos: vec2<f32>,
}

struct math_module_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn falloff(p: vec3<f32>, light: vec3<f32>) -> f32 {
    let _e2 = (p - light);
    let _e8 = normalize(light);
    return (min((1f / dot(_e2, _e2)), 4f) * dot(_e8, _e8));
}

@vertex 
fn math_module_vs(@location(0) a_pos: vec2<f32>) -> math_module_vs_out {
    var v_pos: vec2<f32>;
    var gl_Position: vec4<f32>;
    var s: f32;
    var c: f32;

    s = f32();
    c = f32();
    let _e6 = uniforms.u_time;
    let sincos_x = ((_e6 * 2f) * 3.1415927f);
    s = sin(sincos_x);
    c = cos(sincos_x);
    let _e14 = c;
    let _e15 = s;
    let _e17 = s;
    let _e19 = c;
    v_pos = (mat2x2<f32>(vec2<f32>(_e14, _e15), vec2<f32>(-(_e17), _e19)) * a_pos);
    gl_Position = vec4<f32>(((a_pos * 0.9f) + vec2(0.05f)), 0f, 1f);
    let _e32 = gl_Position;
    let _e42 = v_pos;
    return math_module_vs_out(vec4<f32>(_e32.x, -(_e32.y), ((_e32.z + _e32.w) * 0.5f), _e32.w), _e42);
}

@fragment 
fn math_module_fs(@location(0) v_pos_1: vec2<f32>) -> math_module_fs_out {
    var f_color: vec4<f32>;

    let cell = vec2<i32>(floor((v_pos_1 * 8f)));
    let _e7 = uniforms.u_seed;
    let _e8 = bitcast<vec2<u32>>(cell);
    let _e16 = (((_e8.x + (198491317u * _e8.y)) * 1759714724u) + _e7);
    let _e21 = ((_e16 ^ (_e16 >> 8u)) + 3039394381u);
    let _e25 = ((_e21 ^ (_e21 << 8u)) * 458671337u);
    let grain = (f32(((_e25 ^ (_e25 >> 8u)) & 255u)) / 255f);
    let ring = fract(((1f / length(vec2<f32>(v_pos_1.x, 1f))) + (1f / (1f + dot(v_pos_1, v_pos_1)))));
    let steps = f32(((i32(ceil((ring * 4f))) + i32(round(grain))) - i32(trunc(-(1.5f)))));
    let _e58 = (u32(cell.x) * 1759714724u);
    let _e61 = ((_e58 ^ (_e58 >> 8u)) + 3039394381u);
    let _e64 = ((_e61 ^ (_e61 << 8u)) * 458671337u);
    let hash = (f32(((_e64 ^ (_e64 >> 8u)) >> 24u)) / 255f);
    let p_1 = vec3<f32>(v_pos_1, 0f);
    let _e74 = falloff(p_1, vec3<f32>(0f, 0f, 1f));
    let _e76 = (p_1 - vec3(0f));
    let lit = (_e74 * saturate(dot(_e76, _e76)));
    let m = (mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f)) * vec3<f32>(grain, ring, hash));
    f_color = vec4<f32>(((m * vec3(lit)) + vec3((steps * 0.00000011920929f))), 1f);
    let _e94 = f_color;
    return math_module_fs_out(_e94);
}
