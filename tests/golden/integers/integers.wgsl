diagnostic(off, derivative_uniformity);

struct int_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) @interpolate(flat) v_cell: vec2<i32>,
    @location(1) @interpolate(flat) v_hash: u32,
}

struct int_fs_out {
    @location(0) f_color: vec4<f32>,
}

const NEG_MOD: i32 = -1i;
const NEG_DIV: i32 = -3i;
const WRAP: u32 = 4294967295u;
const TRUNC: i32 = -2i;
const FMOD: f32 = 0.5f;

@group(0) @binding(0) 
var<uniform> u_seed: u32;
var<private> a_pos: vec2<f32>;
var<private> v_cell: vec2<i32>;
var<private> v_hash: u32;
var<private> f_color: vec4<f32>;
var<private> gl_VertexID: i32;
var<private> gl_Position: vec4<f32>;

fn hash(x: u32) -> u32 {
    var h: u32;

    h = (x ^ (x >> 16u));
    let _e7 = h;
    h = (_e7 * 2146121005u);
    let _e11 = h;
    let _e15 = h;
    h = (_e15 ^ (_e11 >> u32(15i)));
    let _e19 = h;
    let _e24 = h;
    h = ((_e19 << u32(3i)) | (_e24 >> 29u));
    let _e29 = h;
    return _e29;
}

@vertex 
fn int_vs(@location(0) in_a_pos: vec2<f32>, @builtin(vertex_index) in_VertexID: u32) -> int_vs_out {
    a_pos = in_a_pos;
    gl_VertexID = i32(in_VertexID);
    let _e6 = a_pos;
    let cell = vec2<i32>(floor((_e6 * 8f)));
    v_cell = ((cell % vec2(3i)) * (cell / vec2<i32>(2i, -(2i))));
    let _e23 = gl_VertexID;
    let _e26 = u_seed;
    let _e28 = hash((u32(_e23) + _e26));
    v_hash = _e28;
    let _e31 = a_pos;
    gl_Position = vec4<f32>(_e31, 0f, 1f);
    let _e36 = gl_Position;
    let _e47 = v_cell;
    let _e49 = v_hash;
    return int_vs_out(vec4<f32>(_e36.x, -(_e36.y), ((_e36.z + _e36.w) * 0.5f), _e36.w), _e47, _e49);
}

@fragment 
fn int_fs(@location(0) @interpolate(flat) in_v_cell: vec2<i32>, @location(1) @interpolate(flat) in_v_hash: u32) -> int_fs_out {
    var bits: vec2<u32>;

    v_cell = in_v_cell;
    v_hash = in_v_hash;
    let _e5 = v_cell;
    let masked = ((_e5 & vec2(255i)) | (vec2(1i) << vec2<u32>(vec2<i32>(2i, 3i))));
    let flipped = (~(masked) ^ vec2<i32>(NEG_MOD, NEG_DIV));
    bits = (vec2<u32>(flipped) >> vec2<u32>(1u, 2u));
    let _e31 = bits;
    bits = (_e31 % vec2(7u));
    let f = (bitcast<f32>(1065353216i) + bitcast<f32>(bitcast<u32>(0.5f)));
    let _e41 = bits.x;
    let _e44 = bits.y;
    let _e47 = v_hash;
    let k = ((f32(((_e41 + _e44) + (_e47 & WRAP))) + f32(TRUNC)) + FMOD);
    let _e62 = v_hash;
    f_color = vec4<f32>(fract((k * 0.001f)), f, f32((i32((_e62 % 5u)) - 2i)), 1f);
    let _e72 = f_color;
    return int_fs_out(_e72);
}
