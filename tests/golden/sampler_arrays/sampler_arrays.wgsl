diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_pick: i32,
}

struct layers_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct layers_fs_out {
    @location(0) f_color: vec4<f32>,
}

const DETAIL: i32 = 2i;

@group(0) @binding(0) 
var layers_0_: texture_2d<f32>;
@group(0) @binding(1) 
var layers_0_sampler: sampler;
@group(0) @binding(2) 
var layers_1_: texture_2d<f32>;
@group(0) @binding(3) 
var layers_1_sampler: sampler;
@group(0) @binding(4) 
var layers_2_: texture_2d<f32>;
@group(0) @binding(5) 
var layers_2_sampler: sampler;
@group(0) @binding(6) 
var shadows_0_: texture_depth_2d;
@group(0) @binding(7) 
var shadows_0_sampler: sampler_comparison;
@group(0) @binding(8) 
var shadows_1_: texture_depth_2d;
@group(0) @binding(9) 
var shadows_1_sampler: sampler_comparison;
@group(0) @binding(10) 
var<uniform> uniforms: Uniforms;

fn layer(i_1: i32, uv: vec2<f32>) -> vec4<f32> {
    var texel_2: vec4<f32>;

    switch clamp(i_1, 0i, 2i) {
        case 0: {
            let _e7 = textureSample(layers_0_, layers_0_sampler, uv);
            texel_2 = _e7;
        }
        case 1: {
            let _e11 = textureSample(layers_1_, layers_1_sampler, uv);
            texel_2 = _e11;
        }
        default: {
            let _e14 = textureSample(layers_2_, layers_2_sampler, uv);
            texel_2 = _e14;
        }
    }
    let _e15 = texel_2;
    return _e15;
}

@vertex 
fn layers_vs(@location(0) a_pos: vec2<f32>) -> layers_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return layers_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn layers_fs(@location(0) v_uv_1: vec2<f32>) -> layers_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var texel: vec2<i32>;
    var lit: f32;
    var i: i32;
    var texel_1: f32;

    let _e4 = textureSample(layers_0_, layers_0_sampler, v_uv_1);
    c = (_e4 * 0.5f);
    let _e12 = textureSampleLevel(layers_2_, layers_2_sampler, (v_uv_1 * 4f), 0f);
    let _e13 = c;
    c = (_e13 + _e12);
    let _e17 = uniforms.u_pick;
    let _e18 = layer(_e17, v_uv_1);
    let _e19 = c;
    c = (_e19 + _e18);
    let _e23 = uniforms.u_pick;
    switch clamp((_e23 + 1i), 0i, 2i) {
        case 0: {
            let _e28 = textureDimensions(layers_0_, 0i);
            texel = vec2<i32>(_e28);
        }
        case 1: {
            let _e32 = textureDimensions(layers_1_, 0i);
            texel = vec2<i32>(_e32);
        }
        default: {
            let _e34 = textureDimensions(layers_2_, 0i);
            texel = vec2<i32>(_e34);
        }
    }
    let size = texel;
    lit = 0f;
    i = 0i;
    loop {
        let _e39 = i;
        if !((_e39 < 2i)) {
            break;
        }
        let _e42 = i;
        switch clamp(_e42, 0i, 1i) {
            case 0: {
                let _e46 = textureSampleCompare(shadows_0_, shadows_0_sampler, v_uv_1, 0.5f);
                texel_1 = _e46;
            }
            default: {
                let _e50 = textureSampleCompare(shadows_1_, shadows_1_sampler, v_uv_1, 0.5f);
                texel_1 = _e50;
            }
        }
        let _e51 = texel_1;
        let _e52 = lit;
        lit = (_e52 + _e51);
        continuing {
            let _e54 = i;
            i = (_e54 + 1i);
        }
    }
    let _e57 = c;
    let _e58 = lit;
    f_color = ((_e57 * _e58) + vec4((f32(size.x) * 0f)));
    let _e65 = f_color;
    return layers_fs_out(_e65);
}
