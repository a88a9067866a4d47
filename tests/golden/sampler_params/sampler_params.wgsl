diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_texel: f32,
}

struct sampler_params_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_height: f32,
}

struct sampler_params_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var albedo: texture_2d<f32>;
@group(0) @binding(1) 
var albedo_sampler: sampler;
@group(0) @binding(2) 
var detail: texture_2d<f32>;
@group(0) @binding(3) 
var detail_sampler: sampler;
@group(0) @binding(4) 
var sun_shadow: texture_depth_2d;
@group(0) @binding(5) 
var sun_shadow_sampler: sampler_comparison;
@group(0) @binding(6) 
var cascades_0_: texture_depth_2d;
@group(0) @binding(7) 
var cascades_0_sampler: sampler_comparison;
@group(0) @binding(8) 
var cascades_1_: texture_depth_2d;
@group(0) @binding(9) 
var cascades_1_sampler: sampler_comparison;
@group(0) @binding(10) 
var<uniform> uniforms: Uniforms;

fn tap_detail_vertex(uv: vec2<f32>) -> vec4<f32> {
    let _e3 = textureSampleLevel(detail, detail_sampler, uv, 0.0);
    return _e3;
}

fn tap_albedo(uv_1: vec2<f32>) -> vec4<f32> {
    let _e3 = textureSample(albedo, albedo_sampler, uv_1);
    return _e3;
}

fn blur_albedo(uv_2: vec2<f32>) -> vec4<f32> {
    let _e3 = uniforms.u_texel;
    let _e7 = tap_albedo((uv_2 - vec2<f32>(_e3, 0f)));
    let _e9 = uniforms.u_texel;
    let _e12 = tap_albedo((uv_2 + vec2<f32>(_e9, 0f)));
    return ((_e7 + _e12) * 0.5f);
}

fn tap_detail(uv_3: vec2<f32>) -> vec4<f32> {
    let _e3 = textureSample(detail, detail_sampler, uv_3);
    return _e3;
}

fn blur_detail(uv_4: vec2<f32>) -> vec4<f32> {
    let _e3 = uniforms.u_texel;
    let _e7 = tap_detail((uv_4 - vec2<f32>(_e3, 0f)));
    let _e9 = uniforms.u_texel;
    let _e12 = tap_detail((uv_4 + vec2<f32>(_e9, 0f)));
    return ((_e7 + _e12) * 0.5f);
}

fn pcf_sun_shadow(uv_5: vec2<f32>, depth: f32) -> f32 {
    var lit: f32;
    var y: i32;
    var x: i32;

    lit = 0f;
    y = -(1i);
    loop {
        let _e8 = y;
        if !((_e8 < 2i)) {
            break;
        }
        x = -(1i);
        loop {
            let _e13 = x;
            if !((_e13 < 2i)) {
                break;
            }
            let _e16 = x;
            let _e18 = y;
            let _e23 = uniforms.u_texel;
            let _e28 = textureSampleCompare(sun_shadow, sun_shadow_sampler, (uv_5 + (vec2<f32>(f32(_e16), f32(_e18)) * _e23)), depth);
            let _e29 = lit;
            lit = (_e29 + _e28);
            continuing {
                let _e31 = x;
                x = (_e31 + 1i);
            }
        }
        continuing {
            let _e33 = y;
            y = (_e33 + 1i);
        }
    }
    let _e35 = lit;
    return (_e35 / 9f);
}

fn pcf_cascades_1_(uv_6: vec2<f32>, depth_1: f32) -> f32 {
    var lit_1: f32;
    var y_1: i32;
    var x_1: i32;

    lit_1 = 0f;
    y_1 = -(1i);
    loop {
        let _e8 = y_1;
        if !((_e8 < 2i)) {
            break;
        }
        x_1 = -(1i);
        loop {
            let _e13 = x_1;
            if !((_e13 < 2i)) {
                break;
            }
            let _e16 = x_1;
            let _e18 = y_1;
            let _e23 = uniforms.u_texel;
            let _e28 = textureSampleCompare(cascades_1_, cascades_1_sampler, (uv_6 + (vec2<f32>(f32(_e16), f32(_e18)) * _e23)), depth_1);
            let _e29 = lit_1;
            lit_1 = (_e29 + _e28);
            continuing {
                let _e31 = x_1;
                x_1 = (_e31 + 1i);
            }
        }
        continuing {
            let _e33 = y_1;
            y_1 = (_e33 + 1i);
        }
    }
    let _e35 = lit_1;
    return (_e35 / 9f);
}

@vertex 
fn sampler_params_vs(@location(0) a_pos: vec2<f32>) -> sampler_params_vs_out {
    var v_uv: vec2<f32>;
    var v_height: f32;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e7 = v_uv;
    let _e8 = tap_detail_vertex(_e7);
    v_height = _e8.x;
    let _e11 = v_height;
    gl_Position = vec4<f32>(a_pos, _e11, 1f);
    let _e14 = gl_Position;
    let _e23 = v_uv;
    let _e24 = v_height;
    return sampler_params_vs_out(vec4<f32>(_e14.x, -(_e14.y), ((_e14.z + _e14.w) * 0.5f), _e14.w), _e23, _e24);
}

@fragment 
fn sampler_params_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_height_1: f32) -> sampler_params_fs_out {
    var f_color: vec4<f32>;

    let _e2 = blur_albedo(v_uv_1);
    let _e7 = blur_detail((v_uv_1 * 4f));
    let base = ((_e2 * 0.75f) + (_e7 * 0.25f));
    let _e12 = pcf_sun_shadow(v_uv_1, 0.5f);
    let _e13 = pcf_cascades_1_(v_uv_1, v_height_1);
    let lit_2 = (_e12 * _e13);
    let _e18 = tap_detail(v_uv_1);
    f_color = vec4<f32>((base.xyz * lit_2), _e18.w);
    let _e21 = f_color;
    return sampler_params_fs_out(_e21);
}
