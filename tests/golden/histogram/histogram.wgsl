diagnostic(off, derivative_uniformity);

struct Samples {
    count: u32,
    data: array<u32>,
}

struct Histogram_atomic {
    total: atomic<u32>,
    largest: atomic<u32>,
    bins: array<atomic<u32>, 64>,
}

const BINS: i32 = 64i;

@group(0) @binding(0) 
var<storage> samples: Samples;
@group(0) @binding(1) 
var<storage, read_write> histogram: Histogram_atomic;
var<workgroup> local_bins: array<atomic<u32>, 64>;

@compute @workgroup_size(64, 1, 1) 
fn histogram_cs(@builtin(local_invocation_index) LocalInvocationIndex: u32, @builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    atomicStore((&local_bins[LocalInvocationIndex]), 0u);
    workgroupBarrier();
    let i = GlobalInvocationID.x;
    let _e9 = samples.count;
    if (i < _e9) {
        let v = samples.data[i];
        let _e19 = atomicAdd((&local_bins[(v % u32(BINS))]), 1u);
        let _e22 = atomicMax((&histogram.largest), v);
    }
    workgroupBarrier();
    let n = atomicLoad((&local_bins[LocalInvocationIndex]));
    if (n > 0u) {
        let _e28 = atomicAdd((&histogram.bins[LocalInvocationIndex]), n);
        let _e30 = atomicAdd((&histogram.total), n);
    }
    return;
}
