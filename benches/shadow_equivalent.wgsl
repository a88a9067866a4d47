// The WGSL program the compile benchmark feeds naga's own front end, beside
// shaders/shadow.das for umbrac's. It is written to be equivalent to the DSL
// program: the same four entry points (shadow_vs, shadow_fs, main_vs,
// main_fs), the same vertex inputs, varyings and colour output, the same
// resources in the same order, the same helper functions, and the same
// clip-space adaptation that umbrac's portable conventions append to every
// vertex entry point.

@group(0) @binding(0) var<uniform> u_light_vp: mat4x4<f32>;
@group(0) @binding(1) var<uniform> u_model: mat4x4<f32>;
@group(0) @binding(2) var<uniform> u_view: mat4x4<f32>;
@group(0) @binding(3) var<uniform> u_proj: mat4x4<f32>;
@group(0) @binding(4) var<uniform> u_light_dir: vec3<f32>;
@group(0) @binding(5) var<uniform> u_cam_pos: vec3<f32>;
@group(0) @binding(6) var<uniform> u_is_floor: f32;
@group(0) @binding(7) var shadow_map: texture_depth_2d;
@group(0) @binding(8) var shadow_map_sampler: sampler_comparison;

const SHADOW_MAP_SIZE: f32 = 1024.0;
const PCF_RADIUS: i32 = 1;

struct VaryingsOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) light_space: vec4<f32>,
}

struct Varyings {
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) light_space: vec4<f32>,
}

// OpenGL clip space (z in [-w, w]) to WebGPU's (z in [0, w]), y mirrored.
fn to_webgpu_clip(p: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(p.x, -p.y, (p.z + p.w) * 0.5, p.w);
}

@vertex
fn shadow_vs(@location(0) a_pos: vec3<f32>) -> @builtin(position) vec4<f32> {
    return to_webgpu_clip(u_light_vp * (u_model * vec4<f32>(a_pos, 1.0)));
}

@fragment
fn shadow_fs() -> @location(0) vec4<f32> {
    return vec4<f32>(1.0);
}

@vertex
fn main_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> VaryingsOut {
    let world = u_model * vec4<f32>(a_pos, 1.0);
    var o: VaryingsOut;
    o.world_pos = world.xyz;
    o.world_normal = (u_model * vec4<f32>(a_normal, 0.0)).xyz;
    o.light_space = u_light_vp * world;
    o.position = to_webgpu_clip(u_proj * (u_view * world));
    return o;
}

fn sun_visibility(uv: vec2<f32>, depth: f32) -> f32 {
    let step = 1.0 / SHADOW_MAP_SIZE;
    var lit = 0.0;
    var taps = 0.0;
    for (var y = -PCF_RADIUS; y < PCF_RADIUS + 1; y += 1) {
        for (var x = -PCF_RADIUS; x < PCF_RADIUS + 1; x += 1) {
            lit += textureSampleCompare(shadow_map, shadow_map_sampler, uv + vec2<f32>(f32(x), f32(y)) * step, depth);
            taps += 1.0;
        }
    }
    return lit / taps;
}

fn floor_albedo(p: vec3<f32>) -> vec3<f32> {
    let cell = floor(p.x * 0.5 + 100.0) + floor(p.z * 0.5 + 100.0);
    let odd = cell - 2.0 * floor(cell * 0.5);
    let shade = select(0.30, 0.85, odd < 0.5);
    return vec3<f32>(shade) * vec3<f32>(0.80, 0.82, 0.88);
}

@fragment
fn main_fs(v: Varyings) -> @location(0) vec4<f32> {
    let n = normalize(v.world_normal);
    let l = normalize(u_light_dir);
    let to_eye = normalize(u_cam_pos - v.world_pos);
    let ndotl = max(dot(n, l), 0.0);
    let clip_w = max(v.light_space.w, 0.0001);
    let ndc = v.light_space.xyz / clip_w;
    let uv = ndc.xy * 0.5 + 0.5;
    let depth = ndc.z * 0.5 + 0.5;
    let bias = max(0.0025 * (1.0 - ndotl), 0.0008);
    var lit = sun_visibility(uv, depth - bias);
    if (ndotl < 0.05) {
        lit = 0.0;
    }
    let up = n.y * 0.5 + 0.5;
    let ambient = mix(vec3<f32>(0.10, 0.09, 0.08), vec3<f32>(0.30, 0.34, 0.42), vec3<f32>(up));
    let sun_color = vec3<f32>(1.30, 1.15, 0.90);
    var albedo = vec3<f32>(0.85, 0.45, 0.30);
    var gloss = 0.5;
    if (u_is_floor > 0.5) {
        albedo = floor_albedo(v.world_pos);
        gloss = 0.15;
    }
    let h = normalize(l + to_eye);
    let spec = pow(max(dot(n, h), 0.0), 48.0) * lit * gloss;
    let color = albedo * (ambient + sun_color * (ndotl * lit)) + vec3<f32>(spec);
    return vec4<f32>(color, 1.0);
}
