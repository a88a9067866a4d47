diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_mode: i32,
}

struct enums_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct enums_fs_out {
    @location(0) f_color: vec4<f32>,
}

const WEIGHTS: array<f32, 4> = array<f32, 4>(0.25f, 0.5f, 0.75f, 1f);

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn attenuate(f: u32, d: f32) -> f32 {
    if (f == 1u) {
        return 1f;
    } else {
        if (f == 2u) {
            return max((1f - d), 0f);
        }
    }
    return (1f / (1f + ((f32(f) * d) * d)));
}

fn channel(c: vec4<f32>, ch: i32) -> f32 {
    return c[ch];
}

@vertex 
fn enums_vs(@location(0) a_pos: vec2<f32>) -> enums_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return enums_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn enums_fs(@location(0) v_uv_1: vec2<f32>) -> enums_fs_out {
    var f_color: vec4<f32>;

    let _e3 = uniforms.u_mode;
    let ch_1 = select(2i, 0i, (_e3 == 0i));
    let f_1 = select(2u, 8u, (ch_1 > 1i));
    let c_1 = vec4<f32>(v_uv_1, 0.5f, 1f);
    let _e17 = attenuate(f_1, length(v_uv_1));
    let _e19 = channel(c_1, ch_1);
    f_color = vec4<f32>((_e19 * _e17), WEIGHTS[3], (f32(ch_1) / 3f), 1f);
    let _e27 = f_color;
    return enums_fs_out(_e27);
}
