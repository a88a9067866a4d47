diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view_proj: mat4x4<f32>,
    u_light_view_proj: mat4x4<f32>,
    u_light_dir: vec3<f32>,
    u_color: vec4<f32>,
}

struct pcf_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
    @location(1) v_light_pos: vec4<f32>,
}

struct pcf_fs_out {
    @location(0) f_color: vec4<f32>,
}

const PCF_RADIUS: i32 = 2i;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var shadow_map: texture_depth_2d;
@group(0) @binding(2) 
var shadow_map_sampler: sampler_comparison;

fn pcf_5x5_(coord: vec3<f32>, bias: f32) -> f32 {
    var lit: f32;
    var y: i32;
    var x: i32;

    let _e6 = textureDimensions(shadow_map, 0i);
    let texel = (vec2(1f) / vec2<f32>(vec2<i32>(_e6)));
    lit = 0f;
    y = -(PCF_RADIUS);
    loop {
        let _e17 = y;
        if !((_e17 < (PCF_RADIUS + 1i))) {
            break;
        }
        x = -(PCF_RADIUS);
        loop {
            let _e23 = x;
            if !((_e23 < (PCF_RADIUS + 1i))) {
                break;
            }
            let _e26 = x;
            let _e28 = y;
            let offset = (vec2<f32>(f32(_e26), f32(_e28)) * texel);
            let _e37 = textureSampleCompare(shadow_map, shadow_map_sampler, (coord.xy + offset), (coord.z - bias));
            let _e38 = lit;
            lit = (_e38 + _e37);
            continuing {
                let _e40 = x;
                x = (_e40 + 1i);
            }
        }
        continuing {
            let _e42 = y;
            y = (_e42 + 1i);
        }
    }
    let n = ((2i * PCF_RADIUS) + 1i);
    let _e47 = lit;
    return (_e47 / f32((n * n)));
}

@vertex 
fn pcf_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>) -> pcf_vs_out {
    var v_normal: vec3<f32>;
    var v_light_pos: vec4<f32>;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_model;
    let world = (_e4 * vec4<f32>(a_position, 1f));
    let _e10 = uniforms.u_model;
    v_normal = (_e10 * vec4<f32>(a_normal, 0f)).xyz;
    let _e17 = uniforms.u_light_view_proj;
    v_light_pos = (_e17 * world);
    let _e21 = uniforms.u_view_proj;
    gl_Position = (_e21 * world);
    let _e23 = gl_Position;
    let _e33 = v_normal;
    let _e34 = v_light_pos;
    return pcf_vs_out(vec4<f32>(_e23.x, -(_e23.y), ((_e23.z + _e23.w) * 0.5f), _e23.w), _e33, _e34);
}

@fragment 
fn pcf_fs(@location(0) v_normal_1: vec3<f32>, @location(1) v_light_pos_1: vec4<f32>) -> pcf_fs_out {
    var f_color: vec4<f32>;
    var shadow: f32;

    let n_1 = normalize(v_normal_1);
    let _e5 = uniforms.u_light_dir;
    let l = normalize(-(_e5));
    let ndotl = max(dot(n_1, l), 0f);
    let coord_1 = (((v_light_pos_1.xyz / vec3(v_light_pos_1.w)) * 0.5f) + vec3(0.5f));
    shadow = 1f;
    if (coord_1.z <= 1f) {
        let bias_1 = max((0.005f * (1f - ndotl)), 0.0005f);
        let edge = min(min(coord_1.x, coord_1.y), min((1f - coord_1.x), (1f - coord_1.y)));
        let _e37 = pcf_5x5_(coord_1, bias_1);
        shadow = mix(1f, _e37, saturate((edge * 20f)));
    }
    let _e44 = uniforms.u_color;
    let _e49 = shadow;
    let _e55 = uniforms.u_color.w;
    f_color = vec4<f32>((_e44.xyz * (0.15f + ((0.85f * ndotl) * _e49))), _e55);
    let _e57 = f_color;
    return pcf_fs_out(_e57);
}
