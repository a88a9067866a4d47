diagnostic(off, derivative_uniformity);

struct tex_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_dir: vec3<f32>,
}

struct tex_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var t_color: texture_2d<f32>;
@group(0) @binding(1) 
var t_color_sampler: sampler;
@group(0) @binding(2) 
var t_volume: texture_3d<f32>;
@group(0) @binding(3) 
var t_volume_sampler: sampler;
@group(0) @binding(4) 
var t_sky: texture_cube<f32>;
@group(0) @binding(5) 
var t_sky_sampler: sampler;
@group(0) @binding(6) 
var t_layers: texture_2d_array<f32>;
@group(0) @binding(7) 
var t_layers_sampler: sampler;
@group(0) @binding(8) 
var t_shadow: texture_depth_2d;
@group(0) @binding(9) 
var t_shadow_sampler: sampler_comparison;
@group(0) @binding(10) 
var t_shadow_layers: texture_depth_2d_array;
@group(0) @binding(11) 
var t_shadow_layers_sampler: sampler_comparison;
@group(0) @binding(12) 
var t_shadow_cube: texture_depth_cube;
@group(0) @binding(13) 
var t_shadow_cube_sampler: sampler_comparison;
@group(0) @binding(14) 
var t_ids: texture_2d<i32>;
@group(0) @binding(15) 
var t_ids_sampler: sampler;
var<private> a_pos: vec3<f32>;
var<private> v_uv: vec2<f32>;
var<private> v_dir: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

@vertex 
fn tex_vs(@location(0) in_a_pos: vec3<f32>) -> tex_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4.xy * 0.5f) + vec2(0.5f));
    let _e13 = a_pos;
    v_dir = _e13;
    let _e16 = a_pos;
    gl_Position = vec4<f32>(_e16, 1f);
    let _e20 = gl_Position;
    let _e31 = v_uv;
    let _e33 = v_dir;
    return tex_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e31, _e33);
}

@fragment 
fn tex_fs(@location(0) in_v_uv: vec2<f32>, @location(1) in_v_dir: vec3<f32>) -> tex_fs_out {
    var c: vec4<f32>;
    var s: f32;

    v_uv = in_v_uv;
    v_dir = in_v_dir;
    let _e6 = v_uv;
    let _e9 = textureSample(t_color, t_color_sampler, _e6);
    c = _e9;
    let _e12 = v_uv;
    let _e16 = textureSampleBias(t_color, t_color_sampler, _e12, 0.5f);
    let _e17 = c;
    c = (_e17 + _e16);
    let _e21 = v_uv;
    let _e25 = textureSampleLevel(t_color, t_color_sampler, _e21, 1f);
    let _e26 = c;
    c = (_e26 + _e25);
    let _e30 = v_uv;
    let _e32 = vec3<f32>(_e30, 2f);
    let _e39 = textureSample(t_color, t_color_sampler, (_e32.xy / vec2(_e32.z)));
    let _e40 = c;
    c = (_e40 + _e39);
    let _e48 = textureLoad(t_color, vec2<i32>(3i, 4i), 0i);
    let _e49 = c;
    c = (_e49 + _e48);
    let _e53 = v_dir;
    let _e56 = textureSample(t_volume, t_volume_sampler, _e53);
    let _e57 = c;
    c = (_e57 + _e56);
    let _e61 = v_dir;
    let _e64 = textureSample(t_sky, t_sky_sampler, _e61);
    let _e65 = c;
    c = (_e65 + _e64);
    let _e69 = v_uv;
    let _e71 = vec3<f32>(_e69, 2f);
    let _e78 = textureSample(t_layers, t_layers_sampler, _e71.xy, i32(round(_e71.z)));
    let _e79 = c;
    c = (_e79 + _e78);
    let _e83 = textureDimensions(t_color, 0i);
    let size = vec2<i32>(_e83);
    let _e87 = textureDimensions(t_layers, 0i);
    let _e89 = textureNumLayers(t_layers);
    let layers = vec3<i32>(vec2<i32>(_e87), i32(_e89));
    let _e94 = v_uv;
    let _e98 = textureSampleCompare(t_shadow, t_shadow_sampler, _e94, 0.5f);
    s = _e98;
    let _e101 = v_uv;
    let _e104 = vec4<f32>(_e101, 0.5f, 1f);
    let _e113 = textureSampleCompare(t_shadow, t_shadow_sampler, (_e104.xy / vec2(_e104.w)), (_e104.z / _e104.w));
    let _e114 = s;
    s = (_e114 + _e113);
    let _e118 = v_uv;
    let _e120 = vec3<f32>(_e118, 1f);
    let _e128 = textureSampleCompare(t_shadow_layers, t_shadow_layers_sampler, _e120.xy, i32(round(_e120.z)), 0.5f);
    let _e129 = s;
    s = (_e129 + _e128);
    let _e133 = v_dir;
    let _e137 = textureSampleCompare(t_shadow_cube, t_shadow_cube_sampler, _e133, 0.5f);
    let _e138 = s;
    s = (_e138 + _e137);
    let id = textureLoad(t_ids, vec2<i32>(0i, 0i), 0i);
    let k = f32(((size.x + layers.z) + id.x));
    let _e154 = c;
    let _e156 = s;
    f_color = ((_e154 * _e156) + vec4((k * 0.0001f)));
    let _e163 = f_color;
    return tex_fs_out(_e163);
}
