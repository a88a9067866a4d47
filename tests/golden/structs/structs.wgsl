diagnostic(off, derivative_uniformity);

struct Light {
    dir: vec3<f32>,
    intensity: f32,
    color: vec4<f32>,
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
var<uniform> u_mvp: mat4x4<f32>;
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_normal: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn shade(m_1: Material, n: vec3<f32>, l: Light) -> vec3<f32> {
    let ndotl = saturate(dot(n, -(l.dir)));
    return ((m_1.albedo * l.color.xyz) * (ndotl * l.intensity));
}

@vertex 
fn struct_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> struct_vs_out {
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    let _e6 = a_normal;
    v_normal = _e6;
    let _e9 = u_mvp;
    let _e11 = a_pos;
    gl_Position = (_e9 * vec4<f32>(_e11, 1f));
    let _e16 = gl_Position;
    let _e27 = v_normal;
    return struct_vs_out(vec4<f32>(_e16.x, -(_e16.y), ((_e16.z + _e16.w) * 0.5f), _e16.w), _e27);
}

@fragment 
fn struct_fs(@location(0) in_v_normal: vec3<f32>) -> struct_fs_out {
    var m: Material;

    v_normal = in_v_normal;
    m = Material();
    m.albedo = vec3<f32>(0.8f, 0.6f, 0.4f);
    m.roughness = 0.5f;
    let _e14 = m;
    let _e16 = v_normal;
    let _e19 = light;
    let _e20 = shade(_e14, normalize(_e16), _e19);
    let _e24 = m.roughness;
    f_color = vec4<f32>((_e20 + vec3((_e24 * 0.1f))), 1f);
    let _e32 = f_color;
    return struct_fs_out(_e32);
}
