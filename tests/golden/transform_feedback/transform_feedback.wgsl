diagnostic(off, derivative_uniformity);

struct feedback_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_speed: f32,
    @location(1) o_pos: vec3<f32>,
    @location(2) o_vel: vec3<f32>,
    @location(3) @interpolate(flat) o_alive: i32,
}

@group(0) @binding(0) 
var<uniform> u_dt: f32;
var<private> a_pos: vec3<f32>;
var<private> a_vel: vec3<f32>;
var<private> v_speed: f32;
var<private> o_pos: vec3<f32>;
var<private> o_vel: vec3<f32>;
var<private> o_alive: i32;
var<private> gl_Position: vec4<f32>;

@vertex 
fn feedback_vs(@location(0) in_a_pos: vec3<f32>, @location(1) in_a_vel: vec3<f32>) -> feedback_vs_out {
    a_pos = in_a_pos;
    a_vel = in_a_vel;
    let _e5 = a_vel;
    let _e12 = u_dt;
    let v = (_e5 + (vec3<f32>(0f, -(9.81f), 0f) * _e12));
    let _e17 = a_pos;
    let _e19 = u_dt;
    o_pos = (_e17 + (v * _e19));
    o_vel = v;
    let _e26 = o_pos.y;
    o_alive = select(0i, 1i, (_e26 > 0f));
    v_speed = length(v);
    let _e36 = o_pos;
    gl_Position = vec4<f32>(_e36, 1f);
    let _e40 = gl_Position;
    let _e51 = v_speed;
    let _e53 = o_pos;
    let _e55 = o_vel;
    let _e57 = o_alive;
    return feedback_vs_out(vec4<f32>(_e40.x, -(_e40.y), ((_e40.z + _e40.w) * 0.5f), _e40.w), _e51, _e53, _e55, _e57);
}
