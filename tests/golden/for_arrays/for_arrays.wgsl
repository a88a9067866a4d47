diagnostic(off, derivative_uniformity);

struct Light {
    pos: vec4<f32>,
    color: vec4<f32>,
}

struct for_arrays_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct for_arrays_fs_out {
    @location(0) f_color: vec4<f32>,
}

const KERNEL: array<f32, 3> = array<f32, 3>(0.25f, 0.5f, 0.25f);

@group(0) @binding(0) 
var<uniform> u_lights: array<Light, 4>;
@group(0) @binding(1) 
var<uniform> u_count: i32;

@vertex 
fn for_arrays_vs(@location(0) a_pos: vec2<f32>) -> for_arrays_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return for_arrays_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
}

@fragment 
fn for_arrays_fs(@location(0) v_uv_1: vec2<f32>) -> for_arrays_fs_out {
    var f_color: vec4<f32>;
    var c: vec3<f32>;
    var i: i32;
    var taps: array<f32, 3>;
    var t_index: i32;
    var blur: f32;
    var t_index_1: i32;
    var ramp: f32;
    var i_1: i32;

    c = vec3(0f);
    i = 0i;
    let _e7 = u_count;
    loop {
        let _e8 = i;
        if !((_e8 < _e7)) {
            break;
        }
        let _e12 = i;
        if (u32(_e12) >= 4u) {
            break;
        }
        let _e18 = i;
        let l = u_lights[_e18];
        let d = distance(v_uv_1, l.pos.xy);
        let _e30 = i;
        let _e37 = c;
        c = (_e37 + (l.color.xyz * (1f / ((1f + f32(_e30)) + (d * d)))));
        continuing {
            let _e39 = i;
            i = (_e39 + 1i);
        }
    }
    taps = array<f32, 3>();
    t_index = 0i;
    loop {
        let _e47 = t_index;
        if !((_e47 < 3i)) {
            break;
        }
        let _e52 = t_index;
        let k = KERNEL[_e52];
        let _e56 = t_index;
        taps[_e56] = (k * v_uv_1.y);
        continuing {
            let _e60 = t_index;
            t_index = (_e60 + 1i);
        }
    }
    blur = 0f;
    t_index_1 = 0i;
    loop {
        let _e68 = t_index_1;
        if !((_e68 < 3i)) {
            break;
        }
        let _e74 = t_index_1;
        let _e76 = taps[_e74];
        let _e77 = blur;
        blur = (_e77 + _e76);
        continuing {
            let _e79 = t_index_1;
            t_index_1 = (_e79 + 1i);
        }
    }
    ramp = 0f;
    {
        let j_count = select(0u, (u32(8i) - u32(5i)), (8i > 5i));
        i_1 = 1i;
        loop {
            let _e97 = i_1;
            if !((_e97 < 10i)) {
                break;
            }
            let _e101 = i_1;
            let i_step = (u32(_e101) - u32(1i));
            if (i_step >= j_count) {
                break;
            }
            if (i_step >= 3u) {
                break;
            }
            let j = (5i + i32(i_step));
            let k_1 = KERNEL[i32(i_step)];
            let _e117 = i_1;
            let _e121 = ramp;
            ramp = (_e121 + (f32((_e117 * j)) * k_1));
            continuing {
                let _e123 = i_1;
                i_1 = (_e123 + 1i);
            }
        }
    }
    let _e128 = c;
    let _e130 = blur;
    let _e134 = ramp;
    f_color = vec4<f32>((_e128 + vec3(_e130)), (_e134 / 50f));
    let _e139 = f_color;
    return for_arrays_fs_out(_e139);
}
