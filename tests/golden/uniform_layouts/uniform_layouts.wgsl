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
    let _e15 = gl_Position;
    let _e25 = v_pos;
    let _e26 = v_normal;
    return layout_vs_out(vec4<f32>(_e15.x, -(_e15.y), ((_e15.z + _e15.w) * 0.5f), _e15.w), _e25, _e26);
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
        let _e15 = i;
        let _e17 = scene.lights[_e15];
        let _e18 = light_at(_e17, v_pos_1, n_1);
        let _e19 = c;
        c = (_e19 + _e18);
        continuing {
            let _e21 = i;
            i = (_e21 + 1i);
        }
    }
    i_1 = 0i;
    loop {
        let _e26 = i_1;
        if !((_e26 < 2i)) {
            break;
        }
        let _e31 = i_1;
        let _e33 = uniforms.u_lights[_e31];
        let _e34 = light_at(_e33, v_pos_1, n_1);
        let _e35 = c;
        c = (_e35 + _e34);
        continuing {
            let _e37 = i_1;
            i_1 = (_e37 + 1i);
        }
    }
    k = 0f;
    i_2 = 0i;
    loop {
        let _e42 = i_2;
        if !((_e42 < 8i)) {
            break;
        }
        let _e46 = i_2;
        let _e49 = uniforms.u_kernel[_e46].x;
        let _e51 = i_2;
        let _e54 = uniforms.u_kernel[_e51].w;
        let _e56 = k;
        k = (_e56 + (_e49 + _e54));
        continuing {
            let _e58 = i_2;
            i_2 = (_e58 + 1i);
        }
    }
    let _e62 = scene.fog.density;
    let f = exp((-(_e62) * length(v_pos_1)));
    let _e69 = scene.fog.color;
    let _e70 = c;
    let _e72 = scene.exposure;
    c = mix(_e69, (_e70 * _e72), vec3(f));
    let _e77 = c;
    let _e79 = scene.tint;
    let _e83 = k;
    f_color = vec4<f32>(((_e77 * vec3<f32>(_e79, 1f)) + vec3((_e83 * 0.001f))), 1f);
    let _e89 = f_color;
    return layout_fs_out(_e89);
}
