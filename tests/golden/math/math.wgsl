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
    let _e10 = uniforms.u_frame;
    v_id = ((_e10 << u32(2i)) | 1i);
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e21 = gl_Position;
    let _e32 = v_uv;
    let _e34 = v_id;
    return math_vs_out(vec4<f32>(_e21.x, -(_e21.y), ((_e21.z + _e21.w) * 0.5f), _e21.w), _e32, _e34);
}

@fragment 
fn math_fs(@location(0) v_uv_1: vec2<f32>, @location(1) @interpolate(flat) v_id_1: i32) -> math_fs_out {
    var f_color: vec4<f32>;
    var p: vec2<f32>;
    var col: vec3<f32>;
    var sum: vec2<f32>;
    var i: i32;

    p = ((v_uv_1 * 2f) - vec2(1f));
    let _e11 = uniforms.u_time;
    let _e12 = rotate(_e11);
    let _e14 = p;
    p = (_e12 * _e14);
    col = vec3(0f);
    let _e20 = col;
    let _e22 = p;
    let _e23 = abs(_e22);
    col = vec3<f32>(_e23.x, _e23.y, _e20.z);
    let _e32 = uniforms.u_time;
    let _e39 = -(7.5f);
    col.z = ((_e32 - (1f * floor((_e32 / 1f)))) + ((_e39 - (2f * floor((_e39 / 2f)))) * 0f));
    sum = vec2(0f);
    i = 0i;
    loop {
        let _e54 = i;
        if !((_e54 < 4i)) {
            break;
        }
        let _e60 = i;
        let _e62 = sum;
        sum = (_e62 + OFFSETS[_e60]);
        continuing {
            let _e64 = i;
            i = (_e64 + 1i);
        }
    }
    let m = mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f));
    let _e75 = col;
    let _e78 = sum;
    col = ((m * _e75) + vec3<f32>(_e78, 0f));
    let bits = ((v_id_1 & 7i) ^ (v_id_1 >> u32(1i)));
    let _e90 = p.y;
    let _e93 = p.x;
    let angle = ((atan2(_e90, _e93) / TAU) + 0.5f);
    let _e103 = col.x;
    col.x = clamp(mix(_e103, angle, 0.5f), 0f, 1f);
    let _e114 = p;
    col.y = (smoothstep(0.2f, 0.8f, length(_e114)) * step(0.5f, f32((bits % 3i))));
    let _e125 = col;
    f_color = vec4<f32>(pow(_e125, vec3((1f / 2.2f))), 1f);
    let _e134 = f_color;
    return math_fs_out(_e134);
}
