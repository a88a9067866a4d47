diagnostic(off, derivative_uniformity);

struct points_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
}

struct points_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_size: f32;
var<private> a_pos: vec3<f32>;
var<private> f_color: vec4<f32>;
var<private> gl_PointSize: f32;
var<private> gl_Position: vec4<f32>;
var<private> gl_PointCoord: vec2<f32>;

@vertex 
fn points_vs(@location(0) in_a_pos: vec3<f32>) -> points_vs_out {
    a_pos = in_a_pos;
    let _e4 = u_size;
    let _e7 = a_pos.z;
    gl_PointSize = (_e4 / max(_e7, 0.1f));
    let _e13 = a_pos;
    gl_Position = vec4<f32>(_e13, 1f);
    let _e17 = gl_Position;
    return points_vs_out(vec4<f32>(_e17.x, -(_e17.y), ((_e17.z + _e17.w) * 0.5f), _e17.w));
}

@fragment 
fn points_fs() -> points_fs_out {
    gl_PointCoord = vec2(0.5f);
    let _e4 = gl_PointCoord;
    let d = (_e4 - vec2(0.5f));
    if (dot(d, d) > 0.25f) {
        discard;
    }
    let _e13 = gl_PointCoord;
    f_color = vec4<f32>(_e13, 1f, 1f);
    let _e18 = f_color;
    return points_fs_out(_e18);
}
