diagnostic(off, derivative_uniformity);

struct Taps {
    gain: f32,
    weights: array<f32, 4>,
    bits: array<u32>,
}

@group(0) @binding(0) 
var c_destTex: texture_storage_2d<rgba8unorm,write>;
@group(0) @binding(1) 
var<storage, read_write> taps: Taps;

@compute @workgroup_size(8, 8, 1) 
fn dialect_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    var s: f32;
    var n: i32;
    var i: i32;

    let p = vec2<i32>(GlobalInvocationID.xy);
    let _e4 = textureDimensions(c_destTex);
    let size = vec2<i32>(_e4);
    if ((p.x >= size.x) || (p.y >= size.y)) {
        return;
    }
    s = 0f;
    n = 0i;
    i = 0i;
    loop {
        let _e19 = i;
        if !((_e19 < 4i)) {
            break;
        }
        let _e23 = i;
        if (((p.x >> u32(_e23)) & 1i) == 1i) {
            let _e31 = i;
            let _e33 = taps.weights[_e31];
            let _e34 = s;
            s = (_e34 + _e33);
        }
        let _e37 = i;
        if (((p.y >> u32(_e37)) & 1i) == 1i) {
            let _e42 = i;
            let _e45 = n;
            n = (_e45 + (1i << u32(_e42)));
        }
        continuing {
            let _e47 = i;
            i = (_e47 + 1i);
        }
    }
    let _e56 = n;
    taps.bits[((p.y * size.x) + p.x)] = bitcast<u32>(f32(_e56));
    let _e59 = s;
    let _e61 = taps.gain;
    textureStore(c_destTex, p, vec4<f32>((_e59 * _e61), (f32((p.y % 3i)) / 2f), 0.25f, 1f));
    return;
}
