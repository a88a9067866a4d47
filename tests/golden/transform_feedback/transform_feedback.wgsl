diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_dt: f32,
}

struct feedback_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_speed: f32,
    @location(1) o_pos: vec3<f32>,
    @location(2) o_vel: vec3<f32>,
    @location(3) @interpolate(flat) o_alive: i32,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@vertex 
fn feedback_vs(@location(0) a_pos: vec3<f32>, @location(1) a_vel: vec3<f32>) -> feedback_vs_out {
    var v_speed: f32;
    var o_pos: vec3<f32>;
    var o_vel: vec3<f32>;
    var o_alive: i32;
    var gl_Position: vec4<f32>;

    let _e8 = uniforms.u_dt;
    let v = (a_vel + (vec3<f32>(0f, -(9.81f), 0f) * _e8));
    let _e13 = uniforms.u_dt;
    o_pos = (a_pos + (v * _e13));
    o_vel = v;
    let _e19 = o_pos.y;
    o_alive = select(0i, 1i, (_e19 > 0f));
    v_speed = length(v);
    let _e27 = o_pos;
    gl_Position = vec4<f32>(_e27, 1f);
    let _e30 = gl_Position;
    let _e40 = v_speed;
    let _e41 = o_pos;
    let _e42 = o_vel;
    let _e43 = o_alive;
    return feedback_vs_out(vec4<f32>(_e30.x, -(_e30.y), ((_e30.z + _e30.w) * 0.5f), _e30.w), _e40, _e41, _e42, _e43);
}
