diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_taps: array<vec4<f32>, 4>,
}

struct Accum {
    sum: vec3<f32>,
    weight: f32,
}

struct references_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct references_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn flip_y(uv_1: ptr<function, vec2<f32>>) {
    let _e4 = (*uv_1).y;
    (*uv_1).y = (1f - _e4);
    return;
}

fn falloff(d: f32, k: f32) -> f32 {
    var d_1: f32;

    d_1 = d;
    let _e3 = d_1;
    d_1 = max(_e3, 0f);
    let _e6 = d_1;
    d_1 = (_e6 * k);
    let _e9 = d_1;
    let _e10 = d_1;
    return (1f / (1f + (_e9 * _e10)));
}

fn add_tap(acc_1: ptr<function, Accum>, c_1: vec3<f32>, w: f32) {
    let _e5 = (*acc_1).sum;
    (*acc_1).sum = (_e5 + (c_1 * w));
    let _e8 = (*acc_1).weight;
    (*acc_1).weight = (_e8 + w);
    return;
}

fn clamp_into(x_2: ptr<function, f32>, lo: f32, hi: f32) {
    let _e3 = (*x_2);
    (*x_2) = clamp(_e3, lo, hi);
    return;
}

fn settle(acc_2: ptr<function, Accum>) {
    let _e3 = (*acc_2).weight;
    let _e7 = (*acc_2).sum;
    let _e9 = (*acc_2).weight;
    (*acc_2).sum = select(vec3(0f), (_e7 / vec3(_e9)), (_e3 > 0f));
    (*acc_2).weight = 1f;
    return;
}

fn mean(acc_3: Accum) -> vec3<f32> {
    return select(vec3(0f), (acc_3.sum / vec3(acc_3.weight)), (acc_3.weight > 0f));
}

fn saturate2_(v_1: ptr<function, vec2<f32>>) {
    let _e1 = (*v_1);
    (*v_1) = saturate(_e1);
    return;
}

@vertex 
fn references_vs(@location(0) a_pos: vec2<f32>) -> references_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;
    var uv: vec2<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e6 = v_uv;
    uv = _e6;
    flip_y((&uv));
    let _e8 = uv;
    v_uv = _e8;
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e13 = gl_Position;
    let _e22 = v_uv;
    return references_vs_out(vec4<f32>(_e13.x, -(_e13.y), ((_e13.z + _e13.w) * 0.5f), _e13.w), _e22);
}

@fragment 
fn references_fs(@location(0) v_uv_1: vec2<f32>) -> references_fs_out {
    var f_color: vec4<f32>;
    var acc: Accum;
    var weights: array<f32, 4>;
    var i: i32;
    var x: f32;
    var c: vec3<f32>;
    var x_1: f32;
    var v: vec2<f32>;

    acc = Accum(vec3(0f), 0f);
    weights = array<f32, 4>();
    i = 0i;
    loop {
        let _e10 = i;
        if !((_e10 < 4i)) {
            break;
        }
        let _e15 = i;
        let tap = uniforms.u_taps[_e15];
        let _e18 = i;
        let _e23 = falloff(distance(v_uv_1, tap.xy), 4f);
        weights[_e18] = _e23;
        let _e30 = i;
        let _e32 = weights[_e30];
        add_tap((&acc), vec3<f32>(tap.z, tap.w, (1f - tap.z)), _e32);
        continuing {
            let _e33 = i;
            i = (_e33 + 1i);
        }
    }
    let _e37 = weights[3];
    x = _e37;
    clamp_into((&x), 0f, 0.5f);
    let _e40 = x;
    weights[3] = _e40;
    settle((&acc));
    let _e42 = acc;
    let _e43 = mean(_e42);
    c = _e43;
    let _e45 = c.y;
    x_1 = _e45;
    clamp_into((&x_1), 0.1f, 0.9f);
    let _e49 = x_1;
    c.y = _e49;
    let _e50 = c;
    v = _e50.xz;
    saturate2_((&v));
    let _e53 = v;
    let _e54 = c;
    c = vec3<f32>(_e53.x, _e54.y, _e53.y);
    let _e60 = c;
    let _e62 = weights[3];
    f_color = vec4<f32>(_e60, _e62);
    let _e64 = f_color;
    return references_fs_out(_e64);
}
