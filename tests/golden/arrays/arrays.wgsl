diagnostic(off, derivative_uniformity);

struct arrays_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) @interpolate(flat) v_id: i32,
}

struct arrays_fs_out {
    @location(0) f_color: vec4<f32>,
}

const RING: array<i32, 4> = array<i32, 4>(3i, 1i, 4i, 1i);
const COLORS: array<vec3<f32>, 3> = array<vec3<f32>, 3>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f));
const WEIGHTS: array<f32, 5> = array<f32, 5>(0.227027f, 0.1945946f, 0.1216216f, 0.054054f, 0.016216f);

@group(0) @binding(0) 
var<uniform> u_count: i32;
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_id: i32;
var<private> f_color: vec4<f32>;
var<private> gl_VertexID: i32;
var<private> gl_Position: vec4<f32>;

fn sum_first(n: i32) -> f32 {
    var acc: array<f32, 5>;
    var i: i32;
    var s: f32;
    var i_1: i32;

    acc = array<f32, 5>();
    i = 0i;
    loop {
        let _e6 = i;
        if !((_e6 < 5i)) {
            break;
        }
        let _e11 = i;
        let _e15 = i;
        let _e18 = i;
        acc[_e11] = (WEIGHTS[_e15] * f32((_e18 + 1i)));
        continuing {
            let _e23 = i;
            i = (_e23 + 1i);
        }
    }
    s = 0f;
    i_1 = 0i;
    loop {
        let _e32 = i_1;
        if !((_e32 < min(n, 5i))) {
            break;
        }
        let _e38 = i_1;
        let _e40 = acc[_e38];
        let _e41 = s;
        s = (_e41 + _e40);
        continuing {
            let _e43 = i_1;
            i_1 = (_e43 + 1i);
        }
    }
    let _e47 = s;
    return _e47;
}

@vertex 
fn arrays_vs(@location(0) in_a_pos: vec2<f32>, @builtin(vertex_index) in_VertexID: u32) -> arrays_vs_out {
    a_pos = in_a_pos;
    gl_VertexID = i32(in_VertexID);
    let _e7 = a_pos;
    v_uv = ((_e7 * 0.5f) + vec2(0.5f));
    let _e16 = gl_VertexID;
    v_id = RING[(_e16 % 4i)];
    let _e22 = a_pos;
    gl_Position = vec4<f32>(_e22, 0f, 1f);
    let _e27 = gl_Position;
    let _e38 = v_uv;
    let _e40 = v_id;
    return arrays_vs_out(vec4<f32>(_e27.x, -(_e27.y), ((_e27.z + _e27.w) * 0.5f), _e27.w), _e38, _e40);
}

@fragment 
fn arrays_fs(@location(1) @interpolate(flat) in_v_id: i32) -> arrays_fs_out {
    var local: mat3x3<f32>;
    var grid: array<vec2<i32>, 2>;
    var m: mat2x2<f32>;

    v_id = in_v_id;
    let basis = mat3x3<f32>(COLORS[0], COLORS[1], COLORS[2]);
    let _e10 = v_id;
    local = basis;
    let col = local[(_e10 % 3i)];
    grid = array<vec2<i32>, 2>();
    let _e20 = v_id;
    let _e25 = v_id;
    let _e27 = v_id;
    grid[(_e20 & 1i)] = vec2<i32>(_e25, -(_e27));
    let g = grid[1];
    m = mat2x2<f32>(vec2<f32>(1f, 0f), vec2<f32>(0f, 1f));
    let _e41 = u_count;
    m[(_e41 & 1i)] = vec2(0.5f);
    let _e49 = u_count;
    let _e50 = sum_first(_e49);
    let _e56 = m[1];
    f_color = vec4<f32>(((col * _e50) + vec3<f32>(f32(g.x), _e56)), 1f);
    let _e62 = f_color;
    return arrays_fs_out(_e62);
}
