diagnostic(off, derivative_uniformity);

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
var<uniform> u_exposure: f32;
@group(0) @binding(1) 
var<uniform> u_steps: i32;
@group(0) @binding(2) 
var<uniform> u_grade: Grade;
@group(0) @binding(3) 
var<uniform> u_basis: mat3x3<f32>;

@vertex 
fn grade_vs(@location(0) a_pos: vec2<f32>) -> grade_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return grade_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
}

@fragment 
fn grade_fs(@location(0) v_uv_1: vec2<f32>) -> grade_fs_out {
    var f_color: vec4<f32>;

    let _e3 = u_steps;
    let _e8 = u_steps;
    let banded = (floor((v_uv_1.x * f32(_e3))) / f32(_e8));
    let _e12 = u_basis;
    let _e18 = u_exposure;
    let _e22 = u_grade.lift;
    let c = (((_e12 * vec3<f32>(banded, v_uv_1.y, 0.5f)) * _e18) + _e22);
    let _e28 = u_grade.gamma;
    let _e36 = u_grade.gain;
    f_color = (vec4<f32>(pow(c, vec3((1f / _e28))), 1f) * _e36);
    let _e39 = f_color;
    return grade_fs_out(_e39);
}
