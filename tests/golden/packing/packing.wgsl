diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_albedo: vec4<f32>,
}

struct packing_vs_out {
    @builtin(position) gl_Position: vec4<f32>,
    @location(0) v_normal: vec3<f32>,
}

struct packing_fs_out {
    @location(0) g_packed: vec4<u32>,
    @location(1) f_check: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@vertex 
fn packing_vs(@location(0) a_pos: vec2<f32>) -> packing_vs_out {
    var v_normal: vec3<f32>;
    var gl_Position: vec4<f32>;

    v_normal = normalize(vec3<f32>(a_pos, 1f));
    gl_Position = vec4<f32>(a_pos, 0f, 1f);
    let _e8 = gl_Position;
    let _e18 = v_normal;
    return packing_vs_out(vec4<f32>(_e8.x, -(_e8.y), ((_e8.z + _e8.w) * 0.5f), _e8.w), _e18);
}

@fragment 
fn packing_fs(@location(0) v_normal_1: vec3<f32>, @builtin(position) FragCoord: vec4<f32>) -> packing_fs_out {
    var g_packed: vec4<u32>;
    var f_check: vec4<f32>;

    let n = normalize(v_normal_1);
    let _e5 = uniforms.u_albedo;
    let albedo = pack4x8unorm(_e5);
    let normal = (pack2x16snorm(n.xy) ^ pack2x16unorm(((n.xy * 0.5f) + vec2(0.5f))));
    let depth = pack2x16float(vec2<f32>(FragCoord.z, n.z));
    g_packed = vec4<u32>(albedo, normal, depth, pack4x8snorm(vec4<f32>(n, -(1f))));
    let _e28 = g_packed.w;
    let back = (unpack4x8unorm(albedo) + unpack4x8snorm(_e28));
    let nz = ((unpack2x16float(depth).y + (unpack2x16snorm(normal).x * 0f)) + (unpack2x16unorm(normal).y * 0f));
    f_check = vec4<f32>(back.xyz, nz);
    let _e45 = g_packed;
    let _e46 = f_check;
    return packing_fs_out(_e45, _e46);
}
