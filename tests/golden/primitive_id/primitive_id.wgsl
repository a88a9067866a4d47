diagnostic(off, derivative_uniformity);

enable primitive_index;

struct prim_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct prim_fs_out {
    @location(0) f_color: vec4<f32>,
}

@vertex 
fn prim_vs(@location(0) a_pos: vec2<f32>) -> prim_vs_out {
    var gl_Position: vec4<f32>;

    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e5 = gl_Position;
    return prim_vs_out(vec4<f32>(_e5.x, -(_e5.y), ((_e5.z + _e5.w) * 0.5f), _e5.w));
}

@fragment 
fn prim_fs(@builtin(primitive_index) PrimitiveID: u32) -> prim_fs_out {
    var f_color: vec4<f32>;

    let _e1 = i32(PrimitiveID);
    let k = (_e1 % 8i);
    f_color = vec4<f32>((f32(k) / 7f), f32((_e1 & 1i)), 0f, 1f);
    let _e14 = f_color;
    return prim_fs_out(_e14);
}
