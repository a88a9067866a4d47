diagnostic(off, derivative_uniformity);

struct vector_shifts_fs_out {
    @location(0) f_color: vec4<f32>,
}

@group(0) @binding(0) 
var<uniform> u_bits: i32;
@group(0) @binding(1) 
var<uniform> u_mask: vec4<u32>;

@fragment 
fn vector_shifts_fs(@builtin(position) FragCoord: vec4<f32>) -> vector_shifts_fs_out {
    var f_color: vec4<f32>;
    var acc: vec3<i32>;

    let texel = vec2<i32>(FragCoord.xy);
    let tile = (texel >> vec2(u32(3i)));
    let _e8 = u_mask;
    let _e10 = u_bits;
    let unpacked = ((_e8 >> vec4(u32(_e10))) & vec4(255u));
    acc = (vec3<i32>(tile, 1i) << vec3(u32(2i)));
    let _e26 = acc;
    acc = (_e26 << vec3(u32(1i)));
    let _e32 = u_bits;
    let _e33 = acc;
    acc = (_e33 >> vec3(u32(_e32)));
    let _e39 = acc;
    f_color = vec4<f32>((vec3<f32>((_e39 & vec3(7i))) / vec3(7f)), (f32(unpacked.x) / 255f));
    let _e53 = f_color;
    return vector_shifts_fs_out(_e53);
}
