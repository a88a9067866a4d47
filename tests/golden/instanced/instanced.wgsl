diagnostic(off, derivative_uniformity);

struct Instance {
    offset_scale: vec4<f32>,
    color: vec4<f32>,
}

struct instanced_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_color: vec4<f32>,
    @location(1) v_normal: vec3<f32>,
    @location(2) v_bary: vec3<f32>,
    @location(3) @interpolate(flat) v_instance: i32,
}

struct instanced_fs_out {
    @location(0) f_color: vec4<f32>,
}

const MAX_INSTANCES: i32 = 64i;

@group(0) @binding(0) 
var<uniform> u_view_proj: mat4x4<f32>;
@group(0) @binding(1) 
var<uniform> u_instances: array<Instance, 64>;
@group(0) @binding(2) 
var<uniform> u_time: f32;
var<private> a_position: vec3<f32>;
var<private> a_normal: vec3<f32>;
var<private> v_color: vec4<f32>;
var<private> v_normal: vec3<f32>;
var<private> v_bary: vec3<f32>;
var<private> v_instance: i32;
var<private> f_color: vec4<f32>;
var<private> gl_InstanceID: i32;
var<private> gl_VertexID: i32;
var<private> gl_Position: vec4<f32>;

fn spin(p: vec3<f32>, angle: f32) -> vec3<f32> {
    let c = cos(angle);
    let s = sin(angle);
    return vec3<f32>(((c * p.x) + (s * p.z)), p.y, ((-(s) * p.x) + (c * p.z)));
}

@vertex 
fn instanced_vs(@location(0) in_a_position: vec3<f32>, @location(1) in_a_normal: vec3<f32>, @builtin(instance_index) in_InstanceID: u32, @builtin(vertex_index) in_VertexID: u32) -> instanced_vs_out {
    a_position = in_a_position;
    a_normal = in_a_normal;
    gl_InstanceID = i32(in_InstanceID);
    gl_VertexID = i32(in_VertexID);
    let _e12 = gl_InstanceID;
    let inst = u_instances[(_e12 % MAX_INSTANCES)];
    let _e18 = u_time;
    let _e20 = gl_InstanceID;
    let angle_1 = (_e18 + (f32(_e20) * 0.37f));
    let _e26 = a_position;
    let _e27 = spin(_e26, angle_1);
    let p_1 = ((_e27 * inst.offset_scale.w) + inst.offset_scale.xyz);
    let _e36 = a_normal;
    let _e37 = spin(_e36, angle_1);
    v_normal = _e37;
    v_color = inst.color;
    let _e41 = gl_VertexID;
    let corner = (_e41 % 3i);
    v_bary = vec3<f32>(select(0f, 1f, (corner == 0i)), select(0f, 1f, (corner == 1i)), select(0f, 1f, (corner == 2i)));
    let _e63 = gl_InstanceID;
    v_instance = _e63;
    let _e66 = u_view_proj;
    gl_Position = (_e66 * vec4<f32>(p_1, 1f));
    let _e71 = gl_Position;
    let _e82 = v_color;
    let _e84 = v_normal;
    let _e86 = v_bary;
    let _e88 = v_instance;
    return instanced_vs_out(vec4<f32>(_e71.x, -(_e71.y), ((_e71.z + _e71.w) * 0.5f), _e71.w), _e82, _e84, _e86, _e88);
}

@fragment 
fn instanced_fs(@location(0) in_v_color: vec4<f32>, @location(1) in_v_normal: vec3<f32>, @location(2) in_v_bary: vec3<f32>, @location(3) @interpolate(flat) in_v_instance: i32) -> instanced_fs_out {
    v_color = in_v_color;
    v_normal = in_v_normal;
    v_bary = in_v_bary;
    v_instance = in_v_instance;
    let _e9 = v_normal;
    let light = ((max(dot(normalize(_e9), normalize(vec3<f32>(0.3f, 1f, 0.5f))), 0f) * 0.8f) + 0.2f);
    let _e25 = v_bary.x;
    let _e28 = v_bary.y;
    let _e32 = v_bary.z;
    let edge = min(min(_e25, _e28), _e32);
    let _e36 = fwidth(edge);
    let wire = (1f - smoothstep(0f, (_e36 * 1.5f), edge));
    let _e42 = v_instance;
    let stripe = select(0.85f, 1f, ((_e42 & 1i) == 0i));
    let _e52 = v_color;
    let _e62 = v_color.w;
    f_color = vec4<f32>(mix(((_e52.xyz * light) * stripe), vec3(0f), vec3(wire)), _e62);
    let _e65 = f_color;
    return instanced_fs_out(_e65);
}
