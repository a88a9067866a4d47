#version 310 es

precision highp float;
precision highp int;

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Totals_atomic {
    uint sum;
    uint largest;
    uint adds;
};
const uint SCALE = 3u;

layout(std430, binding = 0) readonly buffer input_ssbo {
    uint count;
    uint data[];
} input_;

layout(std430, binding = 1) buffer totals_ssbo { Totals_atomic totals; };


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    uint i = GlobalInvocationID.x;
    uint _e4 = input_.count;
    uint _e8 = input_.data[i];
    uint v = ((i < _e4) ? (_e8 * SCALE) : 0u);
    uint _e15 = atomicAdd(totals.sum, v);
    uint _e17 = atomicMax(totals.largest, v);
    uint _e20 = atomicAdd(totals.adds, 1u);
    return;
}

