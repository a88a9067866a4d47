diagnostic(off, derivative_uniformity);

enable f16;

struct Uniforms {
    u_exposure: f32,
}

struct half_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct half_fs_out {
    @location(0) f_color: vec4<f32>,
}

const WHITE_POINT: f16 = 4h;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn reinhard(c: vec3<f16>) -> vec3<f16> {
    let w2_ = (WHITE_POINT * WHITE_POINT);
    return ((c * (vec3(1h) + (c / vec3(w2_)))) / (vec3(1h) + c));
}

@vertex 
fn half_vs(@location(0) a_pos: vec2<f32>) -> half_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return half_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn half_fs(@location(0) v_uv_1: vec2<f32>) -> half_fs_out {
    var f_color: vec4<f32>;

    let _e5 = uniforms.u_exposure;
    let hdr = vec3<f16>((vec3<f32>(v_uv_1, 0.5f) * _e5));
    let _e8 = reinhard(hdr);
    f_color = vec4<f32>(vec3<f32>(_e8), f32(max(_e8.x, 0.25h)));
    let _e16 = f_color;
    return half_fs_out(_e16);
}
