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
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return flow_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
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
        let _e6 = i;
        let _e9 = uniforms.u_steps;
        if !((_e6 < _e9)) {
            break;
        }
        let _e14 = i;
        i = (_e14 + 1i);
        let _e17 = i;
        if ((_e17 % 2i) == 0i) {
            continue;
        }
        let _e25 = i;
        let _e28 = acc;
        acc = (_e28 + (1f / f32(_e25)));
        let _e31 = acc;
        let _e34 = uniforms.u_threshold;
        if (_e31 > _e34) {
            break;
        }
    }
    count = 0u;
    k = 2i;
    loop {
        let _e41 = k;
        if !((_e41 < 7i)) {
            break;
        }
        let _e46 = k;
        let _e48 = count;
        count = (_e48 + u32(_e46));
        continuing {
            let _e50 = k;
            k = (_e50 + 1i);
        }
    }
    let _e55 = band(v_uv_1.x);
    level = (f32(_e55) / 3f);
    let _e66 = level;
    level = (_e66 * select(0.5f, 1f, (v_uv_1.y > 0.5f)));
    let _e70 = acc;
    let _e72 = level;
    let _e74 = count;
    f_color = vec4<f32>(_e70, _e72, (f32(_e74) / 20f), 1f);
    let _e81 = f_color;
    return flow_fs_out(_e81);
}
