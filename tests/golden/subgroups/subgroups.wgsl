enable subgroups;
diagnostic(off, subgroup_uniformity);
diagnostic(off, derivative_uniformity);

struct Lanes {
    values: array<f32>,
}

struct Masks {
    bits: array<u32>,
}

@group(0) @binding(0) 
var<storage, read_write> lanes: Lanes;
@group(0) @binding(1) 
var<storage, read_write> masks: Masks;

fn lane_sum(v: f32) -> f32 {
    let _e1 = subgroupAdd(v);
    let _e2 = subgroupInclusiveAdd(v);
    let _e4 = subgroupExclusiveAdd(v);
    return ((_e1 + _e2) - _e4);
}

@compute @workgroup_size(64, 1, 1) 
fn subgroup_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>, @builtin(subgroup_invocation_id) SubgroupInvocationID: u32, @builtin(subgroup_id) SubgroupID: u32, @builtin(subgroup_size) SubgroupSize: u32, @builtin(num_subgroups) NumSubgroups: u32) {
    var r: f32;

    let i = GlobalInvocationID.x;
    let v_1 = lanes.values[i];
    let _e11 = lane_sum(v_1);
    let _e13 = subgroupMul(1f);
    let _e15 = subgroupMin(v_1);
    let _e17 = subgroupMax(v_1);
    r = (((_e11 * _e13) + _e15) + _e17);
    let _e19 = subgroupBroadcastFirst(v_1);
    let _e21 = subgroupBroadcast(v_1, 0u);
    let _e25 = subgroupShuffle(v_1, (SubgroupInvocationID ^ 1u));
    let _e27 = r;
    r = (_e27 + ((_e19 + _e21) + _e25));
    let _e29 = subgroupShuffleXor(v_1, 1u);
    let _e30 = subgroupShuffleUp(v_1, 1u);
    let _e32 = subgroupShuffleDown(v_1, 1u);
    let _e34 = r;
    r = (_e34 + ((_e29 + _e30) + _e32));
    let _e38 = subgroupBallot((v_1 > 0.5f));
    let _e40 = subgroupAnd(u32(v_1));
    let _e42 = subgroupOr(_e38.x);
    let _e44 = subgroupXor(i32(i));
    let mask = (_e40 | (_e42 ^ u32(_e44)));
    let _e48 = subgroupExclusiveAdd(1u);
    let _e52 = subgroupAll((v_1 >= 0f));
    let _e54 = subgroupAny((v_1 < 0f));
    if ((_e48 == 0u) && (_e52 || _e54)) {
        masks.bits[SubgroupID] = (mask + (SubgroupSize * NumSubgroups));
    }
    let _e64 = r;
    lanes.values[i] = _e64;
    return;
}
