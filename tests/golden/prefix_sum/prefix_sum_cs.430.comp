#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 128, local_size_y = 1, local_size_z = 1) in;

const int BLOCK = 128;

layout(std430, binding = 0) readonly buffer input_ssbo {
    uint count;
    uint data[];
} input_;

layout(std430, binding = 1) buffer output_ssbo {
    uint count;
    uint data[];
} output_;

layout(std430, binding = 2) buffer totals_ssbo {
    uint data[];
} totals;

shared uint scratch[128];


void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        scratch = uint[128](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    uint LocalInvocationIndex = gl_LocalInvocationIndex;
    uvec3 WorkGroupID = gl_WorkGroupID;
    uint value = 0u;
    uint offset = 0u;
    uint add = 0u;
    uint i = GlobalInvocationID.x;
    value = 0u;
    uint _e8 = input_.count;
    if ((i < _e8)) {
        uint _e14 = input_.data[i];
        value = _e14;
    }
    uint _e18 = value;
    scratch[LocalInvocationIndex] = _e18;
    memoryBarrierShared();
    barrier();
    offset = 1u;
    while(true) {
        uint _e23 = offset;
        if (!((_e23 < uint(BLOCK)))) {
            break;
        }
        add = 0u;
        uint _e31 = offset;
        if ((LocalInvocationIndex >= _e31)) {
            uint _e36 = offset;
            uint _e39 = scratch[(LocalInvocationIndex - _e36)];
            add = _e39;
        }
        memoryBarrierShared();
        barrier();
        uint _e45 = scratch[LocalInvocationIndex];
        uint _e47 = add;
        scratch[LocalInvocationIndex] = (_e45 + _e47);
        memoryBarrierShared();
        barrier();
        uint _e52 = offset;
        offset = (_e52 * 2u);
    }
    uint _e57 = input_.count;
    if ((i < _e57)) {
        uint _e64 = scratch[LocalInvocationIndex];
        output_.data[i] = _e64;
    }
    if ((LocalInvocationIndex == (uint(BLOCK) - 1u))) {
        uint _e76 = scratch[LocalInvocationIndex];
        totals.data[WorkGroupID.x] = _e76;
    }
    return;
}

