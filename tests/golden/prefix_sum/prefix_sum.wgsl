diagnostic(off, derivative_uniformity);

struct Values {
    count: u32,
    data: array<u32>,
}

struct Totals {
    data: array<u32>,
}

const BLOCK: i32 = 128i;

@group(0) @binding(0) 
var<storage> input: Values;
@group(0) @binding(1) 
var<storage, read_write> output: Values;
@group(0) @binding(2) 
var<storage, read_write> totals: Totals;
var<workgroup> scratch: array<u32, 128>;

@compute @workgroup_size(128, 1, 1) 
fn prefix_sum_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>, @builtin(local_invocation_index) LocalInvocationIndex: u32, @builtin(workgroup_id) WorkGroupID: vec3<u32>) {
    var value: u32;
    var offset: u32;
    var add: u32;

    let i = GlobalInvocationID.x;
    value = 0u;
    let _e8 = input.count;
    if (i < _e8) {
        let _e14 = input.data[i];
        value = _e14;
    }
    let _e18 = value;
    scratch[LocalInvocationIndex] = _e18;
    workgroupBarrier();
    offset = 1u;
    loop {
        let _e23 = offset;
        if !((_e23 < u32(BLOCK))) {
            break;
        }
        add = 0u;
        let _e31 = offset;
        if (LocalInvocationIndex >= _e31) {
            let _e36 = offset;
            let _e39 = scratch[(LocalInvocationIndex - _e36)];
            add = _e39;
        }
        workgroupBarrier();
        let _e45 = scratch[LocalInvocationIndex];
        let _e47 = add;
        scratch[LocalInvocationIndex] = (_e45 + _e47);
        workgroupBarrier();
        let _e52 = offset;
        offset = (_e52 * 2u);
    }
    let _e57 = input.count;
    if (i < _e57) {
        let _e64 = scratch[LocalInvocationIndex];
        output.data[i] = _e64;
    }
    if (LocalInvocationIndex == (u32(BLOCK) - 1u)) {
        let _e76 = scratch[LocalInvocationIndex];
        totals.data[WorkGroupID.x] = _e76;
    }
    return;
}
