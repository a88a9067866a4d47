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
var<uniform> u_kernel: array<vec4<f32>, 8>;
@group(0) @binding(2) 
var<uniform> u_lights: array<Light, 2>;
@group(0) @binding(3) 
var<uniform> u_mvp: mat4x4<f32>;

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
    let _e10 = u_mvp;
    gl_Position = (_e10 * vec4<f32>(a_pos, 1f));
    let _e15 = gl_Position;
    let _e26 = v_pos;
    let _e28 = v_normal;
    return layout_vs_out(vec4<f32>(_e15.x, -(_e15.y), ((_e15.z + _e15.w) * 0.5f), _e15.w), _e26, _e28);
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
        let _e36 = i_1;
        let _e38 = u_lights[_e36];
        let _e39 = light_at(_e38, v_pos_1, n_1);
        let _e40 = c;
        c = (_e40 + _e39);
        continuing {
            let _e42 = i_1;
            i_1 = (_e42 + 1i);
        }
    }
    k = 0f;
    i_2 = 0i;
    loop {
        let _e50 = i_2;
        if !((_e50 < 8i)) {
            break;
        }
        let _e56 = i_2;
        let _e59 = u_kernel[_e56].x;
        let _e62 = i_2;
        let _e65 = u_kernel[_e62].w;
        let _e67 = k;
        k = (_e67 + (_e59 + _e65));
        continuing {
            let _e69 = i_2;
            i_2 = (_e69 + 1i);
        }
    }
    let _e75 = scene.fog.density;
    let f = exp((-(_e75) * length(v_pos_1)));
    let _e84 = scene.fog.color;
    let _e86 = c;
    let _e89 = scene.exposure;
    c = mix(_e84, (_e86 * _e89), vec3(f));
    let _e95 = c;
    let _e98 = scene.tint;
    let _e103 = k;
    f_color = vec4<f32>(((_e95 * vec3<f32>(_e98, 1f)) + vec3((_e103 * 0.001f))), 1f);
    let _e111 = f_color;
    return layout_fs_out(_e111);
}
