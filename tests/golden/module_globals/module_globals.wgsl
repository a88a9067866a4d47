diagnostic(off, derivative_uniformity);

struct Uniforms {
    pc_time: f32,
}

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
var<uniform> uniforms: Uniforms;

fn visit_ring(d: f32) {
    let _e2 = rings_seen;
    if (d < (f32((_e2 + 1i)) * RING_WIDTH)) {
        let _e14 = glow;
        glow = (_e14 + (1f / f32(RINGS)));
    }
    let _e16 = rings_seen;
    rings_seen = (_e16 + 1i);
    let _e20 = fade;
    fade = (_e20 * 0.9f);
    return;
}

@vertex 
fn rings_vs(@location(0) a_pos: vec2<f32>) -> rings_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position: vec4<f32>;

    v_uv = ((a_pos * 0.5f) + vec2(0.5f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e10 = gl_Position;
    let _e19 = v_uv;
    return rings_vs_out(vec4<f32>(_e10.x, -(_e10.y), ((_e10.z + _e10.w) * 0.5f), _e10.w), _e19);
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
        let _e16 = uniforms.pc_time;
        visit_ring((d_1 + (0.01f * sin(_e16))));
        continuing {
            let _e20 = i;
            i = (_e20 + 1i);
        }
    }
    let _e26 = glow;
    let c = mix(COOL, WARM, vec3(_e26));
    let _e31 = fade;
    let _e34 = rings_seen;
    f_color = vec4<f32>((c * _e31), (f32(_e34) / f32(RINGS)));
    let _e39 = f_color;
    return rings_fs_out(_e39);
}
