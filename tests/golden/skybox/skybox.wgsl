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
    let _e8 = uniforms.u_view[1];
    let _e12 = uniforms.u_view[2];
    let rot = mat3x3<f32>(_e4.xyz, _e8.xyz, _e12.xyz);
    let view = mat4x4<f32>(vec4<f32>(rot[0], 0f), vec4<f32>(rot[1], 0f), vec4<f32>(rot[2], 0f), vec4<f32>(0f, 0f, 0f, 1f));
    v_dir = a_position;
    let _e27 = uniforms.u_proj;
    let p = ((_e27 * view) * vec4<f32>(a_position, 1f));
    gl_Position = p.xyww;
    let _e33 = gl_Position;
    let _e43 = v_dir;
    return sky_vs_out(vec4<f32>(_e33.x, -(_e33.y), ((_e33.z + _e33.w) * 0.5f), _e33.w), _e43);
}

@fragment 
fn sky_fs(@location(0) v_dir_1: vec3<f32>) -> sky_fs_out {
    var f_color: vec4<f32>;

    let _e4 = textureSample(sky, sky_sampler, normalize(v_dir_1));
    let _e8 = uniforms.u_exposure;
    let hdr = (_e4.xyz * _e8);
    let mapped = (hdr / (hdr + vec3(1f)));
    f_color = vec4<f32>(pow(mapped, vec3((1f / 2.2f))), 1f);
    let _e20 = f_color;
    return sky_fs_out(_e20);
}
