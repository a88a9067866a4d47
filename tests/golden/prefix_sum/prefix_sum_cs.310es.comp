#version 310 es

precision highp float;
precision highp int;

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
        uint _e12 = input_.data[i];
        value = _e12;
    }
    uint _e15 = value;
    scratch[LocalInvocationIndex] = _e15;
    memoryBarrierShared();
    barrier();
    offset = 1u;
    while(true) {
        uint _e19 = offset;
        if (!((_e19 < uint(BLOCK)))) {
            break;
        }
        add = 0u;
        uint _e25 = offset;
        if ((LocalInvocationIndex >= _e25)) {
            uint _e27 = offset;
            uint _e30 = scratch[(LocalInvocationIndex - _e27)];
            add = _e30;
        }
        memoryBarrierShared();
        barrier();
        uint _e33 = scratch[LocalInvocationIndex];
        uint _e34 = add;
        scratch[LocalInvocationIndex] = (_e33 + _e34);
        memoryBarrierShared();
        barrier();
        uint _e36 = offset;
        offset = (_e36 * 2u);
    }
    uint _e40 = input_.count;
    if ((i < _e40)) {
        uint _e46 = scratch[LocalInvocationIndex];
        output_.data[i] = _e46;
    }
    if ((LocalInvocationIndex == (uint(BLOCK) - 1u))) {
        uint _e55 = scratch[LocalInvocationIndex];
        totals.data[WorkGroupID.x] = _e55;
    }
    return;
}

