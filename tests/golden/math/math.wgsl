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
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_id: i32;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn rotate(a: f32) -> mat2x2<f32> {
    let c = cos(a);
    let s = sin(a);
    return mat2x2<f32>(vec2<f32>(c, s), vec2<f32>(-(s), c));
}

@vertex 
fn math_vs(@location(0) in_a_pos: vec2<f32>) -> math_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4 * 0.5f) + vec2(0.5f));
    let _e12 = u_frame;
    v_id = ((_e12 << u32(2i)) | 1i);
    let _e20 = a_pos;
    gl_Position = vec4<f32>(_e20, 0f, 1f);
    let _e25 = gl_Position;
    let _e36 = v_uv;
    let _e38 = v_id;
    return math_vs_out(vec4<f32>(_e25.x, -(_e25.y), ((_e25.z + _e25.w) * 0.5f), _e25.w), _e36, _e38);
}

@fragment 
fn math_fs(@location(0) in_v_uv: vec2<f32>, @location(1) @interpolate(flat) in_v_id: i32) -> math_fs_out {
    var p: vec2<f32>;
    var col: vec3<f32>;
    var sum: vec2<f32>;
    var i: i32;

    v_uv = in_v_uv;
    v_id = in_v_id;
    let _e6 = v_uv;
    p = ((_e6 * 2f) - vec2(1f));
    let _e14 = u_time;
    let _e15 = rotate(_e14);
    let _e17 = p;
    p = (_e15 * _e17);
    col = vec3(0f);
    let _e23 = col;
    let _e25 = p;
    let _e26 = abs(_e25);
    col = vec3<f32>(_e26.x, _e26.y, _e23.z);
    let _e34 = u_time;
    let _e41 = -(7.5f);
    col.z = ((_e34 - (1f * floor((_e34 / 1f)))) + ((_e41 - (2f * floor((_e41 / 2f)))) * 0f));
    sum = vec2(0f);
    i = 0i;
    loop {
        let _e56 = i;
        if !((_e56 < 4i)) {
            break;
        }
        let _e62 = i;
        let _e64 = sum;
        sum = (_e64 + OFFSETS[_e62]);
        continuing {
            let _e66 = i;
            i = (_e66 + 1i);
        }
    }
    let m = mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f));
    let _e77 = col;
    let _e80 = sum;
    col = ((m * _e77) + vec3<f32>(_e80, 0f));
    let _e85 = v_id;
    let _e89 = v_id;
    let bits = ((_e85 & 7i) ^ (_e89 >> u32(1i)));
    let _e96 = p.y;
    let _e99 = p.x;
    let angle = ((atan2(_e96, _e99) / TAU) + 0.5f);
    let _e109 = col.x;
    col.x = clamp(mix(_e109, angle, 0.5f), 0f, 1f);
    let _e120 = p;
    col.y = (smoothstep(0.2f, 0.8f, length(_e120)) * step(0.5f, f32((bits % 3i))));
    let _e131 = col;
    f_color = vec4<f32>(pow(_e131, vec3((1f / 2.2f))), 1f);
    let _e140 = f_color;
    return math_fs_out(_e140);
}
