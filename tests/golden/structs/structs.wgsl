diagnostic(off, derivative_uniformity);

struct Light {
    dir: vec3<f32>,
    intensity: f32,
    color: vec4<f32>,
}

struct Uniforms {
    u_mvp: mat4x4<f32>,
}

struct Material {
    albedo: vec3<f32>,
    roughness: f32,
}

struct struct_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
}

struct struct_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> light: Light;
@group(0) @binding(1) 
var<uniform> uniforms: Uniforms;

fn shade(m_1: Material, n: vec3<f32>, l: Light) -> vec3<f32> {
    let ndotl = saturate(dot(n, -(l.dir)));
    return ((m_1.albedo * l.color.xyz) * (ndotl * l.intensity));
}

@vertex 
fn struct_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> struct_vs_out {
    var v_normal: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_normal = a_normal;
    let _e6 = uniforms.u_mvp;
    gl_Position = (_e6 * vec4<f32>(a_pos, 1f));
    let _e10 = gl_Position;
    let _e20 = v_normal;
    return struct_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e20);
}

@fragment 
fn struct_fs(@location(0) v_normal_1: vec3<f32>) -> struct_fs_out {
    var f_color: vec4<f32>;
    var m: Material;

    m = Material();
    m.albedo = vec3<f32>(0.8f, 0.6f, 0.4f);
    m.roughness = 0.5f;
    let _e10 = m;
    let _e13 = light;
    let _e14 = shade(_e10, normalize(v_normal_1), _e13);
    let _e17 = m.roughness;
    f_color = vec4<f32>((_e14 + vec3((_e17 * 0.1f))), 1f);
    let _e24 = f_color;
    return struct_fs_out(_e24);
}
