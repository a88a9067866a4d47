diagnostic(off, derivative_uniformity);

struct texel_offsets_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct texel_offsets_fs_out {
    @location(0) f_color: vec4<f32>,
}

const RIGHT: vec2<i32> = vec2<i32>(1i, 0i);

@group(0) @binding(0) 
var albedo: texture_2d<f32>;
@group(0) @binding(1) 
var albedo_sampler: sampler;
@group(0) @binding(2) 
var layers: texture_2d_array<f32>;
@group(0) @binding(3) 
var layers_sampler: sampler;
@group(0) @binding(4) 
var volume: texture_3d<f32>;
@group(0) @binding(5) 
var volume_sampler: sampler;
@group(0) @binding(6) 
var sun_shadow: texture_depth_2d;
@group(0) @binding(7) 
var sun_shadow_sampler: sampler_comparison;

fn pcf4_(uv: vec2<f32>, depth: f32) -> f32 {
    var lit: f32;

    let _e8 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(0i, 0i));
    lit = _e8;
    let _e15 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(1i, 0i));
    let _e16 = lit;
    lit = (_e16 + _e15);
    let _e24 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(0i, 1i));
    let _e25 = lit;
    lit = (_e25 + _e24);
    let _e33 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(1i, 1i));
    let _e34 = lit;
    lit = (_e34 + _e33);
    let _e37 = lit;
    return (_e37 * 0.25f);
}

@vertex 
fn texel_offsets_vs(@location(0) a_pos: vec2<f32>) -> texel_offsets_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e8 = v_uv;
    let _e14 = textureSampleLevel(albedo, albedo_sampler, _e8, 0.0, vec2<i32>(-1i, 0i));
    let h = _e14.x;
    gl_Position = vec4<f32>(a_pos, h, 1f);
    let _e20 = gl_Position;
    let _e31 = v_uv;
    return texel_offsets_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e31);
}

@fragment 
fn texel_offsets_fs(@location(0) v_uv_1: vec2<f32>, @builtin(position) FragCoord: vec4<f32>) -> texel_offsets_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;

    let _e8 = textureSample(albedo, albedo_sampler, v_uv_1, vec2<i32>(-2i, 3i));
    c = _e8;
    let _e16 = textureSampleBias(albedo, albedo_sampler, v_uv_1, 0.5f, vec2<i32>(-1i, 0i));
    let _e17 = c;
    c = (_e17 + _e16);
    let _e21 = vec3<f32>(v_uv_1, 1f);
    let _e32 = textureSampleLevel(layers, layers_sampler, _e21.xy, i32(round(_e21.z)), 0f, vec2<i32>(7i, -8i));
    let _e33 = c;
    c = (_e33 + _e32);
    let _e44 = textureSample(volume, volume_sampler, vec3<f32>(v_uv_1, 0.5f), vec3<i32>(0i, 1i, -1i));
    let _e45 = c;
    c = (_e45 + _e44);
    let _e56 = textureLoad(albedo, (vec2<i32>(FragCoord.xy) + vec2<i32>(1i, 1i)), 0i);
    let _e57 = c;
    c = (_e57 + _e56);
    let _e63 = vec3<i32>(vec2<i32>(FragCoord.xy), 2i);
    let _e72 = textureLoad(layers, (_e63.xy + vec2<i32>(1i, 0i)), _e63.z, 0i);
    let _e73 = c;
    c = (_e73 + _e72);
    let _e77 = c;
    let _e79 = pcf4_(v_uv_1, 0.5f);
    f_color = (_e77 * _e79);
    let _e82 = f_color;
    return texel_offsets_fs_out(_e82);
}
