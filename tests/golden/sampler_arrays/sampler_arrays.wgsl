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
            let _e15 = textureSample(layers_2_, layers_2_sampler, uv);
            texel_2 = _e15;
        }
    }
    let _e18 = texel_2;
    return _e18;
}

@vertex 
fn layers_vs(@location(0) a_pos: vec2<f32>) -> layers_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return layers_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
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
    let _e13 = textureSampleLevel(layers_2_, layers_2_sampler, (v_uv_1 * 4f), 0f);
    let _e14 = c;
    c = (_e14 + _e13);
    let _e19 = uniforms.u_pick;
    let _e20 = layer(_e19, v_uv_1);
    let _e21 = c;
    c = (_e21 + _e20);
    let _e26 = uniforms.u_pick;
    switch clamp((_e26 + 1i), 0i, 2i) {
        case 0: {
            let _e33 = textureDimensions(layers_0_, 0i);
            texel = vec2<i32>(_e33);
        }
        case 1: {
            let _e37 = textureDimensions(layers_1_, 0i);
            texel = vec2<i32>(_e37);
        }
        default: {
            let _e41 = textureDimensions(layers_2_, 0i);
            texel = vec2<i32>(_e41);
        }
    }
    let size = texel;
    lit = 0f;
    i = 0i;
    loop {
        let _e51 = i;
        if !((_e51 < 2i)) {
            break;
        }
        let _e57 = i;
        switch clamp(_e57, 0i, 1i) {
            case 0: {
                let _e63 = textureSampleCompare(shadows_0_, shadows_0_sampler, v_uv_1, 0.5f);
                texel_1 = _e63;
            }
            default: {
                let _e67 = textureSampleCompare(shadows_1_, shadows_1_sampler, v_uv_1, 0.5f);
                texel_1 = _e67;
            }
        }
        let _e70 = texel_1;
        let _e71 = lit;
        lit = (_e71 + _e70);
        continuing {
            let _e73 = i;
            i = (_e73 + 1i);
        }
    }
    let _e78 = c;
    let _e80 = lit;
    f_color = ((_e78 * _e80) + vec4((f32(size.x) * 0f)));
    let _e89 = f_color;
    return layers_fs_out(_e89);
}
