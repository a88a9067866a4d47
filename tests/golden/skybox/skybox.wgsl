diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_view: mat4x4<f32>,
    u_proj: mat4x4<f32>,
    u_exposure: f32,
}

struct sky_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_dir: vec3<f32>,
}

struct sky_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var sky: texture_cube<f32>;
@group(0) @binding(2) 
var sky_sampler: sampler;

@vertex 
fn sky_vs(@location(0) a_position: vec3<f32>) -> sky_vs_out {
    var v_dir: vec3<f32>;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_view[0];
    let _e9 = uniforms.u_view[1];
    let _e14 = uniforms.u_view[2];
    let rot = mat3x3<f32>(_e4.xyz, _e9.xyz, _e14.xyz);
    let view = mat4x4<f32>(vec4<f32>(rot[0], 0f), vec4<f32>(rot[1], 0f), vec4<f32>(rot[2], 0f), vec4<f32>(0f, 0f, 0f, 1f));
    v_dir = a_position;
    let _e35 = uniforms.u_proj;
    let p = ((_e35 * view) * vec4<f32>(a_position, 1f));
    gl_Position = p.xyww;
    let _e43 = gl_Position;
    let _e54 = v_dir;
    return sky_vs_out(vec4<f32>(_e43.x, -(_e43.y), ((_e43.z + _e43.w) * 0.5f), _e43.w), _e54);
}

@fragment 
fn sky_fs(@location(0) v_dir_1: vec3<f32>) -> sky_fs_out {
    var f_color: vec4<f32>;

    let _e4 = textureSample(sky, sky_sampler, normalize(v_dir_1));
    let _e8 = uniforms.u_exposure;
    let hdr = (_e4.xyz * _e8);
    let mapped = (hdr / (hdr + vec3(1f)));
    f_color = vec4<f32>(pow(mapped, vec3((1f / 2.2f))), 1f);
    let _e23 = f_color;
    return sky_fs_out(_e23);
}
