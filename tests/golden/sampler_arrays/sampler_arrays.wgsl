diagnostic(off, derivative_uniformity);

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
var<uniform> u_pick: i32;
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

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
fn layers_vs(@location(0) in_a_pos: vec2<f32>) -> layers_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4 * 0.5f) + vec2(0.5f));
    let _e12 = a_pos;
    gl_Position = vec4<f32>(_e12, 0f, 1f);
    let _e17 = gl_Position;
    let _e28 = v_uv;
    return layers_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e28);
}

@fragment 
fn layers_fs(@location(0) in_v_uv: vec2<f32>) -> layers_fs_out {
    var c: vec4<f32>;
    var texel: vec2<i32>;
    var lit: f32;
    var i: i32;
    var texel_1: f32;

    v_uv = in_v_uv;
    let _e4 = v_uv;
    let _e7 = textureSample(layers_0_, layers_0_sampler, _e4);
    c = (_e7 * 0.5f);
    let _e12 = v_uv;
    let _e18 = textureSampleLevel(layers_2_, layers_2_sampler, (_e12 * 4f), 0f);
    let _e19 = c;
    c = (_e19 + _e18);
    let _e23 = u_pick;
    let _e25 = v_uv;
    let _e26 = layer(_e23, _e25);
    let _e27 = c;
    c = (_e27 + _e26);
    let _e31 = u_pick;
    switch clamp((_e31 + 1i), 0i, 2i) {
        case 0: {
            let _e38 = textureDimensions(layers_0_, 0i);
            texel = vec2<i32>(_e38);
        }
        case 1: {
            let _e42 = textureDimensions(layers_1_, 0i);
            texel = vec2<i32>(_e42);
        }
        default: {
            let _e46 = textureDimensions(layers_2_, 0i);
            texel = vec2<i32>(_e46);
        }
    }
    let size = texel;
    lit = 0f;
    i = 0i;
    loop {
        let _e56 = i;
        if !((_e56 < 2i)) {
            break;
        }
        let _e61 = v_uv;
        let _e64 = i;
        switch clamp(_e64, 0i, 1i) {
            case 0: {
                let _e70 = textureSampleCompare(shadows_0_, shadows_0_sampler, _e61, 0.5f);
                texel_1 = _e70;
            }
            default: {
                let _e74 = textureSampleCompare(shadows_1_, shadows_1_sampler, _e61, 0.5f);
                texel_1 = _e74;
            }
        }
        let _e77 = texel_1;
        let _e78 = lit;
        lit = (_e78 + _e77);
        continuing {
            let _e80 = i;
            i = (_e80 + 1i);
        }
    }
    let _e85 = c;
    let _e87 = lit;
    f_color = ((_e85 * _e87) + vec4((f32(size.x) * 0f)));
    let _e96 = f_color;
    return layers_fs_out(_e96);
}
