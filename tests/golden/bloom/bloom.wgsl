diagnostic(off, derivative_uniformity);

struct fullscreen_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct bright_fs_out {
    @location(0) f_color: vec4<f32>,
}

struct blur_fs_out {
    @location(0) f_color: vec4<f32>,
}

struct composite_fs_out {
    @location(0) f_color: vec4<f32>,
}

const WEIGHTS: array<f32, 5> = array<f32, 5>(0.227027f, 0.1945946f, 0.1216216f, 0.054054f, 0.016216f);

@group(0) @binding(0) 
var<uniform> u_threshold: vec4<f32>;
@group(0) @binding(1) 
var<uniform> u_direction: vec2<f32>;
@group(0) @binding(2) 
var<uniform> u_exposure: f32;
@group(0) @binding(3) 
var<uniform> u_bloom_strength: f32;
@group(0) @binding(4) 
var hdr_scene: texture_2d<f32>;
@group(0) @binding(5) 
var hdr_scene_sampler: sampler;
@group(0) @binding(6) 
var bloom_src: texture_2d<f32>;
@group(0) @binding(7) 
var bloom_src_sampler: sampler;
var<private> v_uv: vec2<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_VertexID: i32;
var<private> gl_Position: vec4<f32>;

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn aces(x: vec3<f32>) -> vec3<f32> {
    let a = (x * ((x * 2.51f) + vec3(0.03f)));
    let b = ((x * ((x * 2.43f) + vec3(0.59f))) + vec3(0.14f));
    return saturate((a / b));
}

@vertex 
fn fullscreen_vs(@builtin(vertex_index) in_VertexID: u32) -> fullscreen_vs_out {
    gl_VertexID = i32(in_VertexID);
    let _e4 = gl_VertexID;
    let _e12 = gl_VertexID;
    let corner = vec2<f32>(f32(((_e4 << u32(1i)) & 2i)), f32((_e12 & 2i)));
    v_uv = corner;
    gl_Position = vec4<f32>(((corner * 2f) - vec2(1f)), 0f, 1f);
    let _e28 = gl_Position;
    let _e39 = v_uv;
    return fullscreen_vs_out(vec4<f32>(_e28.x, -(_e28.y), ((_e28.z + _e28.w) * 0.5f), _e28.w), _e39);
}

@fragment 
fn bright_fs(@location(0) in_v_uv: vec2<f32>) -> bright_fs_out {
    var soft: f32;

    v_uv = in_v_uv;
    let _e3 = v_uv;
    let _e6 = textureSample(hdr_scene, hdr_scene_sampler, _e3);
    let c_1 = _e6.xyz;
    let _e10 = u_threshold.x;
    let _e13 = u_threshold.y;
    let knee = (_e10 * _e13);
    let _e15 = luminance(c_1);
    let _e19 = u_threshold.x;
    soft = clamp(((_e15 - _e19) + knee), 0f, (2f * knee));
    let _e28 = soft;
    let _e30 = soft;
    soft = ((_e28 * _e30) / ((4f * knee) + 0.00001f));
    let _e38 = soft;
    let _e41 = u_threshold.x;
    let contribution = (max(_e38, (_e15 - _e41)) / max(_e15, 0.00001f));
    f_color = vec4<f32>((c_1 * contribution), 1f);
    let _e52 = f_color;
    return bright_fs_out(_e52);
}

@fragment 
fn blur_fs(@location(0) in_v_uv_1: vec2<f32>) -> blur_fs_out {
    var sum: vec3<f32>;
    var i: i32;

    v_uv = in_v_uv_1;
    let _e3 = u_direction;
    let _e6 = textureDimensions(bloom_src, 0i);
    let texel = (_e3 / vec2<f32>(vec2<i32>(_e6)));
    let _e12 = v_uv;
    let _e15 = textureSample(bloom_src, bloom_src_sampler, _e12);
    sum = (_e15.xyz * WEIGHTS[0]);
    i = 1i;
    loop {
        let _e23 = i;
        if !((_e23 < 5i)) {
            break;
        }
        let _e27 = i;
        let off = (texel * f32(_e27));
        let _e32 = v_uv;
        let _e36 = textureSample(bloom_src, bloom_src_sampler, (_e32 + off));
        let _e40 = i;
        let _e43 = sum;
        sum = (_e43 + (_e36.xyz * WEIGHTS[_e40]));
        let _e47 = v_uv;
        let _e51 = textureSample(bloom_src, bloom_src_sampler, (_e47 - off));
        let _e55 = i;
        let _e58 = sum;
        sum = (_e58 + (_e51.xyz * WEIGHTS[_e55]));
        continuing {
            let _e60 = i;
            i = (_e60 + 1i);
        }
    }
    let _e65 = sum;
    f_color = vec4<f32>(_e65, 1f);
    let _e69 = f_color;
    return blur_fs_out(_e69);
}

@fragment 
fn composite_fs(@location(0) in_v_uv_2: vec2<f32>) -> composite_fs_out {
    v_uv = in_v_uv_2;
    let _e3 = v_uv;
    let _e6 = textureSample(hdr_scene, hdr_scene_sampler, _e3);
    let _e9 = v_uv;
    let _e12 = textureSample(bloom_src, bloom_src_sampler, _e9);
    let _e15 = u_bloom_strength;
    let hdr = (_e6.xyz + (_e12.xyz * _e15));
    let _e19 = u_exposure;
    let _e21 = aces((hdr * _e19));
    f_color = vec4<f32>(pow(_e21, vec3((1f / 2.2f))), 1f);
    let _e31 = f_color;
    return composite_fs_out(_e31);
}
