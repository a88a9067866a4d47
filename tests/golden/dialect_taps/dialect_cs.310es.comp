#version 310 es

precision highp float;
precision highp int;

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0,rgba8) writeonly uniform highp image2D c_destTex;

layout(std430, binding = 1) buffer taps_ssbo {
    float gain;
    float weights[4];
    uint bits[];
} taps;


void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    float s = 0.0;
    int n = 0;
    int i = 0;
    ivec2 p = ivec2(GlobalInvocationID.xy);
    ivec2 size = ivec2(uvec2(imageSize(c_destTex).xy));
    if (((p.x >= size.x) || (p.y >= size.y))) {
        return;
    }
    s = 0.0;
    n = 0;
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e47 = i;
            i = (_e47 + 1);
        }
        loop_init = false;
        int _e19 = i;
        if (!((_e19 < 4))) {
            break;
        }
        int _e23 = i;
        if ((((p.x >> uint(_e23)) & 1) == 1)) {
            int _e31 = i;
            float _e33 = taps.weights[_e31];
            float _e34 = s;
            s = (_e34 + _e33);
        }
        int _e37 = i;
        if ((((p.y >> uint(_e37)) & 1) == 1)) {
            int _e42 = i;
            int _e45 = n;
            n = (_e45 + (1 << uint(_e42)));
        }
    }
    int _e56 = n;
    taps.bits[((p.y * size.x) + p.x)] = floatBitsToUint(float(_e56));
    float _e59 = s;
    float _e61 = taps.gain;
    imageStore(c_destTex, p, vec4((_e59 * _e61), (float((p.y - (3 * (p.y / 3)))) / 2.0), 0.25, 1.0));
    return;
}

