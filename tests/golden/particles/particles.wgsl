diagnostic(off, derivative_uniformity);

struct particles_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_age: f32,
    @location(1) v_color: vec4<f32>,
}

struct particles_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_view_proj: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_time: f32;
@group(0) @binding(2) 
var<uniform> u_size: f32;
@group(0) @binding(3) 
var<uniform> u_gravity: vec3<f32>;
@group(0) @binding(4) 
var sprite: texture_2d<f32>;
@group(0) @binding(5) 
var sprite_sampler: sampler;
var<private> a_origin: vec3<f32>;
var<private> a_velocity: vec3<f32>;
var<private> a_birth: f32;
var<private> a_life: f32;
var<private> v_age: f32;
var<private> v_color: vec4<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_PointSize: f32;
var<private> gl_Position: vec4<f32>;
var<private> gl_PointCoord: vec2<f32>;

@vertex 
fn particles_vs(@location(0) in_a_origin: vec3<f32>, @location(1) in_a_velocity: vec3<f32>, @location(2) in_a_birth: f32, @location(3) in_a_life: f32) -> particles_vs_out {
    a_origin = in_a_origin;
    a_velocity = in_a_velocity;
    a_birth = in_a_birth;
    a_life = in_a_life;
    let _e9 = u_time;
    let _e11 = a_birth;
    let _e12 = (_e9 - _e11);
    let _e14 = a_life;
    let t = (_e12 - (_e14 * floor((_e12 / _e14))));
    let _e21 = a_life;
    v_age = (t / _e21);
    let _e24 = a_origin;
    let _e26 = a_velocity;
    let _e30 = u_gravity;
    let p = ((_e24 + (_e26 * t)) + (_e30 * ((0.5f * t) * t)));
    let _e37 = u_view_proj;
    let clip = (_e37 * vec4<f32>(p, 1f));
    let _e43 = u_size;
    let _e46 = v_age;
    gl_PointSize = clamp(((_e43 * (1f - (_e46 * 0.5f))) / max(clip.w, 0.001f)), 1f, 64f);
    let _e70 = v_age;
    v_color = mix(vec4<f32>(1f, 0.9f, 0.5f, 1f), vec4<f32>(0.8f, 0.2f, 0.1f, 0f), vec4(_e70));
    gl_Position = clip;
    let _e75 = gl_Position;
    let _e86 = v_age;
    let _e88 = v_color;
    return particles_vs_out(vec4<f32>(_e75.x, -(_e75.y), ((_e75.z + _e75.w) * 0.5f), _e75.w), _e86, _e88);
}

@fragment 
fn particles_fs(@location(1) in_v_color: vec4<f32>) -> particles_fs_out {
    gl_PointCoord = vec2(0.5f);
    v_color = in_v_color;
    let _e6 = gl_PointCoord;
    let d = ((_e6 * 2f) - vec2(1f));
    let r2_ = dot(d, d);
    if (r2_ > 1f) {
        discard;
    }
    let _e16 = gl_PointCoord;
    let tex = textureSample(sprite, sprite_sampler, _e16);
    let _e22 = v_color.w;
    let alpha = ((_e22 * tex.w) * (1f - r2_));
    if (alpha < 0.01f) {
        discard;
    }
    let _e32 = v_color;
    f_color = vec4<f32>((_e32.xyz * tex.xyz), alpha);
    let _e38 = f_color;
    return particles_fs_out(_e38);
}
