diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_mvp: mat4x4<f32>,
}

struct terrain_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_height: f32,
}

struct terrain_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var heightmap: texture_2d<f32>;
@group(0) @binding(1) 
var heightmap_sampler: sampler;
@group(0) @binding(2) 
var shadow: texture_depth_2d;
@group(0) @binding(3) 
var shadow_sampler: sampler_comparison;
@group(0) @binding(4) 
var<uniform> uniforms: Uniforms;

fn height_at(uv: vec2<f32>) -> f32 {
    let _e3 = textureSample(heightmap, heightmap_sampler, uv);
    return (_e3.x * 2f);
}

fn height_at_vertex(uv_1: vec2<f32>) -> f32 {
    let _e3 = textureSampleLevel(heightmap, heightmap_sampler, uv_1, 0.0);
    return (_e3.x * 2f);
}

@vertex 
fn terrain_vs(@location(0) a_pos: vec2<f32>) -> terrain_vs_out {
    var v_uv: vec2<f32>;
    var v_height: f32;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e8 = v_uv;
    let _e9 = height_at_vertex(_e8);
    let _e11 = v_uv;
    let _e15 = textureSampleLevel(heightmap, heightmap_sampler, _e11, 1f);
    let h = (_e9 + _e15.y);
    let _e20 = v_uv;
    let _e24 = textureSampleCompareLevel(shadow, shadow_sampler, _e20, 0.5f);
    let _e27 = v_uv;
    let _e29 = vec3<f32>(_e27, 1f);
    let _e36 = textureSampleLevel(heightmap, heightmap_sampler, (_e29.xy / vec2(_e29.z)), 0.0);
    v_height = ((h * _e24) + _e36.z);
    let _e42 = uniforms.u_mvp;
    gl_Position = (_e42 * vec4<f32>(a_pos.x, h, a_pos.y, 1f));
    let _e49 = gl_Position;
    let _e60 = v_uv;
    let _e62 = v_height;
    return terrain_vs_out(vec4<f32>(_e49.x, -(_e49.y), ((_e49.z + _e49.w) * 0.5f), _e49.w), _e60, _e62);
}

@fragment 
fn terrain_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_height_1: f32) -> terrain_fs_out {
    var f_color: vec4<f32>;

    let _e2 = height_at(v_uv_1);
    let _e3 = dpdx(v_uv_1);
    let _e4 = dpdy(v_uv_1);
    let _e7 = textureSampleGrad(heightmap, heightmap_sampler, v_uv_1, _e3, _e4);
    let dx = _e7.x;
    f_color = vec4<f32>(vec3<f32>(((_e2 * 0.5f) + (dx * 0.1f)), v_height_1, 0f), 1f);
    let _e20 = f_color;
    return terrain_fs_out(_e20);
}
