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
    let _e20 = gl_Position;
    let _e30 = v_uv;
    return fullscreen_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e30);
}

@fragment 
fn bright_fs(@location(0) v_uv_1: vec2<f32>) -> bright_fs_out {
    var f_color: vec4<f32>;
    var soft: f32;

    let _e3 = textureSample(hdr_scene, hdr_scene_sampler, v_uv_1);
    let c_1 = _e3.xyz;
    let _e8 = uniforms.u_threshold.x;
    let _e11 = uniforms.u_threshold.y;
    let knee = (_e8 * _e11);
    let _e13 = luminance(c_1);
    let _e17 = uniforms.u_threshold.x;
    soft = clamp(((_e13 - _e17) + knee), 0f, (2f * knee));
    let _e24 = soft;
    let _e25 = soft;
    soft = ((_e24 * _e25) / ((4f * knee) + 0.00001f));
    let _e32 = soft;
    let _e35 = uniforms.u_threshold.x;
    let contribution = (max(_e32, (_e13 - _e35)) / max(_e13, 0.00001f));
    f_color = vec4<f32>((c_1 * contribution), 1f);
    let _e44 = f_color;
    return bright_fs_out(_e44);
}

@fragment 
fn blur_fs(@location(0) v_uv_2: vec2<f32>) -> blur_fs_out {
    var f_color_1: vec4<f32>;
    var sum: vec3<f32>;
    var i: i32;

    let _e3 = uniforms.u_direction;
    let _e6 = textureDimensions(bloom_src, 0i);
    let texel = (_e3 / vec2<f32>(vec2<i32>(_e6)));
    let _e12 = textureSample(bloom_src, bloom_src_sampler, v_uv_2);
    sum = (_e12.xyz * WEIGHTS[0]);
    i = 1i;
    loop {
        let _e20 = i;
        if !((_e20 < 5i)) {
            break;
        }
        let _e23 = i;
        let off = (texel * f32(_e23));
        let _e27 = textureSample(bloom_src, bloom_src_sampler, (v_uv_2 + off));
        let _e29 = i;
        let _e32 = sum;
        sum = (_e32 + (_e27.xyz * WEIGHTS[_e29]));
        let _e35 = textureSample(bloom_src, bloom_src_sampler, (v_uv_2 - off));
        let _e37 = i;
        let _e40 = sum;
        sum = (_e40 + (_e35.xyz * WEIGHTS[_e37]));
        continuing {
            let _e42 = i;
            i = (_e42 + 1i);
        }
    }
    let _e45 = sum;
    f_color_1 = vec4<f32>(_e45, 1f);
    let _e48 = f_color_1;
    return blur_fs_out(_e48);
}

@fragment 
fn composite_fs(@location(0) v_uv_3: vec2<f32>) -> composite_fs_out {
    var f_color_2: vec4<f32>;

    let _e3 = textureSample(hdr_scene, hdr_scene_sampler, v_uv_3);
    let _e7 = textureSample(bloom_src, bloom_src_sampler, v_uv_3);
    let _e11 = uniforms.u_bloom_strength;
    let hdr = (_e3.xyz + (_e7.xyz * _e11));
    let _e15 = uniforms.u_exposure;
    let _e17 = aces((hdr * _e15));
    f_color_2 = vec4<f32>(pow(_e17, vec3((1f / 2.2f))), 1f);
    let _e25 = f_color_2;
    return composite_fs_out(_e25);
}
