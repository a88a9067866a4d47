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

fn march(uv: vec2<f32>) -> f32 {
    var t: f32;
    var p: vec2<f32>;

    t = 0f;
    p = uv;
    loop {
        let _e4 = t;
        if !((_e4 < 1f)) {
            break;
        }
        let _e8 = p;
        let _e11 = textureSample(mask, mask_sampler, _e8);
        let m = _e11.x;
        if (m > 0.9f) {
            break;
        }
        let _e17 = t;
        t = (_e17 + (0.1f + m));
        let _e21 = p;
        p = (_e21 + vec2(0.01f));
    }
    let _e23 = t;
    return _e23;
}

@vertex 
fn nonuniform_vs(@location(0) a_pos: vec2<f32>) -> nonuniform_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return nonuniform_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn nonuniform_fs(@location(0) v_uv_1: vec2<f32>) -> nonuniform_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var i: i32;

    if (v_uv_1.x < 0.1f) {
        f_color = vec4(0f);
        let _e7 = f_color;
        return nonuniform_fs_out(_e7);
    }
    let m_1 = textureSample(mask, mask_sampler, v_uv_1);
    if (m_1.w < 0.5f) {
        discard;
    }
    let _e18 = textureSample(albedo, albedo_sampler, v_uv_1);
    c = _e18;
    i = 0i;
    loop {
        let _e22 = i;
        if !((_e22 < 8i)) {
            break;
        }
        let _e26 = c.x;
        if (_e26 > 0.95f) {
            break;
        }
        let _e29 = i;
        let _e35 = textureSample(albedo, albedo_sampler, (v_uv_1 + vec2((f32(_e29) * 0.01f))));
        let _e37 = c;
        c = (_e37 + (_e35 * 0.1f));
        continuing {
            let _e39 = i;
            i = (_e39 + 1i);
        }
    }
    let _e46 = textureSampleCompare(depth, depth_sampler, v_uv_1, 0.5f);
    let lit = select(1f, _e46, (m_1.y > 0.5f));
    let _e49 = c;
    let _e52 = march(v_uv_1);
    f_color = vec4<f32>(((_e49.xyz * lit) * _e52), 1f);
    let _e55 = f_color;
    return nonuniform_fs_out(_e55);
}
