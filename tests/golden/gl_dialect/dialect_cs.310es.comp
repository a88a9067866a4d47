#version 310 es

precision highp float;
precision highp int;

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0,rgba8) writeonly uniform highp image2D c_destTex;

layout(binding = 3,r32f) writeonly uniform highp image2D c_levels;

layout(binding = 1,r32f) readonly uniform highp image2D c_source;

layout(binding = 2,r32ui) uniform highp uimage2D c_counts;

layout(std430, binding = 2) buffer weights_ssbo {
    float gain;
    float taps[4];
    uint data[];
} weights;

layout(std430, binding = 0) readonly buffer scale_ssbo {
    float gain;
    float taps[4];
    uint data[];
} scale;


int classify(int x) {
    if ((x < 0)) {
        return -(1);
    } else {
        if ((x == 0)) {
            return 0;
        }
    }
    if ((x > 100)) {
        return 2;
    } else {
        return 1;
    }
}

int steps(int n) {
    int i = 0;
    int s = 0;
    int k = 0;
    i = 0;
    s = 0;
    while(true) {
        int _e4 = i;
        if (!((_e4 < n))) {
            break;
        }
        int _e8 = i;
        i = (_e8 + 1);
    }
    k = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e18 = k;
            k = (_e18 + 1);
        }
        loop_init = false;
        int _e12 = k;
        if (!((_e12 < 4))) {
            break;
        }
        int _e15 = k;
        int _e16 = s;
        s = (_e16 + _e15);
    }
    int _e20 = s;
    if ((_e20 > 100)) {
        s = 100;
    } else {
        int _e23 = i;
        int _e24 = s;
        s = (_e24 + _e23);
    }
    int _e26 = s;
    return _e26;
}

float tapped(ivec2 p) {
    float s_1 = 0.0;
    int i_1 = 0;
    int i_2 = 0;
    int i_3 = 0;
    s_1 = 0.0;
    i_1 = 0;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            int _e23 = i_1;
            i_1 = (_e23 + 1);
        }
        loop_init_1 = false;
        int _e6 = i_1;
        if (!((_e6 < 4))) {
            break;
        }
        int _e10 = i_1;
        if ((((p.x >> uint(_e10)) & 1) == 1)) {
            int _e18 = i_1;
            float _e20 = weights.taps[_e18];
            float _e21 = s_1;
            s_1 = (_e21 + _e20);
        }
    }
    i_2 = 0;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            int _e33 = i_2;
            i_2 = (_e33 + 1);
        }
        loop_init_2 = false;
        int _e27 = i_2;
        if (!((_e27 < 2))) {
            break;
        }
        float _e31 = s_1;
        s_1 = (_e31 * 1.0);
    }
    i_3 = 1;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            int _e45 = i_3;
            i_3 = (_e45 + 1);
        }
        loop_init_3 = false;
        int _e37 = i_3;
        if (!((_e37 < 3))) {
            break;
        }
        int _e40 = i_3;
        float _e43 = s_1;
        s_1 = (_e43 + (0.0 * float(_e40)));
    }
    float _e47 = s_1;
    float _e49 = weights.gain;
    return (_e47 * _e49);
}

void main() {
    uvec3 GlobalInvocationID = gl_GlobalInvocationID;
    ivec2 p_1 = ivec2(GlobalInvocationID.xy);
    ivec2 size = ivec2(uvec2(imageSize(c_destTex).xy));
    if (((p_1.x >= size.x) || (p_1.y >= size.y))) {
        return;
    }
    vec4 _e14 = imageLoad(c_source, p_1);
    uint bits = floatBitsToUint(_e14.x);
    float back = uintBitsToFloat(bits);
    uvec4 c = imageLoad(c_counts, p_1);
    int _e23 = classify((p_1.x - 1));
    int _e25 = steps(p_1.y);
    imageStore(c_counts, p_1, (c + uvec4(uint((_e23 + _e25)))));
    uint _e39 = scale.data[0];
    weights.data[uint(p_1.x)] = (bits ^ _e39);
    imageStore(c_levels, p_1, vec4(back));
    float _e43 = tapped(p_1);
    imageStore(c_destTex, p_1, vec4(_e43, back, intBitsToFloat(ivec3(0)).x, 1.0));
    return;
}

