#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_KHR_shader_subgroup_shuffle_relative : require
#extension GL_KHR_shader_subgroup_quad : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, binding = 0) buffer lanes_ssbo {
    float values[];
} lanes;

layout(std430, binding = 1) buffer masks_ssbo {
    uint bits[];
} masks;


float lane_sum(float v) {
    float _e1 = subgroupAdd(v);
    float _e2 = subgroupInclusiveAdd(v);
    float _e4 = subgroupExclusiveAdd(v);
    return ((_e1 + _e2) - _e4);
}

void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    uint SubgroupInvocationID = gl_SubgroupInvocationID;
    uint SubgroupID = gl_SubgroupID;
    uint SubgroupSize = gl_SubgroupSize;
    uint NumSubgroups = gl_NumSubgroups;
    float r = 0.0;
    uint i = GlobalInvocationID.x;
    float v_1 = lanes.values[i];
    float _e11 = lane_sum(v_1);
    float _e13 = subgroupMul(1.0);
    float _e15 = subgroupMin(v_1);
    float _e17 = subgroupMax(v_1);
    r = (((_e11 * _e13) + _e15) + _e17);
    float _e19 = subgroupBroadcastFirst(v_1);
    float _e21 = subgroupBroadcast(v_1, 0u);
    float _e25 = subgroupShuffle(v_1, (SubgroupInvocationID ^ 1u));
    float _e27 = r;
    r = (_e27 + ((_e19 + _e21) + _e25));
    float _e29 = subgroupShuffleXor(v_1, 1u);
    float _e30 = subgroupShuffleUp(v_1, 1u);
    float _e32 = subgroupShuffleDown(v_1, 1u);
    float _e34 = r;
    r = (_e34 + ((_e29 + _e30) + _e32));
    uvec4 _e38 = subgroupBallot((v_1 > 0.5));
    uint _e40 = subgroupAnd(uint(v_1));
    uint _e42 = subgroupOr(_e38.x);
    int _e44 = subgroupXor(int(i));
    uint mask = (_e40 | (_e42 ^ uint(_e44)));
    uint _e48 = subgroupExclusiveAdd(1u);
    bool _e52 = subgroupAll((v_1 >= 0.0));
    bool _e54 = subgroupAny((v_1 < 0.0));
    if (((_e48 == 0u) && (_e52 || _e54))) {
        masks.bits[SubgroupID] = (mask + (SubgroupSize * NumSubgroups));
    }
    float _e64 = r;
    lanes.values[i] = _e64;
    return;
}

