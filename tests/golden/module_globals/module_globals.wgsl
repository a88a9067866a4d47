diagnostic(off, derivative_uniformity);

struct rings_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct rings_fs_out {
    @location(0) f_color: vec4<f32>,
}

const RINGS: i32 = 4i;
const RING_WIDTH: f32 = 0.25f;
const COOL: vec3<f32> = vec3<f32>(0.2f, 0.4f, 1f);
const WARM: vec3<f32> = vec3<f32>(1f, 0.6f, 0.3f);

var<private> rings_seen: i32 = i32();
var<private> glow: f32 = 0f;
var<private> fade: f32 = 1f;
@group(0) @binding(0) 
var<uniform> pc_time: f32;

fn visit_ring(d: f32) {
    let _e2 = rings_seen;
    if (d < (f32((_e2 + 1i)) * RING_WIDTH)) {
        let _e14 = glow;
        glow = (_e14 + (1f / f32(RINGS)));
    }
    let _e18 = rings_seen;
    rings_seen = (_e18 + 1i);
    let _e22 = fade;
    fade = (_e22 * 0.9f);
    return;
}

@vertex 
fn rings_vs(@location(0) a_pos: vec2<f32>) -> rings_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e12 = gl_Position;
    let _e23 = v_uv;
    return rings_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w), _e23);
}

@fragment 
fn rings_fs(@location(0) v_uv_1: vec2<f32>) -> rings_fs_out {
    var f_color: vec4<f32>;
    var i: i32;

    let d_1 = (length((v_uv_1 - vec2(0.5f))) * 2f);
    i = 0i;
    loop {
        let _e10 = i;
        if !((_e10 < RINGS)) {
            break;
        }
        let _e15 = pc_time;
        visit_ring((d_1 + (0.01f * sin(_e15))));
        continuing {
            let _e19 = i;
            i = (_e19 + 1i);
        }
    }
    let _e25 = glow;
    let c = mix(COOL, WARM, vec3(_e25));
    let _e30 = fade;
    let _e33 = rings_seen;
    f_color = vec4<f32>((c * _e30), (f32(_e33) / f32(RINGS)));
    let _e40 = f_color;
    return rings_fs_out(_e40);
}
