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
    let _e11 = gl_Position;
    let _e20 = v_uv;
    let _e21 = v_dir;
    return tex_vs_out(vec4<f32>(_e11.x, -(_e11.y), ((_e11.z + _e11.w) * 0.5f), _e11.w), _e20, _e21);
}

@fragment 
fn tex_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_dir_1: vec3<f32>) -> tex_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var s: f32;

    let _e5 = textureSample(t_color, t_color_sampler, v_uv_1);
    c = _e5;
    let _e7 = textureSampleBias(t_color, t_color_sampler, v_uv_1, 0.5f);
    let _e8 = c;
    c = (_e8 + _e7);
    let _e11 = textureSampleLevel(t_color, t_color_sampler, v_uv_1, 1f);
    let _e12 = c;
    c = (_e12 + _e11);
    let _e15 = vec3<f32>(v_uv_1, 2f);
    let _e20 = textureSample(t_color, t_color_sampler, (_e15.xy / vec2(_e15.z)));
    let _e21 = c;
    c = (_e21 + _e20);
    let _e27 = textureLoad(t_color, vec2<i32>(3i, 4i), 0i);
    let _e28 = c;
    c = (_e28 + _e27);
    let _e32 = textureSample(t_volume, t_volume_sampler, v_dir_1);
    let _e33 = c;
    c = (_e33 + _e32);
    let _e37 = textureSample(t_sky, t_sky_sampler, v_dir_1);
    let _e38 = c;
    c = (_e38 + _e37);
    let _e40 = vec3<f32>(v_uv_1, 2f);
    let _e47 = textureSample(t_layers, t_layers_sampler, _e40.xy, i32(round(_e40.z)));
    let _e48 = c;
    c = (_e48 + _e47);
    let _e50 = textureDimensions(t_color, 0i);
    let size = vec2<i32>(_e50);
    let _e52 = textureDimensions(t_layers, 0i);
    let _e54 = textureNumLayers(t_layers);
    let layers = vec3<i32>(vec2<i32>(_e52), i32(_e54));
    let _e60 = textureSampleCompare(t_shadow, t_shadow_sampler, v_uv_1, 0.5f);
    s = _e60;
    let _e61 = vec4<f32>(v_uv_1, 0.5f, 1f);
    let _e68 = textureSampleCompare(t_shadow, t_shadow_sampler, (_e61.xy / vec2(_e61.w)), (_e61.z / _e61.w));
    let _e69 = s;
    s = (_e69 + _e68);
    let _e71 = vec3<f32>(v_uv_1, 1f);
    let _e78 = textureSampleCompare(t_shadow_layers, t_shadow_layers_sampler, _e71.xy, i32(round(_e71.z)), 0.5f);
    let _e79 = s;
    s = (_e79 + _e78);
    let _e83 = textureSampleCompare(t_shadow_cube, t_shadow_cube_sampler, v_dir_1, 0.5f);
    let _e84 = s;
    s = (_e84 + _e83);
    let id = textureLoad(t_ids, vec2<i32>(0i, 0i), 0i);
    let k = f32(((size.x + layers.z) + id.x));
    let _e96 = c;
    let _e97 = s;
    f_color = ((_e96 * _e97) + vec4((k * 0.0001f)));
    let _e103 = f_color;
    return tex_fs_out(_e103);
}
