diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_exposure: f32,
}

struct modules_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct modules_fs_out {
    @location(0) f_color: vec4<f32>,
}

const RAMP_LO: vec3<f32> = vec3<f32>(0.02f, 0.03f, 0.1f);
const RAMP_HI: vec3<f32> = vec3<f32>(3f, 2.2f, 1.4f);

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn palette_ramp(t: f32) -> vec3<f32> {
    return mix(RAMP_LO, RAMP_HI, vec3((t * t)));
}

fn aces(x: vec3<f32>) -> vec3<f32> {
    return saturate(((x * ((2.51f * x) + vec3(0.03f))) / ((x * ((2.43f * x) + vec3(0.59f))) + vec3(0.14f))));
}

@vertex 
fn modules_vs(@location(0) a_pos: vec2<f32>) -> modules_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return modules_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn modules_fs(@location(0) v_uv_1: vec2<f32>) -> modules_fs_out {
    var f_color: vec4<f32>;

    let _e2 = palette_ramp(v_uv_1.x);
    let _e5 = uniforms.u_exposure;
    let hdr = (_e2 * _e5);
    let _e8 = aces(hdr);
    f_color = vec4<f32>(_e8, 1f);
    let _e11 = f_color;
    return modules_fs_out(_e11);
}
