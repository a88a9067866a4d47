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
        let _e13 = i;
        if (u32(_e13) >= 4u) {
            break;
        }
        let _e20 = i;
        let l = uniforms.u_lights[_e20];
        let d = distance(v_uv_1, l.pos.xy);
        let _e32 = i;
        let _e39 = c;
        c = (_e39 + (l.color.xyz * (1f / ((1f + f32(_e32)) + (d * d)))));
        continuing {
            let _e41 = i;
            i = (_e41 + 1i);
        }
    }
    taps = array<f32, 3>();
    t_index = 0i;
    loop {
        let _e49 = t_index;
        if !((_e49 < 3i)) {
            break;
        }
        let _e54 = t_index;
        let k = KERNEL[_e54];
        let _e58 = t_index;
        taps[_e58] = (k * v_uv_1.y);
        continuing {
            let _e62 = t_index;
            t_index = (_e62 + 1i);
        }
    }
    blur = 0f;
    t_index_1 = 0i;
    loop {
        let _e70 = t_index_1;
        if !((_e70 < 3i)) {
            break;
        }
        let _e76 = t_index_1;
        let _e78 = taps[_e76];
        let _e79 = blur;
        blur = (_e79 + _e78);
        continuing {
            let _e81 = t_index_1;
            t_index_1 = (_e81 + 1i);
        }
    }
    i_1 = 0i;
    loop {
        let _e87 = i_1;
        if !((_e87 < 3i)) {
            break;
        }
        let _e93 = i_1;
        let _e95 = taps[_e93];
        let _e101 = i_1;
        let _e105 = blur;
        blur = (_e105 + (_e95 * KERNEL[((TAPS - 1i) - _e101)]));
        continuing {
            let _e107 = i_1;
            i_1 = (_e107 + 1i);
        }
    }
    ramp = 0f;
    {
        let j_count = select(0u, (u32(8i) - u32(5i)), (8i > 5i));
        i_2 = 1i;
        loop {
            let _e125 = i_2;
            if !((_e125 < 10i)) {
                break;
            }
            let _e129 = i_2;
            let i_step = (u32(_e129) - u32(1i));
            if (i_step >= j_count) {
                break;
            }
            if (i_step >= 3u) {
                break;
            }
            let j = (5i + i32(i_step));
            let k_1 = KERNEL[i32(i_step)];
            let _e145 = i_2;
            let _e149 = ramp;
            ramp = (_e149 + (f32((_e145 * j)) * k_1));
            continuing {
                let _e151 = i_2;
                i_2 = (_e151 + 1i);
            }
        }
    }
    let _e156 = c;
    let _e158 = blur;
    let _e162 = ramp;
    f_color = vec4<f32>((_e156 + vec3(_e158)), (_e162 / 50f));
    let _e167 = f_color;
    return for_arrays_fs_out(_e167);
}
