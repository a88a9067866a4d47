diagnostic(off, derivative_uniformity);

struct View {
    inv_view_proj: mat4x4<f32>,
    light_view: mat4x4<f32>,
    size: vec2<i32>,
}

struct Bounds_atomic {
    lo: array<atomic<i32>, 3>,
    hi: array<atomic<i32>, 3>,
    count: atomic<u32>,
}

@group(0) @binding(0) 
var<storage> view: View;
@group(0) @binding(1) 
var<storage, read_write> bounds: Bounds_atomic;
@group(0) @binding(2) 
var depth: texture_storage_2d<r32float,read>;
var<workgroup> lo: array<atomic<i32>, 3>;
var<workgroup> hi: array<atomic<i32>, 3>;
var<workgroup> seen: atomic<u32>;

fn key(f: f32) -> i32 {
    let b = bitcast<i32>(f);
    return select((b ^ 2147483647i), b, (b >= 0i));
}

@compute @workgroup_size(8, 8, 1) 
fn depth_bounds_cs(@builtin(local_invocation_index) LocalInvocationIndex: u32, @builtin(global_invocation_id) GlobalInvocationID: vec3<u32>) {
    var i: i32;

    if (LocalInvocationIndex < 3u) {
        let _e7 = atomicExchange((&lo[LocalInvocationIndex]), 2147483647i);
        let _e13 = atomicExchange((&hi[LocalInvocationIndex]), (-(2147483647i) - 1i));
    }
    if (LocalInvocationIndex == 0u) {
        let _e17 = atomicExchange((&seen), 0u);
    }
    workgroupBarrier();
    let p = vec2<i32>(GlobalInvocationID.xy);
    let _e25 = view.size.x;
    let _e30 = view.size.y;
    if ((p.x < _e25) && (p.y < _e30)) {
        let _e34 = textureLoad(depth, p);
        let d = _e34.x;
        if (d < 1f) {
            let _e43 = view.size;
            let uv = ((vec2<f32>(p) + vec2(0.5f)) / vec2<f32>(_e43));
            let ndc = vec4<f32>(((uv * 2f) - vec2(1f)), ((d * 2f) - 1f), 1f);
            let _e54 = view.inv_view_proj;
            let world = (_e54 * ndc);
            let _e57 = view.light_view;
            let light = (_e57 * vec4<f32>((world.xyz / vec3(world.w)), 1f));
            i = 0i;
            loop {
                let _e67 = i;
                if !((_e67 < 3i)) {
                    break;
                }
                let _e70 = i;
                let _e72 = i;
                let _e74 = key(light[_e72]);
                let _e75 = atomicMin((&lo[_e70]), _e74);
                let _e76 = i;
                let _e78 = i;
                let _e80 = key(light[_e78]);
                let _e81 = atomicMax((&hi[_e76]), _e80);
                continuing {
                    let _e82 = i;
                    i = (_e82 + 1i);
                }
            }
            let _e85 = atomicAdd((&seen), 1u);
        }
    }
    workgroupBarrier();
    if (LocalInvocationIndex < 3u) {
        let _e91 = atomicLoad((&lo[LocalInvocationIndex]));
        let _e92 = atomicMin((&bounds.lo[LocalInvocationIndex]), _e91);
        let _e96 = atomicLoad((&hi[LocalInvocationIndex]));
        let _e97 = atomicMax((&bounds.hi[LocalInvocationIndex]), _e96);
    }
    if (LocalInvocationIndex == 0u) {
        let _e100 = atomicLoad((&seen));
        let _e101 = atomicAdd((&bounds.count), _e100);
    }
    return;
}
