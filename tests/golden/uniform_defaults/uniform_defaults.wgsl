diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_exposure: f32,
    u_steps: i32,
    u_basis: mat3x3<f32>,
}

struct Grade {
    lift: vec3<f32>,
    gamma: f32,
    gain: vec4<f32>,
}

struct grade_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct grade_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var<uniform> u_grade: Grade;

@vertex 
fn grade_vs(@location(0) a_pos: vec2<f32>) -> grade_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return grade_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn grade_fs(@location(0) v_uv_1: vec2<f32>) -> grade_fs_out {
    var f_color: vec4<f32>;

    let _e4 = uniforms.u_steps;
    let _e9 = uniforms.u_steps;
    let banded = (floor((v_uv_1.x * f32(_e4))) / f32(_e9));
    let _e13 = uniforms.u_basis;
    let _e19 = uniforms.u_exposure;
    let _e23 = u_grade.lift;
    let c = (((_e13 * vec3<f32>(banded, v_uv_1.y, 0.5f)) * _e19) + _e23);
    let _e28 = u_grade.gamma;
    let _e34 = u_grade.gain;
    f_color = (vec4<f32>(pow(c, vec3((1f / _e28))), 1f) * _e34);
    let _e36 = f_color;
    return grade_fs_out(_e36);
}
