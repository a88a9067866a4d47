// A hand-written WGSL port of shaders/shadow.das, kept beside the compiler's
// output as a peer for benchmarks and as a known-good shader for the runner.
//
// It has the binding model umbrac emits for that program: group 0, the
// loose uniforms as the members of one uniform buffer in declaration order
// (binding 0), then the shadow map's depth texture followed by its
// comparison sampler. The host math is
// OpenGL's; every vertex entry point ends in `gl_to_target`, umbrac's
// "portable" clip-space adaptation (depth [-w, w] -> [0, w], y mirrored), so
// the rendered image comes out bottom row first and the host flips it.

struct Uniforms {
    u_light_vp: mat4x4<f32>,
    u_model: mat4x4<f32>,
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_light_dir: vec3<f32>,
    u_cam_pos: vec3<f32>,
    u_is_floor: f32,
}
@group(0) @binding(0) var<uniform> uniforms: Uniforms;
@group(0) @binding(1) var shadow_map: texture_depth_2d;
@group(0) @binding(2) var shadow_map_cmp: sampler_comparison;

const SHADOW_TEXEL: f32 = 1.0 / 1024.0;

struct ShadowOut {
    @builtin(position) clip: vec4<f32>,
}

struct MainOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) light_clip: vec4<f32>,
}

// GL clip space to WebGPU's: depth from [-w, w] to [0, w]; y mirrored so a
// texture rendered here is stored bottom row first, as GL stores it.
fn gl_to_target(p: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(p.x, -p.y, 0.5 * (p.z + p.w), p.w);
}

@vertex
fn shadow_vs(@location(0) a_pos: vec3<f32>) -> ShadowOut {
    var out: ShadowOut;
    out.clip = gl_to_target(uniforms.u_light_vp * (uniforms.u_model * vec4<f32>(a_pos, 1.0)));
    return out;
}

@fragment
fn shadow_fs() -> @location(0) vec4<f32> {
    // Nothing reads this: the shadow pass has only a depth attachment.
    return vec4<f32>(1.0);
}

@vertex
fn main_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> MainOut {
    var out: MainOut;
    let world = uniforms.u_model * vec4<f32>(a_pos, 1.0);
    out.world_pos = world.xyz;
    out.world_normal = (uniforms.u_model * vec4<f32>(a_normal, 0.0)).xyz;
    out.light_clip = uniforms.u_light_vp * world;
    out.clip = gl_to_target(uniforms.u_proj * (uniforms.u_view * world));
    return out;
}

// Share of a 3x3 block of depth compares (each a bilinear 2x2) that pass.
fn sunlit_fraction(uv: vec2<f32>, depth: f32) -> f32 {
    var passed = 0.0;
    for (var dy = -1; dy <= 1; dy++) {
        for (var dx = -1; dx <= 1; dx++) {
            let at = uv + vec2<f32>(f32(dx), f32(dy)) * SHADOW_TEXEL;
            passed += textureSampleCompare(shadow_map, shadow_map_cmp, at, depth);
        }
    }
    return passed / 9.0;
}

fn checker(p: vec3<f32>) -> vec3<f32> {
    let cells = floor(p.x * 0.5 + 100.0) + floor(p.z * 0.5 + 100.0);
    let odd = cells - 2.0 * floor(cells * 0.5);
    let grey = select(0.30, 0.85, odd < 0.5);
    return vec3<f32>(grey) * vec3<f32>(0.80, 0.82, 0.88);
}

@fragment
fn main_fs(in: MainOut) -> @location(0) vec4<f32> {
    let n = normalize(in.world_normal);
    let l = normalize(uniforms.u_light_dir);
    let v = normalize(uniforms.u_cam_pos - in.world_pos);
    let n_dot_l = max(dot(n, l), 0.0);

    // The stored depth and the lookup are both in GL's [0, 1] window range.
    let ndc = in.light_clip.xyz / max(in.light_clip.w, 0.0001);
    let uv = ndc.xy * 0.5 + vec2<f32>(0.5);
    let depth = ndc.z * 0.5 + 0.5;
    let bias = max(0.0025 * (1.0 - n_dot_l), 0.0008);
    var sun = sunlit_fraction(uv, depth - bias);
    if (n_dot_l < 0.05) {
        sun = 0.0;
    }

    let sky = n.y * 0.5 + 0.5;
    let ambient = mix(vec3<f32>(0.10, 0.09, 0.08), vec3<f32>(0.30, 0.34, 0.42), vec3<f32>(sky));
    var albedo = vec3<f32>(0.85, 0.45, 0.30);
    var gloss = 0.5;
    if (uniforms.u_is_floor > 0.5) {
        albedo = checker(in.world_pos);
        gloss = 0.15;
    }
    let h = normalize(l + v);
    let spec = pow(max(dot(n, h), 0.0), 48.0) * sun * gloss;
    let sun_rgb = vec3<f32>(1.30, 1.15, 0.90);
    let rgb = albedo * (ambient + sun_rgb * (n_dot_l * sun)) + vec3<f32>(spec);
    return vec4<f32>(rgb, 1.0);
}
