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
    let _e15 = uniforms.u_scale;
    let _e16 = v_uv;
    v_uv = (_e16 * _e15);
    let _e19 = v_uv.x;
    set_tint(_e19);
    let _e22 = a_pos.z;
    v_shade = _e22;
    let _e24 = lifted();
    let _e26 = uniforms.u_scale;
    gl_Position = vec4<f32>((_e24 * _e26), 1f);
    let _e29 = gl_VertexID;
    if (_e29 > 2i) {
        let _e34 = a_pos.x;
        let _e35 = gl_Position.w;
        gl_Position.w = (_e35 + _e34);
    }
    let _e37 = gl_Position;
    let _e47 = v_uv;
    let _e49 = v_tint_1;
    let _e50 = v_shade;
    return entry_io_vs_out(vec4<f32>(_e37.x, -(_e37.y), ((_e37.z + _e37.w) * 0.5f), _e37.w), _e47, _e49, _e50);
}

@fragment 
fn entry_io_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_tint: vec3<f32>, @location(2) in_v_shade: f32, @builtin(position) FragCoord: vec4<f32>) -> entry_io_fs_out {
    var f_color: vec4<f32>;
    var f_extra: vec4<f32>;

    v_shade_1 = in_v_shade;
    let _e5 = v_shade_1;
    v_shade_1 = clamp(_e5, 0f, 1f);
    if (FragCoord.x > 10f) {
        let _e13 = v_shade_1;
        v_shade_1 = (_e13 * 0.5f);
        f_extra = vec4<f32>(v_uv_1, 0f, 1f);
    }
    let _e18 = v_shade_1;
    f_color = vec4<f32>((v_tint * _e18), 1f);
    let _e21 = f_color;
    let _e22 = f_extra;
    return entry_io_fs_out(_e21, _e22);
}
