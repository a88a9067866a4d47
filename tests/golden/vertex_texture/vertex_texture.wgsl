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
    let _e6 = v_uv;
    let _e7 = height_at_vertex(_e6);
    let _e8 = v_uv;
    let _e12 = textureSampleLevel(heightmap, heightmap_sampler, _e8, 1f);
    let h = (_e7 + _e12.y);
    let _e16 = v_uv;
    let _e19 = textureSampleCompareLevel(shadow, shadow_sampler, _e16, 0.5f);
    let _e21 = v_uv;
    let _e22 = vec3<f32>(_e21, 1f);
    let _e27 = textureSampleLevel(heightmap, heightmap_sampler, (_e22.xy / vec2(_e22.z)), 0.0);
    v_height = ((h * _e19) + _e27.z);
    let _e33 = uniforms.u_mvp;
    gl_Position = (_e33 * vec4<f32>(a_pos.x, h, a_pos.y, 1f));
    let _e38 = gl_Position;
    let _e47 = v_uv;
    let _e48 = v_height;
    return terrain_vs_out(vec4<f32>(_e38.x, -(_e38.y), ((_e38.z + _e38.w) * 0.5f), _e38.w), _e47, _e48);
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
    let _e19 = f_color;
    return terrain_fs_out(_e19);
}
