diagnostic(off, derivative_uniformity);

struct Particle {
    pos: vec4<f32>,
    vel: vec4<f32>,
}

struct Step {
    dt: f32,
    count: u32,
}

@group(0) @binding(0) 
var<storage, read_write> particles: array<Particle>;
@group(0) @binding(1) 
var heat: texture_storage_2d<rgba8unorm,write>;
@group(0) @binding(2) 
var<storage, read_write> moving: array<atomic<u32>>;
@group(0) @binding(3) 
var<uniform> step_: Step;

@compute @workgroup_size(64, 1, 1) 
fn advance(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    var p: Particle;

    let i = GlobalInvocationID.x;
    let _e4 = step_.count;
    if (i >= _e4) {
        return;
    }
    let _e9 = particles[i];
    p = _e9;
    let _e12 = p.vel;
    let _e14 = step_.dt;
    let _e16 = p.pos;
    p.pos = (_e16 + (_e12 * _e14));
    let _e19 = p;
    particles[i] = _e19;
    let _e21 = p.vel;
    let _e23 = p.vel;
    if (dot(_e21, _e23) > 0f) {
        let _e30 = atomicAdd((&moving[0]), 1u);
    }
    let _e39 = p.pos;
    textureStore(heat, vec2<i32>(i32((i % 64u)), i32((i / 64u))), vec4<f32>(_e39.xyz, 1f));
    return;
}

@compute @workgroup_size(1, 1, 1) 
fn clear_cs(@builtin(global_invocation_id) GlobalInvocationID_1: vec3<u32>) {
    particles[GlobalInvocationID_1.x].vel = vec4(0f);
    return;
}
