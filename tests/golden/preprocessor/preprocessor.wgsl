diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_mvp: mat4x4<f32>,
    u_light_dir: vec3<f32>,
}

struct pp_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
}

struct pp_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn lambert(n: vec3<f32>, l: vec3<f32>) -> f32 {
    return (max(dot(n, l), 0f) + 0.15f);
}

@vertex 
fn pp_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> pp_vs_out {
    var v_normal: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_normal = a_normal;
    let _e6 = uniforms.u_mvp;
    gl_Position = (_e6 * vec4<f32>(a_pos, 1f));
    let _e10 = gl_Position;
    let _e20 = v_normal;
    return pp_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e20);
}

@fragment 
fn pp_fs(@location(0) v_normal_1: vec3<f32>) -> pp_fs_out {
    var f_color: vec4<f32>;
    var c: vec3<f32>;

    let n_1 = normalize(v_normal_1);
    let _e5 = uniforms.u_light_dir;
    let _e6 = lambert(n_1, _e5);
    c = vec3(_e6);
    let _e9 = c;
    c = (_e9 * 0.9f);
    let _e12 = c;
    f_color = vec4<f32>(_e12, 1f);
    let _e15 = f_color;
    return pp_fs_out(_e15);
}
