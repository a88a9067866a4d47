diagnostic(off, derivative_uniformity);

struct Sums_atomic {
    weighted: atomic<u32>,
    odd: atomic<u32>,
    adds: atomic<u32>,
}

@id(3) override WEIGHT: u32 = 7u;
@id(4) override COUNT: u32 = 1000u;

@group(0) @binding(0) 
var<storage, read_write> values: array<u32>;
@group(0) @binding(1) 
var<storage, read_write> sums: Sums_atomic;

@compute @workgroup_size(32, 1, 1) 
fn vk_reduce(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    let i = GlobalInvocationID.x;
    let _e6 = values[i];
    let v = select(0u, _e6, (i < COUNT));
    let w = (v * WEIGHT);
    let odd = (v & 1u);
    let _e15 = atomicAdd((&sums.weighted), w);
    let _e17 = atomicAdd((&sums.odd), odd);
    let _e19 = atomicAdd((&sums.adds), 1u);
    return;
}
