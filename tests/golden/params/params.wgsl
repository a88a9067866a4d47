diagnostic(off, derivative_uniformity);

struct Ray {
    origin: vec3<f32>,
    dir: vec3<f32>,
}

struct params_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct params_fs_out {
    @location(0) f_color: vec4<f32>,
}

fn along(r: Ray, t: f32) -> vec3<f32> {
    return (r.origin + (r.dir * t));
}

fn total(xs: array<f32, 4>, n: i32) -> f32 {
    var s: f32;
    var i: i32;
    var j: i32;

    s = 0f;
    i = i32();
    j = i32();
    loop {
        let _e7 = i;
        if !((_e7 < n)) {
            break;
        }
        let _e10 = i;
        let _e12 = s;
        s = (_e12 + xs[_e10]);
        let _e15 = i;
        i = (_e15 + 1i);
        let _e17 = j;
        j = (_e17 - 1i);
    }
    let _e19 = s;
    let _e20 = j;
    return (_e19 + (f32(_e20) * 0f));
}

fn blend(a: vec3<f32>, b: vec3<f32>, t_1: f32, uv: vec2<f32>) -> vec3<f32> {
    return (mix(a, b, vec3(t_1)) * vec3<f32>(uv, 1f));
}

@vertex 
fn params_vs(@location(0) a_pos: vec2<f32>) -> params_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = a_pos;
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e6 = gl_Position;
    let _e16 = v_uv;
    return params_vs_out(vec4<f32>(_e6.x, -(_e6.y), ((_e6.z + _e6.w) * 0.5f), _e6.w), _e16);
}

@fragment 
fn params_fs(@location(0) v_uv_1: vec2<f32>) -> params_fs_out {
    var f_color: vec4<f32>;

    let r_1 = Ray(vec3(0f), normalize(vec3<f32>(v_uv_1, -(1f))));
    let xs_1 = array<f32, 4>(0.1f, 0.2f, 0.3f, 0.4f);
    let _e14 = along(r_1, 2f);
    let _e18 = total(xs_1, 3i);
    let _e19 = blend(_e14, vec3<f32>(1f, 0.5f, 0f), _e18, v_uv_1);
    f_color = vec4<f32>(_e19, 1f);
    let _e22 = f_color;
    return params_fs_out(_e22);
}
