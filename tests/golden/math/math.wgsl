diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_time: f32,
    u_frame: i32,
}

struct math_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) @interpolate(flat) v_id: i32,
}

struct math_fs_out {
    @location(0) f_color: vec4<f32>,
}

const OFFSETS: array<vec2<f32>, 4> = array<vec2<f32>, 4>(vec2<f32>(-1f, 0f), vec2<f32>(1f, 0f), vec2<f32>(0f, -1f), vec2<f32>(0f, 1f));
const TAU: f32 = 6.2831855f;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn rotate(a: f32) -> mat2x2<f32> {
    let c = cos(a);
    let s = sin(a);
    return mat2x2<f32>(vec2<f32>(c, s), vec2<f32>(-(s), c));
}

@vertex 
fn math_vs(@location(0) a_pos: vec2<f32>) -> math_vs_out {
    var v_uv: vec2<f32>;
    var v_id: i32;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e9 = uniforms.u_frame;
    v_id = ((_e9 << u32(2i)) | 1i);
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e19 = gl_Position;
    let _e28 = v_uv;
    let _e29 = v_id;
    return math_vs_out(vec4<f32>(_e19.x, -(_e19.y), ((_e19.z + _e19.w) * 0.5f), _e19.w), _e28, _e29);
}

@fragment 
fn math_fs(@location(0) v_uv_1: vec2<f32>, @location(1) @interpolate(flat) v_id_1: i32) -> math_fs_out {
    var f_color: vec4<f32>;
    var p: vec2<f32>;
    var col: vec3<f32>;
    var sum: vec2<f32>;
    var i: i32;

    p = ((v_uv_1 * 2f) - vec2(1f));
    let _e10 = uniforms.u_time;
    let _e11 = rotate(_e10);
    let _e12 = p;
    p = (_e11 * _e12);
    col = vec3(0f);
    let _e17 = col;
    let _e18 = p;
    let _e19 = abs(_e18);
    col = vec3<f32>(_e19.x, _e19.y, _e17.z);
    let _e26 = uniforms.u_time;
    let _e32 = -(7.5f);
    col.z = ((_e26 - (1f * floor((_e26 / 1f)))) + ((_e32 - (2f * floor((_e32 / 2f)))) * 0f));
    sum = vec2(0f);
    i = 0i;
    loop {
        let _e44 = i;
        if !((_e44 < 4i)) {
            break;
        }
        let _e48 = i;
        let _e50 = sum;
        sum = (_e50 + OFFSETS[_e48]);
        continuing {
            let _e52 = i;
            i = (_e52 + 1i);
        }
    }
    let m = mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f));
    let _e59 = col;
    let _e61 = sum;
    col = ((m * _e59) + vec3<f32>(_e61, 0f));
    let bits = ((v_id_1 & 7i) ^ (v_id_1 >> u32(1i)));
    let _e70 = p.y;
    let _e72 = p.x;
    let angle = ((atan2(_e70, _e72) / TAU) + 0.5f);
    let _e80 = col.x;
    col.x = clamp(mix(_e80, angle, 0.5f), 0f, 1f);
    let _e86 = p;
    col.y = (smoothstep(0.2f, 0.8f, length(_e86)) * step(0.5f, f32((bits % 3i))));
    let _e95 = col;
    f_color = vec4<f32>(pow(_e95, vec3((1f / 2.2f))), 1f);
    let _e101 = f_color;
    return math_fs_out(_e101);
}
