diagnostic(off, derivative_uniformity);

struct select_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) @interpolate(flat) v_cell: vec2<i32>,
}

struct select_fs_out {
    @location(0) f_color: vec4<f32>,
    @location(1) f_ids: vec4<u32>,
}

var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_cell: vec2<i32>;
var<private> f_color: vec4<f32>;
var<private> f_ids: vec4<u32>;
var<private> gl_Position: vec4<f32>;

@vertex 
fn select_vs(@location(0) in_a_pos: vec2<f32>) -> select_vs_out {
    a_pos = in_a_pos;
    let _e3 = a_pos;
    let inside = (abs(_e3) < vec2(0.5f));
    v_cell = select(vec2<i32>(-(1i), -(2i)), vec2<i32>(1i, 2i), inside);
    let _e20 = a_pos;
    v_uv = select(vec2(0f), _e20, inside);
    let _e26 = a_pos;
    gl_Position = vec4<f32>(_e26, 0f, 1f);
    let _e31 = gl_Position;
    let _e42 = v_uv;
    let _e44 = v_cell;
    return select_vs_out(vec4<f32>(_e31.x, -(_e31.y), ((_e31.z + _e31.w) * 0.5f), _e31.w), _e42, _e44);
}

@fragment 
fn select_fs(@location(0) in_v_uv: vec2<f32>, @location(1) @interpolate(flat) in_v_cell: vec2<i32>) -> select_fs_out {
    v_uv = in_v_uv;
    v_cell = in_v_cell;
    let _e5 = v_cell;
    let odd = ((_e5 & vec2(1i)) == vec2(1i));
    let _e15 = v_uv;
    let c = select(_e15, vec2(1f), odd);
    let _e18 = v_cell;
    let _e22 = v_cell;
    let n = select(_e22, (_e18 * 2i), odd);
    let _e25 = v_uv;
    let u = select(vec2<u32>(n), vec2<u32>(7u, 8u), (_e25 > vec2(0.25f)));
    let b = select(odd, !(odd), (n < vec2(0i)));
    let any_b = select(0f, 1f, any(b));
    let _e45 = v_uv.x;
    let pick = select(vec3(0i), vec3<i32>(n, 3i), (_e45 > 0.5f));
    f_color = vec4<f32>(c, f32(pick.z), any_b);
    f_ids = vec4<u32>(u, u32(n.x), u32(pick.y));
    let _e64 = f_color;
    let _e66 = f_ids;
    return select_fs_out(_e64, _e66);
}
