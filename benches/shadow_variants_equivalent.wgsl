// The WGSL counterpart of shaders/programs/shadow_variants.das for naga_oil
// (benches/naga_oil/): the same two entry points, inputs, varyings,
// resources, helpers and eight #ifdef switches (PCF, SLOPE_BIAS,
// BORDER_FADE, SPECULAR, RIM, FOG, TONEMAP, GAMMA), and the clip-space
// adaptation umbrac's portable conventions append to the vertex entry point.

@group(0) @binding(0) var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(1) var<uniform> u_view_proj: mat4x4<f32>;
@group(0) @binding(2) var<uniform> u_light_view_proj: mat4x4<f32>;
@group(0) @binding(3) var<uniform> u_light_dir: vec3<f32>;
@group(0) @binding(4) var<uniform> u_eye: vec3<f32>;
@group(0) @binding(5) var<uniform> u_color: vec4<f32>;
#ifdef FOG
@group(0) @binding(6) var<uniform> u_fog_color: vec3<f32>;
@group(0) @binding(7) var<uniform> u_fog_density: f32;
#endif
@group(0) @binding(8) var shadow_map: texture_depth_2d;
@group(0) @binding(9) var shadow_map_sampler: sampler_comparison;

const PCF_RADIUS: i32 = 2;

struct VaryingsOut {
    @builtin(position) position: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) world: vec3<f32>,
    @location(2) light_pos: vec4<f32>,
}

struct Varyings {
    @location(0) normal: vec3<f32>,
    @location(1) world: vec3<f32>,
    @location(2) light_pos: vec4<f32>,
}

fn to_webgpu_clip(p: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(p.x, -p.y, (p.z + p.w) * 0.5, p.w);
}

@vertex
fn variants_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>) -> VaryingsOut {
    var out: VaryingsOut;
    let world = u_model * vec4<f32>(a_position, 1.0);
    out.world = world.xyz;
    out.normal = (u_model * vec4<f32>(a_normal, 0.0)).xyz;
    out.light_pos = u_light_view_proj * world;
    out.position = to_webgpu_clip(u_view_proj * world);
    return out;
}

fn shadow_lookup(coord: vec3<f32>, bias: f32) -> f32 {
#ifdef PCF
    let texel = vec2<f32>(1.0) / vec2<f32>(textureDimensions(shadow_map, 0));
    var lit = 0.0;
    for (var y = -PCF_RADIUS; y < PCF_RADIUS + 1; y++) {
        for (var x = -PCF_RADIUS; x < PCF_RADIUS + 1; x++) {
            let offset = vec2<f32>(f32(x), f32(y)) * texel;
            lit += textureSampleCompareLevel(shadow_map, shadow_map_sampler, vec2<f32>(coord.x, 1.0 - coord.y) + offset, coord.z - bias);
        }
    }
    let n = 2 * PCF_RADIUS + 1;
    return lit / f32(n * n);
#else
    return textureSampleCompareLevel(shadow_map, shadow_map_sampler, vec2<f32>(coord.x, 1.0 - coord.y), coord.z - bias);
#endif
}

fn shadow_factor(in: Varyings, ndotl: f32) -> f32 {
    let coord = in.light_pos.xyz / in.light_pos.w * 0.5 + vec3<f32>(0.5);
    if (coord.z > 1.0) {
        return 1.0;
    }
#ifdef SLOPE_BIAS
    let bias = max(0.005 * (1.0 - ndotl), 0.0005);
#else
    let bias = 0.002;
#endif
    let lit = shadow_lookup(coord, bias);
#ifdef BORDER_FADE
    let edge = min(min(coord.x, coord.y), min(1.0 - coord.x, 1.0 - coord.y));
    return mix(1.0, lit, saturate(edge * 20.0));
#else
    return lit;
#endif
}

@fragment
fn variants_fs(in: Varyings) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let l = normalize(-u_light_dir);
    let v = normalize(u_eye - in.world);
    let ndotl = max(dot(n, l), 0.0);
    let shadow = shadow_factor(in, ndotl);
    var color = u_color.rgb * (0.15 + 0.85 * ndotl * shadow);
#ifdef SPECULAR
    let h = normalize(l + v);
    color += vec3<f32>(0.4) * pow(max(dot(n, h), 0.0), 32.0) * shadow;
#endif
#ifdef RIM
    color += u_color.rgb * 0.25 * pow(1.0 - max(dot(n, v), 0.0), 3.0);
#endif
#ifdef FOG
    let dist = length(u_eye - in.world);
    let fog = exp(-u_fog_density * dist);
    color = mix(u_fog_color, color, saturate(fog));
#endif
#ifdef TONEMAP
    color = color / (color + vec3<f32>(1.0));
#endif
#ifdef GAMMA
    color = pow(max(color, vec3<f32>(0.0)), vec3<f32>(1.0 / 2.2));
#endif
    return vec4<f32>(color, u_color.a);
}
