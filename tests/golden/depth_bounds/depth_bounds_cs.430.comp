#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct View {
    mat4x4 inv_view_proj;
    mat4x4 light_view;
    ivec2 size;
};
struct Bounds_atomic {
    int lo[3];
    int hi[3];
    uint count;
};
layout(std430, binding = 0) readonly buffer view_ssbo { View view; };

layout(std430, binding = 1) buffer bounds_ssbo { Bounds_atomic bounds; };

layout(binding = 0,r32f) readonly uniform image2D depth;

shared int lo[3];

shared int hi[3];

shared uint seen;


int key(float f) {
    int b = floatBitsToInt(f);
    return ((b >= 0) ? b : (b ^ 2147483647));
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        lo = int[3](0, 0, 0);
        hi = int[3](0, 0, 0);
        seen = 0u;
    }
    memoryBarrierShared();
    barrier();
    uint LocalInvocationIndex = gl_LocalInvocationIndex;
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    int i = 0;
    if ((LocalInvocationIndex < 3u)) {
        int _e7 = atomicExchange(lo[LocalInvocationIndex], 2147483647);
        int _e13 = atomicExchange(hi[LocalInvocationIndex], (-(2147483647) - 1));
    }
    if ((LocalInvocationIndex == 0u)) {
        uint _e17 = atomicExchange(seen, 0u);
    }
    memoryBarrierShared();
    barrier();
    ivec2 p = ivec2(GlobalInvocationID.xy);
    int _e25 = view.size.x;
    int _e30 = view.size.y;
    if (((p.x < _e25) && (p.y < _e30))) {
        vec4 _e34 = imageLoad(depth, p);
        float d = _e34.x;
        if ((d < 1.0)) {
            ivec2 _e43 = view.size;
            vec2 uv = ((vec2(p) + vec2(0.5)) / vec2(_e43));
            vec4 ndc = vec4(((uv * 2.0) - vec2(1.0)), ((d * 2.0) - 1.0), 1.0);
            mat4x4 _e54 = view.inv_view_proj;
            vec4 world = (_e54 * ndc);
            mat4x4 _e57 = view.light_view;
            vec4 light = (_e57 * vec4((world.xyz / vec3(world.w)), 1.0));
            i = 0;
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    int _e82 = i;
                    i = (_e82 + 1);
                }
                loop_init = false;
                int _e67 = i;
                if (!((_e67 < 3))) {
                    break;
                }
                int _e70 = i;
                int _e72 = i;
                int _e74 = key(light[_e72]);
                int _e75 = atomicMin(lo[_e70], _e74);
                int _e76 = i;
                int _e78 = i;
                int _e80 = key(light[_e78]);
                int _e81 = atomicMax(hi[_e76], _e80);
            }
            uint _e85 = atomicAdd(seen, 1u);
        }
    }
    memoryBarrierShared();
    barrier();
    if ((LocalInvocationIndex < 3u)) {
        int _e91 = atomicOr(lo[LocalInvocationIndex], 0);
        int _e92 = atomicMin(bounds.lo[LocalInvocationIndex], _e91);
        int _e96 = atomicOr(hi[LocalInvocationIndex], 0);
        int _e97 = atomicMax(bounds.hi[LocalInvocationIndex], _e96);
    }
    if ((LocalInvocationIndex == 0u)) {
        uint _e100 = atomicOr(seen, 0u);
        uint _e101 = atomicAdd(bounds.count, _e100);
    }
    return;
}

