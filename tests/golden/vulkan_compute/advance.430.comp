#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Particle {
    vec4 pos;
    vec4 vel;
};
struct Step {
    float dt;
    uint count;
};
layout(std430, binding = 0) buffer particles_ssbo { Particle particles[]; };

layout(binding = 0,rgba8) writeonly uniform image2D heat;

layout(std430, binding = 1) buffer moving_ssbo { uint moving[]; };

layout(std140) uniform step_ubo {
    float dt;
    uint count;
} step_;


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    Particle p = Particle(vec4(0.0), vec4(0.0));
    uint i = GlobalInvocationID.x;
    uint _e4 = step_.count;
    if ((i >= _e4)) {
        return;
    }
    Particle _e9 = particles[i];
    p = _e9;
    vec4 _e12 = p.vel;
    float _e14 = step_.dt;
    vec4 _e16 = p.pos;
    p.pos = (_e16 + (_e12 * _e14));
    Particle _e19 = p;
    particles[i] = _e19;
    vec4 _e21 = p.vel;
    vec4 _e23 = p.vel;
    if ((dot(_e21, _e23) > 0.0)) {
        uint _e30 = atomicAdd(moving[0], 1u);
    }
    vec4 _e39 = p.pos;
    imageStore(heat, ivec2(int((i % 64u)), int((i / 64u))), vec4(_e39.xyz, 1.0));
    return;
}

