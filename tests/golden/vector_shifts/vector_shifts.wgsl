diagnostic(off, derivative_uniformity);

struct Uniforms {
    u_bits: i32,
    u_mask: vec4<u32>,
}

struct vector_shifts_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> uniforms: Uniforms;

@fragment 
fn vector_shifts_fs(@builtin(position) FragCoord: vec4<f32>) -> vector_shifts_fs_out {
    var f_color: vec4<f32>;
    var acc: vec3<i32>;

    let texel = vec2<i32>(FragCoord.xy);
    let tile = (texel >> vec2(u32(3i)));
    let _e9 = uniforms.u_mask;
    let _e11 = uniforms.u_bits;
    let unpacked = ((_e9 >> vec4(u32(_e11))) & vec4(255u));
    acc = (vec3<i32>(tile, 1i) << vec3(u32(2i)));
    let _e25 = acc;
    acc = (_e25 << vec3(u32(1i)));
    let _e30 = uniforms.u_bits;
    let _e31 = acc;
    acc = (_e31 >> vec3(u32(_e30)));
    let _e36 = acc;
    f_color = vec4<f32>((vec3<f32>((_e36 & vec3(7i))) / vec3(7f)), (f32(unpacked.x) / 255f));
    let _e49 = f_color;
    return vector_shifts_fs_out(_e49);
}
