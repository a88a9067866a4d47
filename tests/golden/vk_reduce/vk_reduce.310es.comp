#version 310 es

precision highp float;
precision highp int;

layout(local_size_x = 32, local_size_y = 1, local_size_z = 1) in;

struct Sums_atomic {
    uint weighted;
    uint odd;
    uint adds;
};
const uint WEIGHT = 7u;
const uint COUNT = 1000u;

layout(std430, binding = 0) buffer values_ssbo { uint values[]; };

layout(std430, binding = 1) buffer sums_ssbo { Sums_atomic sums; };


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    uint i = GlobalInvocationID.x;
    uint _e6 = values[i];
    uint v = ((i < COUNT) ? _e6 : 0u);
    uint w = (v * WEIGHT);
    uint odd = (v & 1u);
    uint _e15 = atomicAdd(sums.weighted, w);
    uint _e17 = atomicAdd(sums.odd, odd);
    uint _e19 = atomicAdd(sums.adds, 1u);
    return;
}

