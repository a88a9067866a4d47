diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_scale: f32,
    u_offset: vec2<f32>,
    u_tint: vec3<f32>,
    u_color: vec4<f32>,
    u_flip: u32,
    u_mask: vec2<u32>,
    u_count: i32,
    u_index: u32,
    u_weights: array<vec4<f32>, 9>,
    u_taps: array<vec4<f32>, 3>,
    u_shear: array<vec4<f32>, 3>,
    u_rot: array<vec4<f32>, 2>,
    u_basis: mat3x3<f32>,
    u_model: mat4x4<f32>,
    u_steps: array<vec4<i32>, 4>,
    u_gains: array<vec3<f32>, 2>,
    u_bias: f32,
    u_levels: vec2<u32>,
    u_on: vec3<u32>,
    u_mix: array<vec4<f32>, 4>,
}

struct blocks_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_p: vec2<f32>,
    @location(1) v_m: vec2<f32>,
    @location(2) v_k: f32,
}

struct blocks_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@vertex 
fn blocks_vs(@builtin(vertex_index) VertexID: u32) -> blocks_vs_out {
    var v_p: vec2<f32>;
    var v_m: vec2<f32>;
    var v_k: f32;
    var gl_Position: vec4<f32>;

    let _e1 = i32(VertexID);
    let c = vec2<f32>(f32(((_e1 << u32(1i)) & 2i)), f32((_e1 & 2i)));
    let a_pos = ((c * 2f) - vec2(1f));
    let _e20 = uniforms.u_shear[0];
    let _e23 = uniforms.u_shear[1];
    let _e26 = uniforms.u_shear[2];
    let _e32 = uniforms.u_offset;
    v_p = ((mat3x2<f32>(_e20.xy, _e23.xy, _e26.xy) * vec3<f32>(a_pos, 1f)) + _e32);
    let _e37 = uniforms.u_rot[0];
    let _e40 = uniforms.u_rot[1];
    v_m = (mat2x2<f32>(_e37.xy, _e40.xy) * a_pos);
    let _e47 = uniforms.u_weights[0];
    let _e51 = uniforms.u_weights[8];
    let _e54 = uniforms.u_count;
    let _e59 = uniforms.u_flip;
    let _e68 = uniforms.u_steps[3];
    v_k = (((_e47.x + (_e51.x * f32(_e54))) + select(0f, 0.25f, (_e59 != 0u))) + (f32(_e68.x) * 0.01f));
    let _e76 = uniforms.u_model;
    let _e78 = uniforms.u_scale;
    gl_Position = (_e76 * vec4<f32>((a_pos * _e78), 0f, 1f));
    let _e82 = gl_Position;
    let _e92 = v_p;
    let _e93 = v_m;
    let _e94 = v_k;
    return blocks_vs_out(vec4<f32>(_e82.x, -(_e82.y), ((_e82.z + _e82.w) * 0.5f), _e82.w), _e92, _e93, _e94);
}

@fragment 
fn blocks_fs(@location(0) v_p_1: vec2<f32>, @location(1) v_m_1: vec2<f32>, @location(2) v_k_1: f32) -> blocks_fs_out {
    var f_color: vec4<f32>;
    var s: f32;
    var i: i32;
    var on: f32;

    s = 0f;
    i = 0i;
    loop {
        let _e8 = i;
        if !((_e8 < 9i)) {
            break;
        }
        let _e13 = i;
        let _e15 = uniforms.u_weights[_e13];
        let _e17 = s;
        s = (_e17 + _e15.x);
        continuing {
            let _e19 = i;
            i = (_e19 + 1i);
        }
    }
    let _e24 = uniforms.u_index;
    let _e27 = uniforms.u_taps[_e24].x;
    let _e31 = uniforms.u_taps[2].y;
    let t = (_e27 + _e31);
    let _e34 = uniforms.u_basis;
    let _e36 = uniforms.u_tint;
    let c_1 = (_e34 * _e36);
    let _e40 = uniforms.u_gains[1];
    let _e42 = uniforms.u_bias;
    let g = (_e40 * _e42);
    let _e49 = uniforms.u_mix[0];
    let _e52 = uniforms.u_mix[1];
    let _e55 = uniforms.u_mix[2];
    let _e58 = uniforms.u_mix[3];
    let mx = (vec2<f32>(v_p_1.x, v_m_1.y) * mat4x2<f32>(_e49.xy, _e52.xy, _e55.xy, _e58.xy));
    let _e65 = uniforms.u_mask.y;
    on = select(0f, 0.05f, (_e65 != 0u));
    let _e72 = uniforms.u_on.x;
    if (_e72 != 0u) {
        let _e75 = on;
        on = (_e75 + 0.1f);
    }
    let _e79 = uniforms.u_on.z;
    if (_e79 != 0u) {
        let _e82 = on;
        on = (_e82 + 0.2f);
    }
    let _e86 = uniforms.u_levels.x;
    let _e89 = uniforms.u_levels.y;
    let lv = (f32((_e86 + _e89)) * 0.01f);
    let _e95 = uniforms.u_color;
    let base = (((_e95.xyz * 0.5f) + (c_1 * 0.1f)) + g);
    let _e110 = on;
    let _e118 = s;
    let _e124 = uniforms.u_steps[1];
    let rgb = (((base + (vec3<f32>(v_p_1.x, v_p_1.y, v_k_1) * 0.25f)) + (vec3<f32>(mx.x, (mx.y + _e110), (mx.z + lv)) * 0.1f)) + vec3((((t * 0.1f) + (_e118 * 0.02f)) + (f32(_e124.x) * 0.01f))));
    f_color = vec4<f32>(clamp(rgb, vec3(0f), vec3(1f)), 1f);
    let _e137 = f_color;
    return blocks_fs_out(_e137);
}
