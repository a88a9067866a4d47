diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_threshold: vec4<f32>,
    u_direction: vec2<f32>,
    u_exposure: f32,
    u_bloom_strength: f32,
}

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
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var hdr_scene: texture_2d<f32>;
@group(0) @binding(2) 
var hdr_scene_sampler: sampler;
@group(0) @binding(3) 
var bloom_src: texture_2d<f32>;
@group(0) @binding(4) 
var bloom_src_sampler: sampler;

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn aces(x: vec3<f32>) -> vec3<f32> {
    let a = (x * ((x * 2.51f) + vec3(0.03f)));
    let b = ((x * ((x * 2.43f) + vec3(0.59f))) + vec3(0.14f));
    return saturate((a / b));
}

@vertex 
fn fullscreen_vs(@builtin(vertex_index) VertexID: u32) -> fullscreen_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    let _e1 = i32(VertexID);
    let corner = vec2<f32>(f32(((_e1 << u32(1i)) & 2i)), f32((_e1 & 2i)));
    v_uv = corner;
    gl_Position = vec4<f32>(((corner * 2f) - vec2(1f)), 0f, 1f);
    let _e23 = gl_Position;
    let _e34 = v_uv;
    return fullscreen_vs_out(vec4<f32>(_e23.x, -(_e23.y), ((_e23.z + _e23.w) * 0.5f), _e23.w), _e34);
}

@fragment 
fn bright_fs(@location(0) v_uv_1: vec2<f32>) -> bright_fs_out {
    var f_color: vec4<f32>;
    var soft: f32;

    let _e3 = textureSample(hdr_scene, hdr_scene_sampler, v_uv_1);
    let c_1 = _e3.xyz;
    let _e8 = uniforms.u_threshold.x;
    let _e12 = uniforms.u_threshold.y;
    let knee = (_e8 * _e12);
    let _e14 = luminance(c_1);
    let _e19 = uniforms.u_threshold.x;
    soft = clamp(((_e14 - _e19) + knee), 0f, (2f * knee));
    let _e28 = soft;
    let _e30 = soft;
    soft = ((_e28 * _e30) / ((4f * knee) + 0.00001f));
    let _e38 = soft;
    let _e42 = uniforms.u_threshold.x;
    let contribution = (max(_e38, (_e14 - _e42)) / max(_e14, 0.00001f));
    f_color = vec4<f32>((c_1 * contribution), 1f);
    let _e53 = f_color;
    return bright_fs_out(_e53);
}

@fragment 
fn blur_fs(@location(0) v_uv_2: vec2<f32>) -> blur_fs_out {
    var f_color_1: vec4<f32>;
    var sum: vec3<f32>;
    var i: i32;

    let _e3 = uniforms.u_direction;
    let _e6 = textureDimensions(bloom_src, 0i);
    let texel = (_e3 / vec2<f32>(vec2<i32>(_e6)));
    let _e13 = textureSample(bloom_src, bloom_src_sampler, v_uv_2);
    sum = (_e13.xyz * WEIGHTS[0]);
    i = 1i;
    loop {
        let _e21 = i;
        if !((_e21 < 5i)) {
            break;
        }
        let _e25 = i;
        let off = (texel * f32(_e25));
        let _e32 = textureSample(bloom_src, bloom_src_sampler, (v_uv_2 + off));
        let _e36 = i;
        let _e39 = sum;
        sum = (_e39 + (_e32.xyz * WEIGHTS[_e36]));
        let _e45 = textureSample(bloom_src, bloom_src_sampler, (v_uv_2 - off));
        let _e49 = i;
        let _e52 = sum;
        sum = (_e52 + (_e45.xyz * WEIGHTS[_e49]));
        continuing {
            let _e54 = i;
            i = (_e54 + 1i);
        }
    }
    let _e59 = sum;
    f_color_1 = vec4<f32>(_e59, 1f);
    let _e63 = f_color_1;
    return blur_fs_out(_e63);
}

@fragment 
fn composite_fs(@location(0) v_uv_3: vec2<f32>) -> composite_fs_out {
    var f_color_2: vec4<f32>;

    let _e3 = textureSample(hdr_scene, hdr_scene_sampler, v_uv_3);
    let _e7 = textureSample(bloom_src, bloom_src_sampler, v_uv_3);
    let _e11 = uniforms.u_bloom_strength;
    let hdr = (_e3.xyz + (_e7.xyz * _e11));
    let _e16 = uniforms.u_exposure;
    let _e18 = aces((hdr * _e16));
    f_color_2 = vec4<f32>(pow(_e18, vec3((1f / 2.2f))), 1f);
    let _e28 = f_color_2;
    return composite_fs_out(_e28);
}
