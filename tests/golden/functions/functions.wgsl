diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_time: f32,
}

struct functions_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct functions_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn wave(x: f32, t: f32) -> f32 {
    return (0.5f + (0.5f * sin(((x * 6.283f) + t))));
}

fn square(x_1: f32) -> f32 {
    return (x_1 * x_1);
}

fn tint(c: vec3<f32>, by: vec3<f32>) -> vec3<f32> {
    return (c * by);
}

fn vignette(uv: vec2<f32>, strength: f32, radius: f32) -> f32 {
    let d = length((uv - vec2(0.5f)));
    return (1f - (strength * smoothstep((radius * 0.5f), radius, d)));
}

fn luma_float3_(c_1: vec3<f32>) -> f32 {
    return dot(c_1, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn luma_float4_(c_2: vec4<f32>) -> f32 {
    let _e2 = luma_float3_(c_2.xyz);
    return (_e2 * c_2.w);
}

fn banded(x_2: f32) -> f32 {
    if (x_2 < 0.1f) {
        return 0f;
    }
    if (x_2 > 0.9f) {
        return 1f;
    } else {
        return (floor((x_2 * 4f)) / 4f);
    }
}

@vertex 
fn functions_vs(@location(0) a_pos: vec2<f32>) -> functions_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return functions_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn functions_fs(@location(0) v_uv_1: vec2<f32>) -> functions_fs_out {
    var f_color: vec4<f32>;

    let _e4 = uniforms.u_time;
    let _e5 = wave(v_uv_1.x, _e4);
    let _e7 = square(v_uv_1.y);
    let _e14 = tint(vec3<f32>(_e5, _e7, 0.25f), vec3<f32>(1f, 0.9f, 0.8f));
    let _e17 = vignette(v_uv_1, 0.6f, 0.75f);
    let _e19 = vignette(v_uv_1, 0.2f, 0.75f);
    let _e22 = vignette(v_uv_1, 0.1f, 0.9f);
    let _e25 = vignette(v_uv_1, 0.6f, 1.2f);
    let v = (((_e17 * _e19) * _e22) * _e25);
    let _e28 = luma_float4_(vec4<f32>(_e14, 1f));
    let _e29 = luma_float3_(_e14);
    let g = (_e28 + _e29);
    let _e35 = banded((g * 0.5f));
    f_color = vec4<f32>((_e14 * v), _e35);
    let _e37 = f_color;
    return functions_fs_out(_e37);
}
