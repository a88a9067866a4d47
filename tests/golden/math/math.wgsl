diagnostic(off, derivative_uniformity);

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
var<uniform> u_time: f32;
@group(0) @binding(1) 
var<uniform> u_frame: i32;

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
    let _e9 = u_frame;
    v_id = ((_e9 << u32(2i)) | 1i);
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e20 = gl_Position;
    let _e31 = v_uv;
    let _e33 = v_id;
    return math_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e31, _e33);
}

@fragment 
fn math_fs(@location(0) v_uv_1: vec2<f32>, @location(1) @interpolate(flat) v_id_1: i32) -> math_fs_out {
    var f_color: vec4<f32>;
    var p: vec2<f32>;
    var col: vec3<f32>;
    var sum: vec2<f32>;
    var i: i32;

    p = ((v_uv_1 * 2f) - vec2(1f));
    let _e10 = u_time;
    let _e11 = rotate(_e10);
    let _e13 = p;
    p = (_e11 * _e13);
    col = vec3(0f);
    let _e19 = col;
    let _e21 = p;
    let _e22 = abs(_e21);
    col = vec3<f32>(_e22.x, _e22.y, _e19.z);
    let _e30 = u_time;
    let _e37 = -(7.5f);
    col.z = ((_e30 - (1f * floor((_e30 / 1f)))) + ((_e37 - (2f * floor((_e37 / 2f)))) * 0f));
    sum = vec2(0f);
    i = 0i;
    loop {
        let _e52 = i;
        if !((_e52 < 4i)) {
            break;
        }
        let _e58 = i;
        let _e60 = sum;
        sum = (_e60 + OFFSETS[_e58]);
        continuing {
            let _e62 = i;
            i = (_e62 + 1i);
        }
    }
    let m = mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f));
    let _e73 = col;
    let _e76 = sum;
    col = ((m * _e73) + vec3<f32>(_e76, 0f));
    let bits = ((v_id_1 & 7i) ^ (v_id_1 >> u32(1i)));
    let _e88 = p.y;
    let _e91 = p.x;
    let angle = ((atan2(_e88, _e91) / TAU) + 0.5f);
    let _e101 = col.x;
    col.x = clamp(mix(_e101, angle, 0.5f), 0f, 1f);
    let _e112 = p;
    col.y = (smoothstep(0.2f, 0.8f, length(_e112)) * step(0.5f, f32((bits % 3i))));
    let _e123 = col;
    f_color = vec4<f32>(pow(_e123, vec3((1f / 2.2f))), 1f);
    let _e132 = f_color;
    return math_fs_out(_e132);
}
