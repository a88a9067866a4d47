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
var<private> a_pos: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_pos: vec3<f32>;
var<private> v_normal: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

fn light_at(l: Light, p: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let d = (l.position - p);
    let att = saturate((1f - (length(d) / l.radius)));
    return ((l.color.xyz * max(dot(n, normalize(d)), 0f)) * att);
}

@vertex 
fn layout_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_normal: vec3<f32>) -> layout_vs_out {
    a_pos = in_a_pos;
    a_normal = in_a_normal;
    let _e6 = a_pos;
    v_pos = _e6;
    let _e10 = scene.normal_matrix;
    let _e12 = a_normal;
    v_normal = (_e10 * _e12);
    let _e16 = u_mvp;
    let _e18 = a_pos;
    gl_Position = (_e16 * vec4<f32>(_e18, 1f));
    let _e23 = gl_Position;
    let _e34 = v_pos;
    let _e36 = v_normal;
    return layout_vs_out(vec4<f32>(_e23.x, -(_e23.y), ((_e23.z + _e23.w) * 0.5f), _e23.w), _e34, _e36);
}

@fragment 
fn layout_fs(@location(0) in_v_pos: vec3<f32>, @location(1) in_v_normal: vec3<f32>) -> layout_fs_out {
    var c: vec3<f32>;
    var i: i32;
    var i_1: i32;
    var k: f32;
    var i_2: i32;

    v_pos = in_v_pos;
    v_normal = in_v_normal;
    let _e5 = v_normal;
    let n_1 = normalize(_e5);
    c = vec3(0f);
    i = 0i;
    let _e14 = scene.light_count;
    loop {
        let _e15 = i;
        if !((_e15 < _e14)) {
            break;
        }
        let _e22 = i;
        let _e24 = scene.lights[_e22];
        let _e26 = v_pos;
        let _e27 = light_at(_e24, _e26, n_1);
        let _e28 = c;
        c = (_e28 + _e27);
        continuing {
            let _e30 = i;
            i = (_e30 + 1i);
        }
    }
    i_1 = 0i;
    loop {
        let _e36 = i_1;
        if !((_e36 < 2i)) {
            break;
        }
        let _e42 = i_1;
        let _e44 = u_lights[_e42];
        let _e46 = v_pos;
        let _e47 = light_at(_e44, _e46, n_1);
        let _e48 = c;
        c = (_e48 + _e47);
        continuing {
            let _e50 = i_1;
            i_1 = (_e50 + 1i);
        }
    }
    k = 0f;
    i_2 = 0i;
    loop {
        let _e58 = i_2;
        if !((_e58 < 8i)) {
            break;
        }
        let _e64 = i_2;
        let _e67 = u_kernel[_e64].x;
        let _e70 = i_2;
        let _e73 = u_kernel[_e70].w;
        let _e75 = k;
        k = (_e75 + (_e67 + _e73));
        continuing {
            let _e77 = i_2;
            i_2 = (_e77 + 1i);
        }
    }
    let _e83 = scene.fog.density;
    let _e86 = v_pos;
    let f = exp((-(_e83) * length(_e86)));
    let _e94 = scene.fog.color;
    let _e96 = c;
    let _e99 = scene.exposure;
    c = mix(_e94, (_e96 * _e99), vec3(f));
    let _e105 = c;
    let _e108 = scene.tint;
    let _e113 = k;
    f_color = vec4<f32>(((_e105 * vec3<f32>(_e108, 1f)) + vec3((_e113 * 0.001f))), 1f);
    let _e121 = f_color;
    return layout_fs_out(_e121);
}
