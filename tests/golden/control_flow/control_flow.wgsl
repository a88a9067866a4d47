diagnostic(off, derivative_uniformity);

struct flow_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct flow_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_steps: i32;
@group(0) @binding(1) 
var<uniform> u_threshold: f32;

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
        let _e8 = u_steps;
        if !((_e6 < _e8)) {
            break;
        }
        let _e13 = i;
        i = (_e13 + 1i);
        let _e16 = i;
        if ((_e16 % 2i) == 0i) {
            continue;
        }
        let _e24 = i;
        let _e27 = acc;
        acc = (_e27 + (1f / f32(_e24)));
        let _e30 = acc;
        let _e32 = u_threshold;
        if (_e30 > _e32) {
            break;
        }
    }
    count = 0u;
    k = 2i;
    loop {
        let _e39 = k;
        if !((_e39 < 7i)) {
            break;
        }
        let _e44 = k;
        let _e46 = count;
        count = (_e46 + u32(_e44));
        continuing {
            let _e48 = k;
            k = (_e48 + 1i);
        }
    }
    let _e53 = band(v_uv_1.x);
    level = (f32(_e53) / 3f);
    let _e64 = level;
    level = (_e64 * select(0.5f, 1f, (v_uv_1.y > 0.5f)));
    let _e68 = acc;
    let _e70 = level;
    let _e72 = count;
    f_color = vec4<f32>(_e68, _e70, (f32(_e72) / 20f), 1f);
    let _e79 = f_color;
    return flow_fs_out(_e79);
}
