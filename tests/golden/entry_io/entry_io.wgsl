diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_scale: f32,
}

struct entry_io_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_tint: vec3<f32>,
    @location(2) v_shade: f32,
}

struct entry_io_fs_out {
    @location(0) f_color: vec4<f32>,
    @location(1) f_extra: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
var<private> a_pos: vec3<f32>;
var<private> v_tint_1: vec3<f32>;
var<private> v_shade_1: f32;
var<private> gl_VertexID: i32;

fn set_tint(k: f32) {
    v_tint_1 = vec3<f32>(k, (1f - k), 0.5f);
    return;
}

fn lifted() -> vec3<f32> {
    let _e1 = a_pos;
    let _e4 = gl_VertexID;
    return (_e1 + vec3<f32>(0f, f32((_e4 % 2i)), 0f));
}

@vertex 
fn entry_io_vs(@location(0) in_a_pos: vec3<f32>, @location(1) a_uv: vec2<f32>, @builtin(vertex_index) in_VertexID: u32) -> entry_io_vs_out {
    var v_uv: vec2<f32>;
    var v_shade: f32;
    var gl_Position: vec4<f32>;

    a_pos = in_a_pos;
    gl_VertexID = i32(in_VertexID);
    v_uv.x = a_uv.x;
    v_uv.y = (1f - a_uv.y);
    let _e17 = uniforms.u_scale;
    let _e18 = v_uv;
    v_uv = (_e18 * _e17);
    let _e22 = v_uv.x;
    set_tint(_e22);
    let _e26 = a_pos.z;
    v_shade = _e26;
    let _e28 = lifted();
    let _e31 = uniforms.u_scale;
    gl_Position = vec4<f32>((_e28 * _e31), 1f);
    let _e36 = gl_VertexID;
    if (_e36 > 2i) {
        let _e43 = a_pos.x;
        let _e44 = gl_Position.w;
        gl_Position.w = (_e44 + _e43);
    }
    let _e47 = gl_Position;
    let _e58 = v_uv;
    let _e60 = v_tint_1;
    let _e62 = v_shade;
    return entry_io_vs_out(vec4<f32>(_e47.x, -(_e47.y), ((_e47.z + _e47.w) * 0.5f), _e47.w), _e58, _e60, _e62);
}

@fragment 
fn entry_io_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_tint: vec3<f32>, @location(2) in_v_shade: f32, @builtin(position) FragCoord: vec4<f32>) -> entry_io_fs_out {
    var f_color: vec4<f32>;
    var f_extra: vec4<f32>;

    v_shade_1 = in_v_shade;
    let _e7 = v_shade_1;
    v_shade_1 = clamp(_e7, 0f, 1f);
    if (FragCoord.x > 10f) {
        let _e16 = v_shade_1;
        v_shade_1 = (_e16 * 0.5f);
        f_extra = vec4<f32>(v_uv_1, 0f, 1f);
    }
    let _e24 = v_shade_1;
    f_color = vec4<f32>((v_tint * _e24), 1f);
    let _e29 = f_color;
    let _e31 = f_extra;
    return entry_io_fs_out(_e29, _e31);
}
