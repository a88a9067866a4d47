diagnostic(off, derivative_uniformity);

struct constant_builtins_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_dir: vec3<f32>,
}

struct constant_builtins_fs_out {
    @location(0) f_color: vec4<f32>,
}

const TILT: mat3x3<f32> = mat3x3<f32>(vec3<f32>(0.5f, 0f, 0f), vec3<f32>(0f, 0.5f, 0f), vec3<f32>(0f, 0f, 0.5f));
const SUN_DIR: vec3<f32> = vec3<f32>(0.4061643f, 0.49642307f, 0.7671993f);
const HALF_ANGLE: f32 = 0.976296f;
const MASK: vec3<i32> = vec3<i32>(16i, 32i, 48i);
const SEED: u32 = 3205652812u;
const SKY: vec3<f32> = vec3<f32>(0.35500002f, 0.39499998f, 0.6375f);
const GOLDEN: f32 = 2.3999631f;
const WHITE: u32 = 4294967295u;

@vertex 
fn constant_builtins_vs(@location(0) a_pos: vec3<f32>) -> constant_builtins_vs_out {
    var v_dir: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_dir = (TILT * a_pos);
    gl_Position = vec4<f32>(a_pos, 1f);
    let _e7 = gl_Position;
    let _e17 = v_dir;
    return constant_builtins_vs_out(vec4<f32>(_e7.x, -(_e7.y), ((_e7.z + _e7.w) * 0.5f), _e7.w), _e17);
}

@fragment 
fn constant_builtins_fs(@location(0) v_dir_1: vec3<f32>) -> constant_builtins_fs_out {
    var f_color: vec4<f32>;

    let d = dot(normalize(v_dir_1), SUN_DIR);
    let sun = smoothstep(HALF_ANGLE, 1f, d);
    let bits = (f32((((MASK.x | MASK.y) | MASK.z) & i32((SEED & 63u)))) / 64f);
    f_color = vec4<f32>(((SKY + vec3(sun)) + vec3(((bits * GOLDEN) * 0f))), (f32((WHITE >> 24u)) / 255f));
    let _e38 = f_color;
    return constant_builtins_fs_out(_e38);
}
