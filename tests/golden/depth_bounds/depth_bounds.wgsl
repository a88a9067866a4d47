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
        let _e14 = atomicExchange((&hi[LocalInvocationIndex]), (-(2147483647i) - 1i));
    }
    if (LocalInvocationIndex == 0u) {
        let _e19 = atomicExchange((&seen), 0u);
    }
    workgroupBarrier();
    let p = vec2<i32>(GlobalInvocationID.xy);
    let _e27 = view.size.x;
    let _e33 = view.size.y;
    if ((p.x < _e27) && (p.y < _e33)) {
        let _e37 = textureLoad(depth, p);
        let d = _e37.x;
        if (d < 1f) {
            let _e47 = view.size;
            let uv = ((vec2<f32>(p) + vec2(0.5f)) / vec2<f32>(_e47));
            let ndc = vec4<f32>(((uv * 2f) - vec2(1f)), ((d * 2f) - 1f), 1f);
            let _e63 = view.inv_view_proj;
            let world = (_e63 * ndc);
            let _e67 = view.light_view;
            let light = (_e67 * vec4<f32>((world.xyz / vec3(world.w)), 1f));
            i = 0i;
            loop {
                let _e78 = i;
                if !((_e78 < 3i)) {
                    break;
                }
                let _e83 = i;
                let _e86 = i;
                let _e88 = key(light[_e86]);
                let _e89 = atomicMin((&lo[_e83]), _e88);
                let _e92 = i;
                let _e95 = i;
                let _e97 = key(light[_e95]);
                let _e98 = atomicMax((&hi[_e92]), _e97);
                continuing {
                    let _e99 = i;
                    i = (_e99 + 1i);
                }
            }
            let _e104 = atomicAdd((&seen), 1u);
        }
    }
    workgroupBarrier();
    if (LocalInvocationIndex < 3u) {
        let _e113 = atomicLoad((&lo[LocalInvocationIndex]));
        let _e114 = atomicMin((&bounds.lo[LocalInvocationIndex]), _e113);
        let _e120 = atomicLoad((&hi[LocalInvocationIndex]));
        let _e121 = atomicMax((&bounds.hi[LocalInvocationIndex]), _e120);
    }
    if (LocalInvocationIndex == 0u) {
        let _e127 = atomicLoad((&seen));
        let _e128 = atomicAdd((&bounds.count), _e127);
    }
    return;
}
