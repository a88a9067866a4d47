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
        let _e12 = input.data[i];
        value = _e12;
    }
    let _e15 = value;
    scratch[LocalInvocationIndex] = _e15;
    workgroupBarrier();
    offset = 1u;
    loop {
        let _e19 = offset;
        if !((_e19 < u32(BLOCK))) {
            break;
        }
        add = 0u;
        let _e25 = offset;
        if (LocalInvocationIndex >= _e25) {
            let _e27 = offset;
            let _e30 = scratch[(LocalInvocationIndex - _e27)];
            add = _e30;
        }
        workgroupBarrier();
        let _e33 = scratch[LocalInvocationIndex];
        let _e34 = add;
        scratch[LocalInvocationIndex] = (_e33 + _e34);
        workgroupBarrier();
        let _e36 = offset;
        offset = (_e36 * 2u);
    }
    let _e40 = input.count;
    if (i < _e40) {
        let _e46 = scratch[LocalInvocationIndex];
        output.data[i] = _e46;
    }
    if (LocalInvocationIndex == (u32(BLOCK) - 1u)) {
        let _e55 = scratch[LocalInvocationIndex];
        totals.data[WorkGroupID.x] = _e55;
    }
    return;
}
