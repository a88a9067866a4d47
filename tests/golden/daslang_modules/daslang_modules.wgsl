diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_mvp: mat4x4<f32>,
    u_lift: f32,
}

struct daslang_modules_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct daslang_modules_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var u_tex: texture_2d<f32>;
@group(0) @binding(1) 
var u_tex_sampler: sampler;
@group(0) @binding(2) 
var<uniform> uniforms: Uniforms;

fn grade(c: vec3<f32>, lift: f32, gain: f32) -> vec3<f32> {
    return pow(max(((c * gain) + vec3(lift)), vec3(0f)), vec3((1f / 2.2f)));
}

@vertex 
fn daslang_modules_vs(@location(0) a_pos: vec3<f32>) -> daslang_modules_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos.xy * 0.5f) + vec2(0.5f));
    let _e10 = uniforms.u_mvp;
    gl_Position = (_e10 * vec4<f32>(a_pos, 1f));
    let _e14 = gl_Position;
    let _e23 = v_uv;
    return daslang_modules_vs_out(vec4<f32>(_e14.x, -(_e14.y), ((_e14.z + _e14.w) * 0.5f), _e14.w), _e23);
}

@fragment 
fn daslang_modules_fs(@location(0) v_uv_1: vec2<f32>) -> daslang_modules_fs_out {
    var f_color: vec4<f32>;

    let _e3 = textureSample(u_tex, u_tex_sampler, v_uv_1);
    let c_1 = _e3.xyz;
    let _e6 = fwidth(v_uv_1.x);
    let _e8 = dpdx(v_uv_1.y);
    let edge = (_e6 + abs(_e8));
    let _e13 = uniforms.u_lift;
    let packed = pack2x16float(vec2<f32>(edge, _e13));
    let back = unpack2x16float(packed);
    let _e25 = grade(fract((c_1 * 4f)), back.y, (1f + back.x));
    f_color = vec4<f32>(_e25, 1f);
    let _e27 = f_color;
    return daslang_modules_fs_out(_e27);
}
