diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_count: i32,
}

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
var<uniform> uniforms: Uniforms;

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
        let _e9 = i;
        let _e12 = i;
        let _e14 = i;
        acc[_e9] = (WEIGHTS[_e12] * f32((_e14 + 1i)));
        continuing {
            let _e19 = i;
            i = (_e19 + 1i);
        }
    }
    s = 0f;
    i_1 = 0i;
    loop {
        let _e25 = i_1;
        if !((_e25 < min(n, 5i))) {
            break;
        }
        let _e28 = i_1;
        let _e30 = acc[_e28];
        let _e31 = s;
        s = (_e31 + _e30);
        continuing {
            let _e33 = i_1;
            i_1 = (_e33 + 1i);
        }
    }
    let _e35 = s;
    return _e35;
}

@vertex 
fn arrays_vs(@location(0) a_pos: vec2<f32>, @builtin(vertex_index) VertexID: u32) -> arrays_vs_out {
    var v_uv: vec2<f32>;
    var v_id: i32;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    v_id = RING[(i32(VertexID) % 4i)];
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e17 = gl_Position;
    let _e26 = v_uv;
    let _e27 = v_id;
    return arrays_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e26, _e27);
}

@fragment 
fn arrays_fs(@location(1) @interpolate(flat) v_id_1: i32) -> arrays_fs_out {
    var f_color: vec4<f32>;
    var local: mat3x3<f32>;
    var grid: array<vec2<i32>, 2>;
    var m: mat2x2<f32>;

    let basis = mat3x3<f32>(COLORS[0], COLORS[1], COLORS[2]);
    local = basis;
    let col = local[(v_id_1 % 3i)];
    grid = array<vec2<i32>, 2>();
    grid[(v_id_1 & 1i)] = vec2<i32>(v_id_1, -(v_id_1));
    let g = grid[1];
    m = mat2x2<f32>(vec2<f32>(1f, 0f), vec2<f32>(0f, 1f));
    let _e28 = uniforms.u_count;
    m[(_e28 & 1i)] = vec2(0.5f);
    let _e35 = uniforms.u_count;
    let _e36 = sum_first(_e35);
    let _e41 = m[1];
    f_color = vec4<f32>(((col * _e36) + vec3<f32>(f32(g.x), _e41)), 1f);
    let _e45 = f_color;
    return arrays_fs_out(_e45);
}
