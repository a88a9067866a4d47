diagnostic(off, derivative_uniformity);

@group(0) @binding(1) 
var out_image: texture_storage_2d<rgba8unorm,write>;

@compute @workgroup_size(8, 8, 1) 
fn fill_cs(@builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    let p = vec2<i32>(GlobalInvocationID.xy);
    let _e4 = textureDimensions(out_image);
    let size = vec2<i32>(_e4);
    if ((p.x >= size.x) || (p.y >= size.y)) {
        return;
    }
    let uv = ((vec2<f32>(p) + vec2(0.5f)) / vec2<f32>(size));
    let checker = f32((((p.x / 4i) + (p.y / 4i)) % 2i));
    textureStore(out_image, p, vec4<f32>(uv.x, uv.y, checker, 1f));
    return;
}
