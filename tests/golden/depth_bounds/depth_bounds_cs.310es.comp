#version 310 es

precision highp float;
precision highp int;

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

layout(binding = 0,r32f) readonly uniform highp image2D depth;

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
        int _e14 = atomicExchange(hi[LocalInvocationIndex], (-(2147483647) - 1));
    }
    if ((LocalInvocationIndex == 0u)) {
        uint _e19 = atomicExchange(seen, 0u);
    }
    memoryBarrierShared();
    barrier();
    ivec2 p = ivec2(GlobalInvocationID.xy);
    int _e27 = view.size.x;
    int _e33 = view.size.y;
    if (((p.x < _e27) && (p.y < _e33))) {
        vec4 _e37 = imageLoad(depth, p);
        float d = _e37.x;
        if ((d < 1.0)) {
            ivec2 _e47 = view.size;
            vec2 uv = ((vec2(p) + vec2(0.5)) / vec2(_e47));
            vec4 ndc = vec4(((uv * 2.0) - vec2(1.0)), ((d * 2.0) - 1.0), 1.0);
            mat4x4 _e63 = view.inv_view_proj;
            vec4 world = (_e63 * ndc);
            mat4x4 _e67 = view.light_view;
            vec4 light = (_e67 * vec4((world.xyz / vec3(world.w)), 1.0));
            i = 0;
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    int _e99 = i;
                    i = (_e99 + 1);
                }
                loop_init = false;
                int _e78 = i;
                if (!((_e78 < 3))) {
                    break;
                }
                int _e83 = i;
                int _e86 = i;
                int _e88 = key(light[_e86]);
                int _e89 = atomicMin(lo[_e83], _e88);
                int _e92 = i;
                int _e95 = i;
                int _e97 = key(light[_e95]);
                int _e98 = atomicMax(hi[_e92], _e97);
            }
            uint _e104 = atomicAdd(seen, 1u);
        }
    }
    memoryBarrierShared();
    barrier();
    if ((LocalInvocationIndex < 3u)) {
        int _e113 = atomicOr(lo[LocalInvocationIndex], 0);
        int _e114 = atomicMin(bounds.lo[LocalInvocationIndex], _e113);
        int _e120 = atomicOr(hi[LocalInvocationIndex], 0);
        int _e121 = atomicMax(bounds.hi[LocalInvocationIndex], _e120);
    }
    if ((LocalInvocationIndex == 0u)) {
        uint _e127 = atomicOr(seen, 0u);
        uint _e128 = atomicAdd(bounds.count, _e127);
    }
    return;
}

