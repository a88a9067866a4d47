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
var<private> a_pos: vec2<f32>;
var<private> v_uv: vec2<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_Position: vec4<f32>;

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
fn flow_vs(@location(0) in_a_pos: vec2<f32>) -> flow_vs_out {
    a_pos = in_a_pos;
    let _e4 = a_pos;
    v_uv = ((_e4 * 0.5f) + vec2(0.5f));
    let _e12 = a_pos;
    gl_Position = vec4<f32>(_e12, 0f, 1f);
    let _e17 = gl_Position;
    let _e28 = v_uv;
    return flow_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w), _e28);
}

@fragment 
fn flow_fs(@location(0) in_v_uv: vec2<f32>) -> flow_fs_out {
    var acc: f32;
    var i: i32;
    var count: u32;
    var k: i32;
    var level: f32;

    v_uv = in_v_uv;
    acc = 0f;
    i = 0i;
    loop {
        let _e7 = i;
        let _e9 = u_steps;
        if !((_e7 < _e9)) {
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
        let _e33 = u_threshold;
        if (_e31 > _e33) {
            break;
        }
    }
    count = 0u;
    k = 2i;
    loop {
        let _e40 = k;
        if !((_e40 < 7i)) {
            break;
        }
        let _e45 = k;
        let _e47 = count;
        count = (_e47 + u32(_e45));
        continuing {
            let _e49 = k;
            k = (_e49 + 1i);
        }
    }
    let _e55 = v_uv.x;
    let _e56 = band(_e55);
    level = (f32(_e56) / 3f);
    let _e63 = v_uv.y;
    let _e69 = level;
    level = (_e69 * select(0.5f, 1f, (_e63 > 0.5f)));
    let _e73 = acc;
    let _e75 = level;
    let _e77 = count;
    f_color = vec4<f32>(_e73, _e75, (f32(_e77) / 20f), 1f);
    let _e84 = f_color;
    return flow_fs_out(_e84);
}
