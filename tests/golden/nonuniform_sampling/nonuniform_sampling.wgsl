diagnostic(off, derivative_uniformity);

struct nonuniform_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct nonuniform_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var albedo: texture_2d<f32>;
@group(0) @binding(1) 
var albedo_sampler: sampler;
@group(0) @binding(2) 
var mask: texture_2d<f32>;
@group(0) @binding(3) 
var mask_sampler: sampler;
@group(0) @binding(4) 
var depth: texture_depth_2d;
@group(0) @binding(5) 
var depth_sampler: sampler_comparison;
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn march(uv: vec2<f32>) -> f32 {
    var t: f32;
    var p: vec2<f32>;

    t = 0f;
    p = uv;
    loop {
        let _e5 = t;
        if !((_e5 < 1f)) {
            break;
        }
        let _e10 = p;
        let _e13 = textureSample(mask, mask_sampler, _e10);
        let m = _e13.x;
        if (m > 0.9f) {
            break;
        }
        let _e20 = t;
        t = (_e20 + (0.1f + m));
        let _e25 = p;
        p = (_e25 + vec2(0.01f));
    }
    let _e28 = t;
    return _e28;
}

@vertex 
fn nonuniform_vs(@location(0) in_a_pos: vec2<f32>) -> nonuniform_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4 * 0.5f) + vec2(0.5f));
    let _e12 = a_pos;
    gl_Position = vec4<f32>(_e12, 0f, 1f);
    let _e17 = gl_Position;
    let _e28 = v_uv;
    return nonuniform_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e28);
}

@fragment 
fn nonuniform_fs(@location(0) in_v_uv: vec2<f32>) -> nonuniform_fs_out {
    var c: vec4<f32>;
    var i: i32;

    v_uv = in_v_uv;
    let _e4 = v_uv.x;
    if (_e4 < 0.1f) {
        f_color = vec4(0f);
        let _e11 = f_color;
        return nonuniform_fs_out(_e11);
    }
    let _e14 = v_uv;
    let m_1 = textureSample(mask, mask_sampler, _e14);
    if (m_1.w < 0.5f) {
        discard;
    }
    let _e23 = v_uv;
    let _e26 = textureSample(albedo, albedo_sampler, _e23);
    c = _e26;
    i = 0i;
    loop {
        let _e30 = i;
        if !((_e30 < 8i)) {
            break;
        }
        let _e35 = c.x;
        if (_e35 > 0.95f) {
            break;
        }
        let _e40 = v_uv;
        let _e42 = i;
        let _e50 = textureSample(albedo, albedo_sampler, (_e40 + vec2((f32(_e42) * 0.01f))));
        let _e53 = c;
        c = (_e53 + (_e50 * 0.1f));
        continuing {
            let _e55 = i;
            i = (_e55 + 1i);
        }
    }
    let _e62 = v_uv;
    let _e66 = textureSampleCompare(depth, depth_sampler, _e62, 0.5f);
    let lit = select(1f, _e66, (m_1.y > 0.5f));
    let _e71 = c;
    let _e75 = v_uv;
    let _e76 = march(_e75);
    f_color = vec4<f32>(((_e71.xyz * lit) * _e76), 1f);
    let _e81 = f_color;
    return nonuniform_fs_out(_e81);
}
