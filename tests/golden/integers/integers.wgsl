diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_seed: u32,
}

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
var<uniform> uniforms: Uniforms;

fn hash(x: u32) -> u32 {
    var h: u32;

    h = (x ^ (x >> 16u));
    let _e6 = h;
    h = (_e6 * 2146121005u);
    let _e8 = h;
    let _e12 = h;
    h = (_e12 ^ (_e8 >> u32(15i)));
    let _e14 = h;
    let _e18 = h;
    h = ((_e14 << u32(3i)) | (_e18 >> 29u));
    let _e22 = h;
    return _e22;
}

@vertex 
fn int_vs(@location(0) a_pos: vec2<f32>, @builtin(vertex_index) VertexID: u32) -> int_vs_out {
    var v_cell: vec2<i32>;
    var v_hash: u32;
    var gl_Position: vec4<f32>;

    let cell = vec2<i32>(floor((a_pos * 8f)));
    v_cell = ((cell % vec2(3i)) * (cell / vec2<i32>(2i, -(2i))));
    let _e20 = uniforms.u_seed;
    let _e22 = hash((u32(i32(VertexID)) + _e20));
    v_hash = _e22;
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e27 = gl_Position;
    let _e37 = v_cell;
    let _e38 = v_hash;
    return int_vs_out(vec4<f32>(_e27.x, -(_e27.y), ((_e27.z + _e27.w) * 0.5f), _e27.w), _e37, _e38);
}

@fragment 
fn int_fs(@location(0) @interpolate(flat) v_cell_1: vec2<i32>, @location(1) @interpolate(flat) v_hash_1: u32) -> int_fs_out {
    var f_color: vec4<f32>;
    var bits: vec2<u32>;

    let masked = ((v_cell_1 & vec2(255i)) | (vec2(1i) << vec2<u32>(vec2<i32>(2i, 3i))));
    let flipped = (~(masked) ^ vec2<i32>(NEG_MOD, NEG_DIV));
    bits = (vec2<u32>(flipped) >> vec2<u32>(1u, 2u));
    let _e26 = bits;
    bits = (_e26 % vec2(7u));
    let f = (bitcast<f32>(1065353216i) + bitcast<f32>(bitcast<u32>(0.5f)));
    let _e35 = bits.x;
    let _e37 = bits.y;
    let k = ((f32(((_e35 + _e37) + (v_hash_1 & WRAP))) + f32(TRUNC)) + FMOD);
    f_color = vec4<f32>(fract((k * 0.001f)), f, f32((i32((v_hash_1 % 5u)) - 2i)), 1f);
    let _e59 = f_color;
    return int_fs_out(_e59);
}
