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

@vertex 
fn tex_vs(@location(0) a_pos: vec3<f32>) -> tex_vs_out {
    var v_uv: vec2<f32>;
    var v_dir: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos.xy * 0.5f) + vec2(0.5f));
    v_dir = a_pos;
    gl_Position = vec4<f32>(a_pos, 1f);
    let _e13 = gl_Position;
    let _e24 = v_uv;
    let _e26 = v_dir;
    return tex_vs_out(vec4<f32>(_e13.x, -(_e13.y), ((_e13.z + _e13.w) * 0.5f), _e13.w), _e24, _e26);
}

@fragment 
fn tex_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_dir_1: vec3<f32>) -> tex_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var s: f32;

    let _e5 = textureSample(t_color, t_color_sampler, v_uv_1);
    c = _e5;
    let _e10 = textureSampleBias(t_color, t_color_sampler, v_uv_1, 0.5f);
    let _e11 = c;
    c = (_e11 + _e10);
    let _e17 = textureSampleLevel(t_color, t_color_sampler, v_uv_1, 1f);
    let _e18 = c;
    c = (_e18 + _e17);
    let _e22 = vec3<f32>(v_uv_1, 2f);
    let _e29 = textureSample(t_color, t_color_sampler, (_e22.xy / vec2(_e22.z)));
    let _e30 = c;
    c = (_e30 + _e29);
    let _e38 = textureLoad(t_color, vec2<i32>(3i, 4i), 0i);
    let _e39 = c;
    c = (_e39 + _e38);
    let _e44 = textureSample(t_volume, t_volume_sampler, v_dir_1);
    let _e45 = c;
    c = (_e45 + _e44);
    let _e50 = textureSample(t_sky, t_sky_sampler, v_dir_1);
    let _e51 = c;
    c = (_e51 + _e50);
    let _e55 = vec3<f32>(v_uv_1, 2f);
    let _e62 = textureSample(t_layers, t_layers_sampler, _e55.xy, i32(round(_e55.z)));
    let _e63 = c;
    c = (_e63 + _e62);
    let _e67 = textureDimensions(t_color, 0i);
    let size = vec2<i32>(_e67);
    let _e71 = textureDimensions(t_layers, 0i);
    let _e73 = textureNumLayers(t_layers);
    let layers = vec3<i32>(vec2<i32>(_e71), i32(_e73));
    let _e80 = textureSampleCompare(t_shadow, t_shadow_sampler, v_uv_1, 0.5f);
    s = _e80;
    let _e84 = vec4<f32>(v_uv_1, 0.5f, 1f);
    let _e93 = textureSampleCompare(t_shadow, t_shadow_sampler, (_e84.xy / vec2(_e84.w)), (_e84.z / _e84.w));
    let _e94 = s;
    s = (_e94 + _e93);
    let _e98 = vec3<f32>(v_uv_1, 1f);
    let _e106 = textureSampleCompare(t_shadow_layers, t_shadow_layers_sampler, _e98.xy, i32(round(_e98.z)), 0.5f);
    let _e107 = s;
    s = (_e107 + _e106);
    let _e113 = textureSampleCompare(t_shadow_cube, t_shadow_cube_sampler, v_dir_1, 0.5f);
    let _e114 = s;
    s = (_e114 + _e113);
    let id = textureLoad(t_ids, vec2<i32>(0i, 0i), 0i);
    let k = f32(((size.x + layers.z) + id.x));
    let _e130 = c;
    let _e132 = s;
    f_color = ((_e130 * _e132) + vec4((k * 0.0001f)));
    let _e139 = f_color;
    return tex_fs_out(_e139);
}
