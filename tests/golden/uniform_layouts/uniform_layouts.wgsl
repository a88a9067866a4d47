diagnostic(off, derivative_uniformity);

struct Light {
    position: vec3<f32>,
    radius: f32,
    color: vec4<f32>,
}

struct Fog {
    color: vec3<f32>,
    density: f32,
}

struct Scene {
    normal_matrix: mat3x3<f32>,
    lights: array<Light, 4>,
    fog: Fog,
    light_count: i32,
    exposure: f32,
    tint: vec2<f32>,
}

struct Uniforms {
    u_kernel: array<vec4<f32>, 8>,
    u_lights: array<Light, 2>,
    u_mvp: mat4x4<f32>,
}

struct layout_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_pos: vec3<f32>,
    @location(1) v_normal: vec3<f32>,
}

struct layout_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> scene: Scene;
@group(0) @binding(1) 
var<uniform> uniforms: Uniforms;

fn light_at(l: Light, p: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let d = (l.position - p);
    let att = saturate((1f - (length(d) / l.radius)));
    return ((l.color.xyz * max(dot(n, normalize(d)), 0f)) * att);
}

@vertex 
fn layout_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> layout_vs_out {
    var v_pos: vec3<f32>;
    var v_normal: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_pos = a_pos;
    let _e6 = scene.normal_matrix;
    v_normal = (_e6 * a_normal);
    let _e11 = uniforms.u_mvp;
    gl_Position = (_e11 * vec4<f32>(a_pos, 1f));
    let _e16 = gl_Position;
    let _e27 = v_pos;
    let _e29 = v_normal;
    return layout_vs_out(vec4<f32>(_e16.x, -(_e16.y), ((_e16.z + _e16.w) * 0.5f), _e16.w), _e27, _e29);
}

@fragment 
fn layout_fs(@location(0) v_pos_1: vec3<f32>, @location(1) v_normal_1: vec3<f32>) -> layout_fs_out {
    var f_color: vec4<f32>;
    var c: vec3<f32>;
    var i: i32;
    var i_1: i32;
    var k: f32;
    var i_2: i32;

    let n_1 = normalize(v_normal_1);
    c = vec3(0f);
    i = 0i;
    let _e10 = scene.light_count;
    loop {
        let _e11 = i;
        if !((_e11 < _e10)) {
            break;
        }
        let _e18 = i;
        let _e20 = scene.lights[_e18];
        let _e21 = light_at(_e20, v_pos_1, n_1);
        let _e22 = c;
        c = (_e22 + _e21);
        continuing {
            let _e24 = i;
            i = (_e24 + 1i);
        }
    }
    i_1 = 0i;
    loop {
        let _e30 = i_1;
        if !((_e30 < 2i)) {
            break;
        }
        let _e37 = i_1;
        let _e39 = uniforms.u_lights[_e37];
        let _e40 = light_at(_e39, v_pos_1, n_1);
        let _e41 = c;
        c = (_e41 + _e40);
        continuing {
            let _e43 = i_1;
            i_1 = (_e43 + 1i);
        }
    }
    k = 0f;
    i_2 = 0i;
    loop {
        let _e51 = i_2;
        if !((_e51 < 8i)) {
            break;
        }
        let _e58 = i_2;
        let _e61 = uniforms.u_kernel[_e58].x;
        let _e65 = i_2;
        let _e68 = uniforms.u_kernel[_e65].w;
        let _e70 = k;
        k = (_e70 + (_e61 + _e68));
        continuing {
            let _e72 = i_2;
            i_2 = (_e72 + 1i);
        }
    }
    let _e78 = scene.fog.density;
    let f = exp((-(_e78) * length(v_pos_1)));
    let _e87 = scene.fog.color;
    let _e89 = c;
    let _e92 = scene.exposure;
    c = mix(_e87, (_e89 * _e92), vec3(f));
    let _e98 = c;
    let _e101 = scene.tint;
    let _e106 = k;
    f_color = vec4<f32>(((_e98 * vec3<f32>(_e101, 1f)) + vec3((_e106 * 0.001f))), 1f);
    let _e114 = f_color;
    return layout_fs_out(_e114);
}
