diagnostic(off, derivative_uniformity);

struct Input {
    count: u32,
    data: array<u32>,
}

struct Totals_atomic {
    sum: atomic<u32>,
    largest: atomic<u32>,
    adds: atomic<u32>,
}

@id(0) override SCALE: u32 = 3u;

@group(0) @binding(0) 
var<storage> input: Input;
@group(0) @binding(1) 
var<storage, read_write> totals: Totals_atomic;

@compute @workgroup_size(64, 1, 1) 
fn reduce_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    let i = GlobalInvocationID.x;
    let _e4 = input.count;
    let _e8 = input.data[i];
    let v = select(0u, (_e8 * SCALE), (i < _e4));
    let _e15 = atomicAdd((&totals.sum), v);
    let _e17 = atomicMax((&totals.largest), v);
    let _e20 = atomicAdd((&totals.adds), 1u);
    return;
}
