#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

struct Particle {
    vec4 pos;
    vec4 vel;
};
layout(std430, binding = 0) buffer particles_ssbo { Particle particles[]; };


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    particles[GlobalInvocationID.x].vel = vec4(0.0);
    return;
}

