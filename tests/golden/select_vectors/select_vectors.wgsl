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

@vertex 
fn select_vs(@location(0) a_pos: vec2<f32>) -> select_vs_out {
    var v_uv: vec2<f32>;
    var v_cell: vec2<i32>;
    var gl_Position: vec4<f32>;

    let inside = (abs(a_pos) < vec2(0.5f));
    v_cell = select(vec2<i32>(-(1i), -(2i)), vec2<i32>(1i, 2i), inside);
    v_uv = select(vec2(0f), a_pos, inside);
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e20 = gl_Position;
    let _e29 = v_uv;
    let _e30 = v_cell;
    return select_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e29, _e30);
}

@fragment 
fn select_fs(@location(0) v_uv_1: vec2<f32>, @location(1) @interpolate(flat) v_cell_1: vec2<i32>) -> select_fs_out {
    var f_color: vec4<f32>;
    var f_ids: vec4<u32>;

    let odd = ((v_cell_1 & vec2(1i)) == vec2(1i));
    let c = select(v_uv_1, vec2(1f), odd);
    let n = select(v_cell_1, (v_cell_1 * 2i), odd);
    let u = select(vec2<u32>(n), vec2<u32>(7u, 8u), (v_uv_1 > vec2(0.25f)));
    let b = select(odd, !(odd), (n < vec2(0i)));
    let any_b = select(0f, 1f, any(b));
    let pick = select(vec3(0i), vec3<i32>(n, 3i), (v_uv_1.x > 0.5f));
    f_color = vec4<f32>(c, f32(pick.z), any_b);
    f_ids = vec4<u32>(u, u32(n.x), u32(pick.y));
    let _e46 = f_color;
    let _e47 = f_ids;
    return select_fs_out(_e46, _e47);
}
