diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_size: f32,
}

struct points_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct points_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@vertex 
fn points_vs(@location(0) a_pos: vec3<f32>) -> points_vs_out {
    var gl_PointSize: f32;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_size;
    gl_PointSize = (_e4 / max(a_pos.z, 0.1f));
    gl_Position = vec4<f32>(a_pos, 1f);
    let _e12 = gl_Position;
    return points_vs_out(vec4<f32>(_e12.x, -(_e12.y), ((_e12.z + _e12.w) * 0.5f), _e12.w));
}

@fragment 
fn points_fs() -> points_fs_out {
    var f_color: vec4<f32>;

    let _e1 = vec2(0.5f);
    let d = (_e1 - vec2(0.5f));
    if (dot(d, d) > 0.25f) {
        discard;
    }
    f_color = vec4<f32>(_e1, 1f, 1f);
    let _e10 = f_color;
    return points_fs_out(_e10);
}
