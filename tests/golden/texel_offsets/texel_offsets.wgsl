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

    let _e7 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(0i, 0i));
    lit = _e7;
    let _e10 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(1i, 0i));
    let _e11 = lit;
    lit = (_e11 + _e10);
    let _e14 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(0i, 1i));
    let _e15 = lit;
    lit = (_e15 + _e14);
    let _e18 = textureSampleCompare(sun_shadow, sun_shadow_sampler, uv, depth, vec2<i32>(1i, 1i));
    let _e19 = lit;
    lit = (_e19 + _e18);
    let _e21 = lit;
    return (_e21 * 0.25f);
}

@vertex 
fn texel_offsets_vs(@location(0) a_pos: vec2<f32>) -> texel_offsets_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    let _e6 = v_uv;
    let _e12 = textureSampleLevel(albedo, albedo_sampler, _e6, 0.0, vec2<i32>(-1i, 0i));
    let h = _e12.x;
    gl_Position = vec4<f32>(a_pos, h, 1f);
    let _e17 = gl_Position;
    let _e26 = v_uv;
    return texel_offsets_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e26);
}

@fragment 
fn texel_offsets_fs(@location(0) v_uv_1: vec2<f32>, @builtin(position) FragCoord: vec4<f32>) -> texel_offsets_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;

    let _e8 = textureSample(albedo, albedo_sampler, v_uv_1, vec2<i32>(-2i, 3i));
    c = _e8;
    let _e13 = textureSampleBias(albedo, albedo_sampler, v_uv_1, 0.5f, vec2<i32>(-1i, 0i));
    let _e14 = c;
    c = (_e14 + _e13);
    let _e17 = vec3<f32>(v_uv_1, 1f);
    let _e28 = textureSampleLevel(layers, layers_sampler, _e17.xy, i32(round(_e17.z)), 0f, vec2<i32>(7i, -8i));
    let _e29 = c;
    c = (_e29 + _e28);
    let _e36 = textureSample(volume, volume_sampler, vec3<f32>(v_uv_1, 0.5f), vec3<i32>(0i, 1i, -1i));
    let _e37 = c;
    c = (_e37 + _e36);
    let _e43 = textureLoad(albedo, (vec2<i32>(FragCoord.xy) + vec2<i32>(1i, 1i)), 0i);
    let _e44 = c;
    c = (_e44 + _e43);
    let _e49 = vec3<i32>(vec2<i32>(FragCoord.xy), 2i);
    let _e54 = textureLoad(layers, (_e49.xy + vec2<i32>(1i, 0i)), _e49.z, 0i);
    let _e55 = c;
    c = (_e55 + _e54);
    let _e58 = c;
    let _e59 = pcf4_(v_uv_1, 0.5f);
    f_color = (_e58 * _e59);
    let _e61 = f_color;
    return texel_offsets_fs_out(_e61);
}
