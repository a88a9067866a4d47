diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_view_proj: mat4x4<f32>,
    u_time: f32,
    u_size: f32,
    u_gravity: vec3<f32>,
}

struct particles_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_age: f32,
    @location(1) v_color: vec4<f32>,
}

struct particles_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var sprite: texture_2d<f32>;
@group(0) @binding(2) 
var sprite_sampler: sampler;

@vertex 
fn particles_vs(@location(0) a_origin: vec3<f32>, @location(1) a_velocity: vec3<f32>, @location(2) a_birth: f32, @location(3) a_life: f32) -> particles_vs_out {
    var v_age: f32;
    var v_color: vec4<f32>;
    var gl_PointSize: f32;
    var gl_Position: vec4<f32>;

    let _e6 = uniforms.u_time;
    let _e7 = (_e6 - a_birth);
    let t = (_e7 - (a_life * floor((_e7 / a_life))));
    v_age = (t / a_life);
    let _e17 = uniforms.u_gravity;
    let p = ((a_origin + (a_velocity * t)) + (_e17 * ((0.5f * t) * t)));
    let _e24 = uniforms.u_view_proj;
    let clip = (_e24 * vec4<f32>(p, 1f));
    let _e30 = uniforms.u_size;
    let _e31 = v_age;
    gl_PointSize = clamp(((_e30 * (1f - (_e31 * 0.5f))) / max(clip.w, 0.001f)), 1f, 64f);
    let _e49 = v_age;
    v_color = mix(vec4<f32>(1f, 0.9f, 0.5f, 1f), vec4<f32>(0.8f, 0.2f, 0.1f, 0f), vec4(_e49));
    gl_Position = clip;
    let _e53 = gl_Position;
    let _e62 = v_age;
    let _e63 = v_color;
    return particles_vs_out(vec4<f32>(_e53.x, -(_e53.y), ((_e53.z + _e53.w) * 0.5f), _e53.w), _e62, _e63);
}

@fragment 
fn particles_fs(@location(1) v_color_1: vec4<f32>) -> particles_fs_out {
    var f_color: vec4<f32>;

    let _e1 = vec2(0.5f);
    let d = ((_e1 * 2f) - vec2(1f));
    let r2_ = dot(d, d);
    if (r2_ > 1f) {
        discard;
    }
    let tex = textureSample(sprite, sprite_sampler, _e1);
    let alpha = ((v_color_1.w * tex.w) * (1f - r2_));
    if (alpha < 0.01f) {
        discard;
    }
    f_color = vec4<f32>((v_color_1.xyz * tex.xyz), alpha);
    let _e25 = f_color;
    return particles_fs_out(_e25);
}
