diagnostic(off, derivative_uniformity);

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
var<uniform> u_mvp: mat4x4<f32>;
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_height: f32;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn height_at(uv: vec2<f32>) -> f32 {
    let _e3 = textureSample(heightmap, heightmap_sampler, uv);
    return (_e3.x * 2f);
}

fn height_at_vertex(uv_1: vec2<f32>) -> f32 {
    let _e3 = textureSampleLevel(heightmap, heightmap_sampler, uv_1, 0.0);
    return (_e3.x * 2f);
}

@vertex 
fn terrain_vs(@location(0) in_a_pos: vec2<f32>) -> terrain_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4 * 0.5f) + vec2(0.5f));
    let _e11 = v_uv;
    let _e12 = height_at_vertex(_e11);
    let _e14 = v_uv;
    let _e18 = textureSampleLevel(heightmap, heightmap_sampler, _e14, 1f);
    let h = (_e12 + _e18.y);
    let _e23 = v_uv;
    let _e27 = textureSampleCompareLevel(shadow, shadow_sampler, _e23, 0.5f);
    let _e30 = v_uv;
    let _e32 = vec3<f32>(_e30, 1f);
    let _e39 = textureSampleLevel(heightmap, heightmap_sampler, (_e32.xy / vec2(_e32.z)), 0.0);
    v_height = ((h * _e27) + _e39.z);
    let _e44 = u_mvp;
    let _e47 = a_pos.x;
    let _e50 = a_pos.y;
    gl_Position = (_e44 * vec4<f32>(_e47, h, _e50, 1f));
    let _e55 = gl_Position;
    let _e66 = v_uv;
    let _e68 = v_height;
    return terrain_vs_out(vec4<f32>(_e55.x, -(_e55.y), ((_e55.z + _e55.w) * 0.5f), _e55.w), _e66, _e68);
}

@fragment 
fn terrain_fs(@location(0) in_v_uv: vec2<f32>, @location(1) in_v_height: f32) -> terrain_fs_out {
    v_uv = in_v_uv;
    v_height = in_v_height;
    let _e5 = v_uv;
    let _e6 = height_at(_e5);
    let _e8 = v_uv;
    let _e10 = v_uv;
    let _e11 = dpdx(_e10);
    let _e13 = v_uv;
    let _e14 = dpdy(_e13);
    let _e17 = textureSampleGrad(heightmap, heightmap_sampler, _e8, _e11, _e14);
    let dx = _e17.x;
    let _e26 = v_height;
    f_color = vec4<f32>(vec3<f32>(((_e6 * 0.5f) + (dx * 0.1f)), _e26, 0f), 1f);
    let _e32 = f_color;
    return terrain_fs_out(_e32);
}
