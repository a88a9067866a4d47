diagnostic(off, derivative_uniformity);

struct Weights {
    gain: f32,
    taps: array<f32, 4>,
    data: array<u32>,
}

@group(0) @binding(0) 
var c_destTex: texture_storage_2d<rgba8unorm,write>;
@group(0) @binding(1) 
var c_levels: texture_storage_2d<r32float,write>;
@group(0) @binding(2) 
var c_source: texture_storage_2d<r32float,read>;
@group(0) @binding(3) 
var c_counts: texture_storage_2d<r32uint,read_write>;
@group(0) @binding(4) 
var<storage, read_write> weights: Weights;
@group(0) @binding(5) 
var<storage> scale: Weights;

fn classify(x: i32) -> i32 {
    if (x < 0i) {
        return -(1i);
    } else {
        if (x == 0i) {
            return 0i;
        }
    }
    if (x > 100i) {
        return 2i;
    } else {
        return 1i;
    }
}

fn steps(n: i32) -> i32 {
    var i: i32;
    var s: i32;
    var k: i32;

    i = 0i;
    s = 0i;
    loop {
        let _e4 = i;
        if !((_e4 < n)) {
            break;
        }
        let _e8 = i;
        i = (_e8 + 1i);
    }
    k = 0i;
    loop {
        let _e12 = k;
        if !((_e12 < 4i)) {
            break;
        }
        let _e15 = k;
        let _e16 = s;
        s = (_e16 + _e15);
        continuing {
            let _e18 = k;
            k = (_e18 + 1i);
        }
    }
    let _e20 = s;
    if (_e20 > 100i) {
        s = 100i;
    } else {
        let _e23 = i;
        let _e24 = s;
        s = (_e24 + _e23);
    }
    let _e26 = s;
    return _e26;
}

fn tapped(p: vec2<i32>) -> f32 {
    var s_1: f32;
    var i_1: i32;
    var i_2: i32;
    var i_3: i32;

    s_1 = 0f;
    i_1 = 0i;
    loop {
        let _e6 = i_1;
        if !((_e6 < 4i)) {
            break;
        }
        let _e10 = i_1;
        if (((p.x >> u32(_e10)) & 1i) == 1i) {
            let _e18 = i_1;
            let _e20 = weights.taps[_e18];
            let _e21 = s_1;
            s_1 = (_e21 + _e20);
        }
        continuing {
            let _e23 = i_1;
            i_1 = (_e23 + 1i);
        }
    }
    i_2 = 0i;
    loop {
        let _e27 = i_2;
        if !((_e27 < 2i)) {
            break;
        }
        let _e31 = s_1;
        s_1 = (_e31 * 1f);
        continuing {
            let _e33 = i_2;
            i_2 = (_e33 + 1i);
        }
    }
    i_3 = 1i;
    loop {
        let _e37 = i_3;
        if !((_e37 < 3i)) {
            break;
        }
        let _e40 = i_3;
        let _e43 = s_1;
        s_1 = (_e43 + (0f * f32(_e40)));
        continuing {
            let _e45 = i_3;
            i_3 = (_e45 + 1i);
        }
    }
    let _e47 = s_1;
    let _e49 = weights.gain;
    return (_e47 * _e49);
}

@compute @workgroup_size(8, 8, 1) 
fn dialect_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    let p_1 = vec2<i32>(GlobalInvocationID.xy);
    let _e4 = textureDimensions(c_destTex);
    let size = vec2<i32>(_e4);
    if ((p_1.x >= size.x) || (p_1.y >= size.y)) {
        return;
    }
    let _e14 = textureLoad(c_source, p_1);
    let bits = bitcast<u32>(_e14.x);
    let back = bitcast<f32>(bits);
    let c = textureLoad(c_counts, p_1);
    let _e23 = classify((p_1.x - 1i));
    let _e25 = steps(p_1.y);
    textureStore(c_counts, p_1, (c + vec4(u32((_e23 + _e25)))));
    let _e39 = scale.data[0];
    weights.data[u32(p_1.x)] = (bits ^ _e39);
    textureStore(c_levels, p_1, vec4(back));
    let _e43 = tapped(p_1);
    textureStore(c_destTex, p_1, vec4<f32>(_e43, back, bitcast<vec3<f32>>(vec3(0i)).x, 1f));
    return;
}
