#version 300 es

precision highp float;
precision highp int;

struct Frame {
    mat4x4 view_proj;
    vec4 tint;
};
struct Model {
    mat4x4 model;
    int layer;
};
struct depth_vs_out {
    vec4 gen_gl_Position;
};
layout(std140) uniform frame_ubo {
    mat4x4 view_proj;
    vec4 tint;
} frame;

layout(std140) uniform model_ubo {
    mat4x4 model;
    int layer;
} model;

layout(location = 0) in vec3 a_pos;

void main() {
    vec3 in_a_pos = a_pos;
    vec4 gen_gl_Position = vec4(0.0);
    mat4x4 _e4 = frame.view_proj;
    mat4x4 _e7 = model.model;
    gen_gl_Position = ((_e4 * _e7) * vec4(in_a_pos, 1.0));
    vec4 _e12 = gen_gl_Position;
    depth_vs_out _tmp_return = depth_vs_out(vec4(_e12.x, _e12.y, ((_e12.z * 2.0) - _e12.w), _e12.w));
    gl_Position = _tmp_return.gen_gl_Position;
    return;
}

