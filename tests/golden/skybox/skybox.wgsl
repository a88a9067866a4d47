diagnostic(off, derivative_uniformity);

struct sky_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_dir: vec3<f32>,
}

struct sky_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_view: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_proj: mat4x4<f32>;
@group(0) @binding(2) 
var<uniform> u_exposure: f32;
@group(0) @binding(3) 
var sky: texture_cube<f32>;
@group(0) @binding(4) 
var sky_sampler: sampler;
var<private> a_position: vec3<f32>;
var<private> v_dir: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

@vertex 
fn sky_vs(@location(0) in_a_position: vec3<f32>) -> sky_vs_out {
    a_position = in_a_position;
    let _e4 = u_view[0];
    let _e8 = u_view[1];
    let _e12 = u_view[2];
    let rot = mat3x3<f32>(_e4.xyz, _e8.xyz, _e12.xyz);
    let view = mat4x4<f32>(vec4<f32>(rot[0], 0f), vec4<f32>(rot[1], 0f), vec4<f32>(rot[2], 0f), vec4<f32>(0f, 0f, 0f, 1f));
    let _e32 = a_position;
    v_dir = _e32;
    let _e34 = u_proj;
    let _e37 = a_position;
    let p = ((_e34 * view) * vec4<f32>(_e37, 1f));
    gl_Position = p.xyww;
    let _e44 = gl_Position;
    let _e55 = v_dir;
    return sky_vs_out(vec4<f32>(_e44.x, -(_e44.y), ((_e44.z + _e44.w) * 0.5f), _e44.w), _e55);
}

@fragment 
fn sky_fs(@location(0) in_v_dir: vec3<f32>) -> sky_fs_out {
    v_dir = in_v_dir;
    let _e3 = v_dir;
    let _e7 = textureSample(sky, sky_sampler, normalize(_e3));
    let _e10 = u_exposure;
    let hdr = (_e7.xyz * _e10);
    let mapped = (hdr / (hdr + vec3(1f)));
    f_color = vec4<f32>(pow(mapped, vec3((1f / 2.2f))), 1f);
    let _e25 = f_color;
    return sky_fs_out(_e25);
}
