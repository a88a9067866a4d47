diagnostic(off, derivative_uniformity);

struct Light {
    pos: vec4<f32>,
    color: vec4<f32>,
}

struct Uniforms {
    u_lights: array<Light, 4>,
    u_count: i32,
}

struct for_arrays_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct for_arrays_fs_out {
    @location(0) f_color: vec4<f32>,
}

const KERNEL: array<f32, 3> = array<f32, 3>(0.25f, 0.5f, 0.25f);
const TAPS: i32 = 3i;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@vertex 
fn for_arrays_vs(@location(0) a_pos: vec2<f32>) -> for_arrays_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return for_arrays_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
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
    var i_1: i32;
    var ramp: f32;
    var i_2: i32;

    c = vec3(0f);
    i = 0i;
    let _e8 = uniforms.u_count;
    loop {
        let _e9 = i;
        if !((_e9 < _e8)) {
            break;
        }
        let _e12 = i;
        if (u32(_e12) >= 4u) {
            break;
        }
        let _e17 = i;
        let l = uniforms.u_lights[_e17];
        let d = distance(v_uv_1, l.pos.xy);
        let _e26 = i;
        let _e33 = c;
        c = (_e33 + (l.color.xyz * (1f / ((1f + f32(_e26)) + (d * d)))));
        continuing {
            let _e35 = i;
            i = (_e35 + 1i);
        }
    }
    taps = array<f32, 3>();
    t_index = 0i;
    loop {
        let _e42 = t_index;
        if !((_e42 < 3i)) {
            break;
        }
        let _e46 = t_index;
        let k = KERNEL[_e46];
        let _e48 = t_index;
        taps[_e48] = (k * v_uv_1.y);
        continuing {
            let _e52 = t_index;
            t_index = (_e52 + 1i);
        }
    }
    blur = 0f;
    t_index_1 = 0i;
    loop {
        let _e56 = t_index_1;
        if !((_e56 < 3i)) {
            break;
        }
        let _e59 = t_index_1;
        let _e61 = taps[_e59];
        let _e62 = blur;
        blur = (_e62 + _e61);
        continuing {
            let _e64 = t_index_1;
            t_index_1 = (_e64 + 1i);
        }
    }
    i_1 = 0i;
    loop {
        let _e67 = i_1;
        if !((_e67 < 3i)) {
            break;
        }
        let _e70 = i_1;
        let _e72 = taps[_e70];
        let _e75 = i_1;
        let _e79 = blur;
        blur = (_e79 + (_e72 * KERNEL[((TAPS - 1i) - _e75)]));
        continuing {
            let _e81 = i_1;
            i_1 = (_e81 + 1i);
        }
    }
    ramp = 0f;
    {
        let j_count = select(0u, (u32(8i) - u32(5i)), (8i > 5i));
        i_2 = 1i;
        loop {
            let _e94 = i_2;
            if !((_e94 < 10i)) {
                break;
            }
            let _e97 = i_2;
            let i_step = (u32(_e97) - u32(1i));
            if (i_step >= j_count) {
                break;
            }
            if (i_step >= 3u) {
                break;
            }
            let j = (5i + i32(i_step));
            let k_1 = KERNEL[i32(i_step)];
            let _e108 = i_2;
            let _e112 = ramp;
            ramp = (_e112 + (f32((_e108 * j)) * k_1));
            continuing {
                let _e114 = i_2;
                i_2 = (_e114 + 1i);
            }
        }
    }
    let _e117 = c;
    let _e118 = blur;
    let _e121 = ramp;
    f_color = vec4<f32>((_e117 + vec3(_e118)), (_e121 / 50f));
    let _e125 = f_color;
    return for_arrays_fs_out(_e125);
}
