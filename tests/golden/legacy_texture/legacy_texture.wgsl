diagnostic(off, derivative_uniformity);

struct legacy_texture_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
    @location(1) v_dir: vec3<f32>,
}

struct legacy_texture_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var u_tex: texture_2d<f32>;
@group(0) @binding(1) 
var u_tex_sampler: sampler;
@group(0) @binding(2) 
var u_env: texture_cube<f32>;
@group(0) @binding(3) 
var u_env_sampler: sampler;

@vertex 
fn legacy_texture_vs(@location(0) a_pos: vec2<f32>) -> legacy_texture_vs_out {
    var v_uv: vec2<f32>;
    var v_dir: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    v_dir = vec3<f32>(a_pos, 1f);
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e21 = v_uv;
    let _e22 = v_dir;
    return legacy_texture_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e21, _e22);
}

@fragment 
fn legacy_texture_fs(@location(0) v_uv_1: vec2<f32>, @location(1) v_dir_1: vec3<f32>) -> legacy_texture_fs_out {
    var f_color: vec4<f32>;

    let _e5 = textureSample(u_tex, u_tex_sampler, v_uv_1);
    let _e8 = textureSample(u_env, u_env_sampler, v_dir_1);
    f_color = (_e5 * _e8);
    let _e10 = f_color;
    return legacy_texture_fs_out(_e10);
}
