diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_light_dir: vec3<f32>,
}

struct Ray {
    origin: vec3<f32>,
    dir: vec3<f32>,
}

struct Material {
    albedo: vec3<f32>,
    roughness: f32,
    metallic: f32,
    emissive: vec3<f32>,
}

struct struct_init_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct struct_init_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn Ray_1(from_: vec3<f32>, to: vec3<f32>) -> Ray {
    return Ray(from_, normalize((to - from_)));
}

fn shade(m: Material, n: vec3<f32>, l: vec3<f32>) -> vec3<f32> {
    var c_1: vec3<f32>;

    c_1 = vec3<f32>();
    {
        let diffuse = ((m.albedo * (1f - m.metallic)) * max(dot(n, l), 0f));
        c_1 = ((diffuse * (1f - (m.roughness * 0.5f))) + m.emissive);
    }
    let _e21 = c_1;
    return _e21;
}

@vertex 
fn struct_init_vs(@location(0) a_pos: vec2<f32>) -> struct_init_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return struct_init_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn struct_init_fs(@location(0) v_uv_1: vec2<f32>) -> struct_init_fs_out {
    var f_color: vec4<f32>;
    var glow: Material;
    var c: vec3<f32>;

    let base = Material(vec3(0.8f), 0.5f, f32(), vec3<f32>());
    let metal = Material(vec3(0.8f), 0.2f, 1f, vec3<f32>());
    glow = Material(vec3(0.8f), 0.5f, f32(), vec3<f32>(0.1f, 0.05f, 0f));
    {
        let _e19 = glow.albedo;
        glow.albedo = (_e19 * 0.5f);
    }
    let _e23 = Ray_1(vec3<f32>(v_uv_1, 1f), vec3<f32>(0.5f, 0.5f, 0f));
    let n_1 = -(_e23.dir);
    let m_1 = select(select(2i, 1i, (v_uv_1.x < 0.66f)), 0i, (v_uv_1.x < 0.33f));
    let _e38 = glow;
    let _e41 = uniforms.u_light_dir;
    let _e42 = shade(_e38, n_1, _e41);
    c = _e42;
    if (m_1 == 0i) {
        let _e45 = uniforms.u_light_dir;
        let _e46 = shade(base, n_1, _e45);
        c = _e46;
    } else {
        if (m_1 == 1i) {
            let _e49 = uniforms.u_light_dir;
            let _e50 = shade(metal, n_1, _e49);
            c = _e50;
        }
    }
    let _e52 = c;
    f_color = vec4<f32>(_e52, 1f);
    let _e54 = f_color;
    return struct_init_fs_out(_e54);
}
