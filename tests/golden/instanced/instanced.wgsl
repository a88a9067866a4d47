diagnostic(off, derivative_uniformity);

struct Instance {
    offset_scale: vec4<f32>,
    color: vec4<f32>,
}

struct Uniforms {
    u_view_proj: mat4x4<f32>,
    u_instances: array<Instance, 64>,
    u_time: f32,
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
var<uniform> uniforms: Uniforms;

fn spin(p: vec3<f32>, angle: f32) -> vec3<f32> {
    let c = cos(angle);
    let s = sin(angle);
    return vec3<f32>(((c * p.x) + (s * p.z)), p.y, ((-(s) * p.x) + (c * p.z)));
}

@vertex 
fn instanced_vs(@location(0) a_position: vec3<f32>, @location(1) a_normal: vec3<f32>, @builtin(instance_index) InstanceID: u32, @builtin(vertex_index) VertexID: u32) -> instanced_vs_out {
    var v_color: vec4<f32>;
    var v_normal: vec3<f32>;
    var v_bary: vec3<f32>;
    var v_instance: i32;
    var gl_Position: vec4<f32>;

    let _e3 = i32(InstanceID);
    let inst = uniforms.u_instances[(_e3 % MAX_INSTANCES)];
    let _e13 = uniforms.u_time;
    let angle_1 = (_e13 + (f32(_e3) * 0.37f));
    let _e18 = spin(a_position, angle_1);
    let p_1 = ((_e18 * inst.offset_scale.w) + inst.offset_scale.xyz);
    let _e26 = spin(a_normal, angle_1);
    v_normal = _e26;
    v_color = inst.color;
    let corner = (i32(VertexID) % 3i);
    v_bary = vec3<f32>(select(0f, 1f, (corner == 0i)), select(0f, 1f, (corner == 1i)), select(0f, 1f, (corner == 2i)));
    v_instance = _e3;
    let _e47 = uniforms.u_view_proj;
    gl_Position = (_e47 * vec4<f32>(p_1, 1f));
    let _e50 = gl_Position;
    let _e60 = v_color;
    let _e61 = v_normal;
    let _e62 = v_bary;
    let _e63 = v_instance;
    return instanced_vs_out(vec4<f32>(_e50.x, -(_e50.y), ((_e50.z + _e50.w) * 0.5f), _e50.w), _e60, _e61, _e62, _e63);
}

@fragment 
fn instanced_fs(@location(0) v_color_1: vec4<f32>, @location(1) v_normal_1: vec3<f32>, @location(2) v_bary_1: vec3<f32>, @location(3) @interpolate(flat) v_instance_1: i32) -> instanced_fs_out {
    var f_color: vec4<f32>;

    let light = ((max(dot(normalize(v_normal_1), normalize(vec3<f32>(0.3f, 1f, 0.5f))), 0f) * 0.8f) + 0.2f);
    let edge = min(min(v_bary_1.x, v_bary_1.y), v_bary_1.z);
    let _e22 = fwidth(edge);
    let wire = (1f - smoothstep(0f, (_e22 * 1.5f), edge));
    let stripe = select(0.85f, 1f, ((v_instance_1 & 1i) == 0i));
    f_color = vec4<f32>(mix(((v_color_1.xyz * light) * stripe), vec3(0f), vec3(wire)), v_color_1.w);
    let _e42 = f_color;
    return instanced_fs_out(_e42);
}
