diagnostic(off, derivative_uniformity);

struct pp_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
}

struct pp_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_mvp: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_light_dir: vec3<f32>;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_normal: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn lambert(n: vec3<f32>, l: vec3<f32>) -> f32 {
    return (max(dot(n, l), 0f) + 0.15f);
}

@vertex 
fn pp_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> pp_vs_out {
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    let _e6 = a_normal;
    v_normal = _e6;
    let _e9 = u_mvp;
    let _e11 = a_pos;
    gl_Position = (_e9 * vec4<f32>(_e11, 1f));
    let _e16 = gl_Position;
    let _e27 = v_normal;
    return pp_vs_out(vec4<f32>(_e16.x, -(_e16.y), ((_e16.z + _e16.w) * 0.5f), _e16.w), _e27);
}

@fragment 
fn pp_fs(@location(0) in_v_normal: vec3<f32>) -> pp_fs_out {
    var c: vec3<f32>;

    v_normal = in_v_normal;
    let _e3 = v_normal;
    let n_1 = normalize(_e3);
    let _e7 = u_light_dir;
    let _e8 = lambert(n_1, _e7);
    c = vec3(_e8);
    let _e12 = c;
    c = (_e12 * 0.9f);
    let _e16 = c;
    f_color = vec4<f32>(_e16, 1f);
    let _e20 = f_color;
    return pp_fs_out(_e20);
}
