#version 300 es

precision highp float;
precision highp int;

struct rings_fs_out {
    vec4 f_color;
};
const float RING_WIDTH = 0.25;
const int RINGS = 4;
const vec3 COOL = vec3(0.2, 0.4, 1.0);
const vec3 WARM = vec3(1.0, 0.6, 0.3);

int rings_seen = 0;

float glow = 0.0;

float fade = 1.0;

uniform float pc_time;

in vec2 v_uv;
out vec4 f_color;

void visit_ring(float d) {
    int _e2 = rings_seen;
    if ((d < (float((_e2 + 1)) * RING_WIDTH))) {
        float _e14 = glow;
        glow = (_e14 + (1.0 / float(RINGS)));
    }
    int _e16 = rings_seen;
    rings_seen = (_e16 + 1);
    float _e20 = fade;
    fade = (_e20 * 0.9);
    return;
}

void main() {
    vec2 in_v_uv = v_uv;
    vec4 out_f_color = vec4(0.0);
    int i = 0;
    float d_1 = (length((in_v_uv - vec2(0.5))) * 2.0);
    i = 0;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e19 = i;
            i = (_e19 + 1);
        }
        loop_init = false;
        int _e10 = i;
        if (!((_e10 < RINGS))) {
            break;
        }
        float _e15 = pc_time;
        visit_ring((d_1 + (0.01 * sin(_e15))));
    }
    float _e25 = glow;
    vec3 c = mix(COOL, WARM, vec3(_e25));
    float _e30 = fade;
    int _e33 = rings_seen;
    out_f_color = vec4((c * _e30), (float(_e33) / float(RINGS)));
    vec4 _e38 = out_f_color;
    rings_fs_out _tmp_return = rings_fs_out(_e38);
    f_color = _tmp_return.f_color;
    return;
}

