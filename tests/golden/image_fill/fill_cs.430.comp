#version 430 core
#extension GL_ARB_compute_shader : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0,rgba8) writeonly uniform image2D out_image;


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    ivec2 p = ivec2(GlobalInvocationID.xy);
    ivec2 size = ivec2(uvec2(imageSize(out_image).xy));
    if (((p.x >= size.x) || (p.y >= size.y))) {
        return;
    }
    vec2 uv = ((vec2(p) + vec2(0.5)) / vec2(size));
    int _e24 = ((p.x / 4) + (p.y / 4));
    float checker = float((_e24 - (2 * (_e24 / 2))));
    imageStore(out_image, p, vec4(uv.x, uv.y, checker, 1.0));
    return;
}

