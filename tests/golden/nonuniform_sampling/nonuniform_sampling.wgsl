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
fn nonuniform_vs(@location(0) a_pos: vec2<f32>) -> nonuniform_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return nonuniform_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
}

@fragment 
fn nonuniform_fs(@location(0) v_uv_1: vec2<f32>) -> nonuniform_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var i: i32;

    if (v_uv_1.x < 0.1f) {
        f_color = vec4(0f);
        let _e8 = f_color;
        return nonuniform_fs_out(_e8);
    }
    let m_1 = textureSample(mask, mask_sampler, v_uv_1);
    if (m_1.w < 0.5f) {
        discard;
    }
    let _e19 = textureSample(albedo, albedo_sampler, v_uv_1);
    c = _e19;
    i = 0i;
    loop {
        let _e23 = i;
        if !((_e23 < 8i)) {
            break;
        }
        let _e28 = c.x;
        if (_e28 > 0.95f) {
            break;
        }
        let _e33 = i;
        let _e41 = textureSample(albedo, albedo_sampler, (v_uv_1 + vec2((f32(_e33) * 0.01f))));
        let _e44 = c;
        c = (_e44 + (_e41 * 0.1f));
        continuing {
            let _e46 = i;
            i = (_e46 + 1i);
        }
    }
    let _e55 = textureSampleCompare(depth, depth_sampler, v_uv_1, 0.5f);
    let lit = select(1f, _e55, (m_1.y > 0.5f));
    let _e60 = c;
    let _e63 = march(v_uv_1);
    f_color = vec4<f32>(((_e60.xyz * lit) * _e63), 1f);
    let _e68 = f_color;
    return nonuniform_fs_out(_e68);
}
