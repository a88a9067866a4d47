diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_model: mat4x4<f32>,
    u_view_proj: mat4x4<f32>,
    u_albedo: vec3<f32>,
    u_light_pos: vec3<f32>,
    u_cam_pos: vec3<f32>,
}

struct deferred_geometry_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_world: vec3<f32>,
    @location(1) v_normal: vec3<f32>,
}

struct deferred_geometry_fs_out {
    @location(0) g_albedo: vec4<f32>,
    @location(1) g_normal: vec4<f32>,
    @location(2) g_position: vec4<f32>,
}

struct deferred_lighting_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_uv: vec2<f32>,
}

struct deferred_lighting_fs_out {
    @location(0) f_color: vec4<f32>,
}

const POSITION_RANGE: f32 = 8f;

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;
@group(0) @binding(1) 
var gbuf_albedo: texture_2d<f32>;
@group(0) @binding(2) 
var gbuf_albedo_sampler: sampler;
@group(0) @binding(3) 
var gbuf_normal: texture_2d<f32>;
@group(0) @binding(4) 
var gbuf_normal_sampler: sampler;
@group(0) @binding(5) 
var gbuf_position: texture_2d<f32>;
@group(0) @binding(6) 
var gbuf_position_sampler: sampler;

@vertex 
fn deferred_geometry_vs(@location(0) a_pos: vec3<f32>, @location(1) a_normal: vec3<f32>) -> deferred_geometry_vs_out {
    var v_world: vec3<f32>;
    var v_normal: vec3<f32>;
    var gl_Position: vec4<f32>;

    let _e4 = uniforms.u_model;
    let world = (_e4 * vec4<f32>(a_pos, 1f));
    v_world = world.xyz;
    let _e12 = uniforms.u_model;
    v_normal = (_e12 * vec4<f32>(a_normal, 0f)).xyz;
    let _e19 = uniforms.u_view_proj;
    gl_Position = (_e19 * world);
    let _e21 = gl_Position;
    let _e31 = v_world;
    let _e32 = v_normal;
    return deferred_geometry_vs_out(vec4<f32>(_e21.x, -(_e21.y), ((_e21.z + _e21.w) * 0.5f), _e21.w), _e31, _e32);
}

@fragment 
fn deferred_geometry_fs(@location(0) v_world_1: vec3<f32>, @location(1) v_normal_1: vec3<f32>) -> deferred_geometry_fs_out {
    var g_albedo: vec4<f32>;
    var g_normal: vec4<f32>;
    var g_position: vec4<f32>;

    let _e5 = uniforms.u_albedo;
    g_albedo = vec4<f32>(_e5, 1f);
    g_normal = vec4<f32>(((normalize(v_normal_1) * 0.5f) + vec3(0.5f)), 1f);
    g_position = vec4<f32>(((v_world_1 / vec3(POSITION_RANGE)) + vec3(0.5f)), 1f);
    let _e22 = g_albedo;
    let _e23 = g_normal;
    let _e24 = g_position;
    return deferred_geometry_fs_out(_e22, _e23, _e24);
}

@vertex 
fn deferred_lighting_vs(@builtin(vertex_index) VertexID: u32) -> deferred_lighting_vs_out {
    var v_uv: vec2<f32>;
    var gl_Position_1: vec4<f32>;

    let _e1 = i32(VertexID);
    let corner = vec2<f32>(f32(((_e1 << u32(1i)) & 2i)), f32((_e1 & 2i)));
    v_uv = corner;
    gl_Position_1 = vec4<f32>(((corner * 2f) - vec2(1f)), 0f, 1f);
    let _e20 = gl_Position_1;
    let _e30 = v_uv;
    return deferred_lighting_vs_out(vec4<f32>(_e20.x, -(_e20.y), ((_e20.z + _e20.w) * 0.5f), _e20.w), _e30);
}

@fragment 
fn deferred_lighting_fs(@location(0) v_uv_1: vec2<f32>) -> deferred_lighting_fs_out {
    var f_color: vec4<f32>;

    let albedo = textureSample(gbuf_albedo, gbuf_albedo_sampler, v_uv_1);
    let _e6 = textureSample(gbuf_normal, gbuf_normal_sampler, v_uv_1);
    let n = normalize(((_e6.xyz * 2f) - vec3(1f)));
    let _e16 = textureSample(gbuf_position, gbuf_position_sampler, v_uv_1);
    let p = ((_e16.xyz - vec3(0.5f)) * POSITION_RANGE);
    let _e25 = uniforms.u_light_pos;
    let to_light = (_e25 - p);
    let d = max(length(to_light), 0.001f);
    let l = (to_light / vec3(d));
    let diffuse = ((max(dot(n, l), 0f) * 20f) / (1f + (d * d)));
    let _e41 = uniforms.u_cam_pos;
    let h = normalize((l + normalize((_e41 - p))));
    let specular = (pow(max(dot(n, h), 0f), 32f) * 0.5f);
    let lit = ((albedo.xyz * (0.1f + diffuse)) + vec3(specular));
    f_color = vec4<f32>(mix(vec3<f32>(0.05f, 0.06f, 0.1f), lit, vec3(albedo.w)), 1f);
    let _e65 = f_color;
    return deferred_lighting_fs_out(_e65);
}
