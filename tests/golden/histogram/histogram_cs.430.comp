#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Histogram_atomic {
    uint total;
    uint largest;
    uint bins[64];
};
const int BINS = 64;

layout(std430, binding = 0) readonly buffer samples_ssbo {
    uint count;
    uint data[];
} samples;

layout(std430, binding = 1) buffer histogram_ssbo { Histogram_atomic histogram; };

shared uint local_bins[64];


void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        local_bins = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uint LocalInvocationIndex = gl_LocalInvocationIndex;
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    atomicExchange(local_bins[LocalInvocationIndex], 0u);
    memoryBarrierShared();
    barrier();
    uint i = GlobalInvocationID.x;
    uint _e9 = samples.count;
    if ((i < _e9)) {
        uint v = samples.data[i];
        uint _e19 = atomicAdd(local_bins[(v % uint(BINS))], 1u);
        uint _e22 = atomicMax(histogram.largest, v);
    }
    memoryBarrierShared();
    barrier();
    uint n = atomicOr(local_bins[LocalInvocationIndex], 0u);
    if ((n > 0u)) {
        uint _e28 = atomicAdd(histogram.bins[LocalInvocationIndex], n);
        uint _e30 = atomicAdd(histogram.total, n);
    }
    return;
}

