diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_steps: i32,
    u_threshold: f32,
}

struct flow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct flow_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

fn band(x: f32) -> i32 {
    if (x < 0.25f) {
        return 0i;
    } else {
        if (x < 0.5f) {
            return 1i;
        } else {
            if (x < 0.75f) {
                return 2i;
            } else {
                return 3i;
            }
        }
    }
}

@vertex 
fn flow_vs(@location(0) a_pos: vec2<f32>) -> flow_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return flow_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
}

@fragment 
fn flow_fs(@location(0) v_uv_1: vec2<f32>) -> flow_fs_out {
    var f_color: vec4<f32>;
    var acc: f32;
    var i: i32;
    var count: u32;
    var k: i32;
    var level: f32;

    acc = 0f;
    i = 0i;
    loop {
        let _e5 = i;
        let _e8 = uniforms.u_steps;
        if !((_e5 < _e8)) {
            break;
        }
        let _e12 = i;
        i = (_e12 + 1i);
        let _e14 = i;
        if ((_e14 % 2i) == 0i) {
            continue;
        }
        let _e19 = i;
        let _e22 = acc;
        acc = (_e22 + (1f / f32(_e19)));
        let _e24 = acc;
        let _e26 = uniforms.u_threshold;
        if (_e24 > _e26) {
            break;
        }
    }
    count = 0u;
    k = 2i;
    loop {
        let _e32 = k;
        if !((_e32 < 7i)) {
            break;
        }
        let _e35 = k;
        let _e37 = count;
        count = (_e37 + u32(_e35));
        continuing {
            let _e39 = k;
            k = (_e39 + 1i);
        }
    }
    let _e43 = band(v_uv_1.x);
    level = (f32(_e43) / 3f);
    let _e51 = level;
    level = (_e51 * select(0.5f, 1f, (v_uv_1.y > 0.5f)));
    let _e54 = acc;
    let _e55 = level;
    let _e56 = count;
    f_color = vec4<f32>(_e54, _e55, (f32(_e56) / 20f), 1f);
    let _e61 = f_color;
    return flow_fs_out(_e61);
}
