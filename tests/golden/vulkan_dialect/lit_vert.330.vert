#version 330 core
struct Frame {
    mat4x4 view_proj;
    vec4 tint;
};
struct Model {
    mat4x4 model;
    int layer;
};
struct lit_vert_out {
    vec4 gen_gl_Position;
    vec2 v_uv;
    float v_depth;
    int v_layer;
    float v_weight;
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
layout(location = 1) in vec2 a_uv;
out vec2 vk_location0;
out float vk_location1;
flat out int vk_location2;
flat out float vk_location3;

void main() {
    vec3 in_a_pos = a_pos;
    vec2 in_a_uv = a_uv;
    uint VertexID = uint(gl_VertexID);
    vec2 out_v_uv = vec2(0.0);
    float out_v_depth = 0.0;
    int out_v_layer = 0;
    float out_v_weight = 0.0;
    vec4 gen_gl_Position = vec4(0.0);
    int _e3 = int(VertexID);
    mat4x4 _e6 = model.model;
    vec4 world = (_e6 * vec4(in_a_pos, 1.0));
    mat4x4 _e13 = frame.view_proj;
    gen_gl_Position = (_e13 * world);
    out_v_uv = in_a_uv;
    float _e18 = gen_gl_Position.z;
    float _e20 = gen_gl_Position.w;
    out_v_depth = (_e18 / _e20);
    int _e24 = model.layer;
    out_v_layer = _e24;
    out_v_weight = float((_e3 - (3 * (_e3 / 3))));
    vec4 _e31 = gen_gl_Position;
    vec2 _e40 = out_v_uv;
    float _e41 = out_v_depth;
    int _e42 = out_v_layer;
    float _e43 = out_v_weight;
    lit_vert_out _tmp_return = lit_vert_out(vec4(_e31.x, _e31.y, ((_e31.z * 2.0) - _e31.w), _e31.w), _e40, _e41, _e42, _e43);
    gl_Position = _tmp_return.gen_gl_Position;
    vk_location0 = _tmp_return.v_uv;
    vk_location1 = _tmp_return.v_depth;
    vk_location2 = _tmp_return.v_layer;
    vk_location3 = _tmp_return.v_weight;
    return;
}

