diagnostic(off, derivative_uniformity);

struct spec_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct spec_fs_out {
    @location(0) f_color: vec4<f32>,
}

@id(0) override TAPS: u32 = 4u;
@id(1) override SPREAD: f32 = 0.125f;
@id(2) override INVERT: bool = false;
@id(7) override OFFSET: i32 = -2i;

@group(0) @binding(0) 
var u_tex: texture_2d<f32>;
@group(0) @binding(1) 
var u_tex_sampler: sampler;

fn tap(i_1: u32) -> vec2<f32> {
    return vec2<f32>((f32(i_1) * SPREAD), 0f);
}

@vertex 
fn spec_vs(@location(0) a_pos: vec2<f32>) -> spec_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = (((a_pos * 0.5f) + vec2(0.5f)) + vec2((f32(OFFSET) * SPREAD)));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e16 = gl_Position;
    let _e25 = v_uv;
    return spec_vs_out(vec4<f32>(_e16.x, -(_e16.y), ((_e16.z + _e16.w) * 0.5f), _e16.w), _e25);
}

@fragment 
fn spec_fs(@location(0) v_uv_1: vec2<f32>) -> spec_fs_out {
    var f_color: vec4<f32>;
    var c: vec4<f32>;
    var i: i32;

    c = vec4(0f);
    i = 0i;
    loop {
        let _e8 = i;
        if !((_e8 < i32(TAPS))) {
            break;
        }
        let _e11 = i;
        let _e13 = tap(u32(_e11));
        let _e17 = textureSample(u_tex, u_tex_sampler, (v_uv_1 + _e13));
        let _e18 = c;
        c = (_e18 + _e17);
        continuing {
            let _e20 = i;
            i = (_e20 + 1i);
        }
    }
    let _e26 = c;
    c = (_e26 / vec4(f32(max(TAPS, 1u))));
    let _e33 = c;
    let _e35 = c;
    f_color = select(_e35, (vec4(1f) - _e33), INVERT);
    let _e37 = f_color;
    return spec_fs_out(_e37);
}
