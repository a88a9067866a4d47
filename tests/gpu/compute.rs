//! DSL compute programs run on every consumer that has compute and
//! compared with the same computation on the CPU: an image fill, a prefix
//! sum in workgroup memory behind barriers, and an atomic histogram
//! (`shaders/compute/`). WGSL and SPIR-V (unchanged) on wgpu/Vulkan, GLSL
//! 430 on an OpenGL 4.3 core context, GLSL ES 3.10 on an OpenGL ES 3.1
//! context (both EGL surfaceless: llvmpipe without a GPU). Integers must
//! match exactly; the image's unorm bytes within 1 (the GPU's float to
//! unorm rounding may differ from the CPU's by one step).

use std::path::Path;

use umbrac::render::consumers;
use umbrac::render::plan::compute::{BufferInput, ComputePlan, ImageInput};
use umbrac::render::program::ShaderSet;
use umbrac::render::{Consumer, ExecError};
use umbrac::Target;

use crate::support;

fn compiled(name: &str) -> umbrac::Compiled {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders/compute").join(format!("{name}.das"));
    let c = umbrac::compile_file(&path, &umbrac::Options::default());
    assert!(!c.has_errors(), "{name} does not compile:\n{}", c.render_diagnostics());
    c.result.expect("compiled")
}

/// Runs `plan` on every compute consumer that is installed: each one's
/// name and read-backs.
fn run_everywhere(name: &str, plan: &ComputePlan) -> Vec<(Consumer, umbrac::render::exec::ComputeReadback)> {
    let c = compiled(name);
    let mut out = Vec::new();
    for consumer in Consumer::COMPUTE {
        let target = consumer.target().expect("a compute consumer has a target");
        let set = ShaderSet::from_compiled(name, &c, target).unwrap_or_else(|e| panic!("{e}"));
        // Open the devices the way the other GPU tests do (skip if missing).
        let ok = match consumer {
            Consumer::VulkanWgsl | Consumer::VulkanSpirv => support::gpu::vulkan().is_some(),
            _ => support::gpu::gl(consumer).is_some(),
        };
        if !ok {
            continue;
        }
        if consumer == Consumer::VulkanSpirv && !support::gpu::vulkan().is_some_and(|v| v.supports_passthrough()) {
            support::skip(format!("{name}: the Vulkan device takes no SPIR-V unchanged"));
            continue;
        }
        match consumers::run_compute(consumer, &set, plan) {
            Ok((r, _device)) => out.push((consumer, r)),
            Err(e @ ExecError::Unavailable { .. }) => support::skip(format!("{name} on {}: {e}", consumer.name())),
            // lavapipe and storage images of SPIR-V passed through: refused
            // by the executor, which says why (`exec/wgpu/compute.rs`).
            Err(ExecError::Unsupported(e)) if consumer == Consumer::VulkanSpirv && e.contains("lavapipe") => eprintln!("{name} on {}: not run: {e}", consumer.name()),
            Err(e) => panic!("{name} on {} ({}): {e}", consumer.name(), target.name()),
        }
    }
    // Nothing ran only when nothing is installed (skipped above).
    out
}

fn words(bytes: &[u8]) -> Vec<u32> {
    bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
}

fn bytes(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

/// A reproducible sequence of `n` values below `below` (an LCG).
fn values(n: usize, seed: u32, below: u32) -> Vec<u32> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (s >> 8) % below
        })
        .collect()
}

#[test]
fn image_fill_matches_the_cpu() {
    // Not a multiple of the 8x8 workgroup: the edge invocations write nothing.
    let (w, h) = (37u32, 23u32);
    let plan = ComputePlan {
        name: "image fill".into(),
        entry: "fill_cs".into(),
        workgroups: [w.div_ceil(8), h.div_ceil(8), 1],
        buffers: vec![],
        images: vec![ImageInput { name: "out_image".into(), width: w, height: h, layers: 1, texels: None }],
        readback: vec!["out_image".into()],
        constants: vec![],
    };
    let ran = run_everywhere("image_fill", &plan);
    let unorm = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as i32;
    for (consumer, r) in &ran {
        let got = &r.resources["out_image"];
        assert_eq!(got.len(), (w * h * 4) as usize, "{}", consumer.name());
        let mut worst = 0;
        let unwritten = got.chunks(4).filter(|t| t[3] == 0).count();
        assert_eq!(unwritten, 0, "{}: {unwritten} of {} texels were not written", consumer.name(), w * h);
        for y in 0..h {
            for x in 0..w {
                let uv = [(x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32];
                let checker = ((x / 4 + y / 4) % 2) as f32;
                let want = [unorm(uv[0]), unorm(uv[1]), unorm(checker), 255];
                let at = ((y * w + x) * 4) as usize;
                for c in 0..4 {
                    let d = (got[at + c] as i32 - want[c]).abs();
                    worst = worst.max(d);
                    assert!(d <= 1, "{}: texel ({x}, {y}) channel {c} is {}, the CPU computes {}", consumer.name(), got[at + c], want[c]);
                }
            }
        }
        eprintln!("image fill on {}: largest difference {worst}/255", consumer.name());
    }
}

#[test]
fn prefix_sum_matches_the_cpu() {
    const BLOCK: usize = 128;
    let n = 1000usize;
    let input = values(n, 7, 1000);
    let blocks = n.div_ceil(BLOCK);
    let with_count = |data: &[u32]| -> Vec<u8> { bytes(&[&[n as u32][..], data].concat()) };
    let plan = ComputePlan {
        name: "prefix sum".into(),
        entry: "prefix_sum_cs".into(),
        workgroups: [blocks as u32, 1, 1],
        buffers: vec![
            BufferInput { name: "input".into(), bytes: with_count(&input) },
            BufferInput { name: "output".into(), bytes: with_count(&vec![0; n]) },
            BufferInput { name: "totals".into(), bytes: bytes(&vec![0; blocks]) },
        ],
        images: vec![],
        readback: vec!["output".into(), "totals".into()],
        constants: vec![],
    };
    // Inclusive scans of each block, and each block's sum.
    let mut want = vec![0u32; n];
    let mut want_totals = vec![0u32; blocks];
    for (b, total) in want_totals.iter_mut().enumerate() {
        let mut sum = 0u32;
        for (w, v) in want.iter_mut().zip(&input).skip(b * BLOCK).take(BLOCK) {
            sum += v;
            *w = sum;
        }
        *total = sum;
    }
    let ran = run_everywhere("prefix_sum", &plan);
    for (consumer, r) in &ran {
        let out = words(&r.resources["output"]);
        assert_eq!(out[0], n as u32, "{}: the count is untouched", consumer.name());
        assert_eq!(&out[1..], &want[..], "{}: the prefix sums differ from the CPU's", consumer.name());
        assert_eq!(words(&r.resources["totals"]), want_totals, "{}: the block totals differ from the CPU's", consumer.name());
    }
}

#[test]
fn histogram_matches_the_cpu() {
    const BINS: usize = 64;
    let n = 5000usize;
    let samples = values(n, 42, 1 << 20);
    let plan = ComputePlan {
        name: "histogram".into(),
        entry: "histogram_cs".into(),
        workgroups: [n.div_ceil(64) as u32, 1, 1],
        buffers: vec![
            BufferInput { name: "samples".into(), bytes: bytes(&[&[n as u32][..], &samples].concat()) },
            BufferInput { name: "histogram".into(), bytes: bytes(&vec![0; 2 + BINS]) },
        ],
        images: vec![],
        readback: vec!["histogram".into()],
        constants: vec![],
    };
    let mut bins = vec![0u32; BINS];
    for v in &samples {
        bins[*v as usize % BINS] += 1;
    }
    let largest = *samples.iter().max().unwrap();
    let ran = run_everywhere("histogram", &plan);
    for (consumer, r) in &ran {
        let h = words(&r.resources["histogram"]);
        assert_eq!(h[0], n as u32, "{}: total", consumer.name());
        assert_eq!(h[1], largest, "{}: largest sample", consumer.name());
        assert_eq!(&h[2..], &bins[..], "{}: the bins differ from the CPU's", consumer.name());
    }
}

/// `shaders/compute/dialect_taps.das`, daslang's own spelling (stacked
/// annotations, `@stage` units, `unroll`, one-line `if`s, `reinterpret`),
/// against the CPU: the bit patterns exactly, the image's bytes within 1.
#[test]
fn gl_dialect_matches_the_cpu() {
    let (w, h) = (29u32, 19u32);
    let (gain, weights) = (1.25f32, [0.1f32, 0.2, 0.3, 0.15]);
    let mut taps: Vec<u8> = [gain].iter().chain(&weights).flat_map(|f| f.to_le_bytes()).collect();
    taps.extend(bytes(&vec![0; (w * h) as usize]));
    let plan = ComputePlan {
        name: "gl dialect".into(),
        entry: "dialect_cs".into(),
        workgroups: [w.div_ceil(8), h.div_ceil(8), 1],
        buffers: vec![BufferInput { name: "taps".into(), bytes: taps }],
        images: vec![ImageInput { name: "c_destTex".into(), width: w, height: h, layers: 1, texels: None }],
        readback: vec!["taps".into(), "c_destTex".into()],
        constants: vec![],
    };
    // The manifest has the units as written or assigned.
    let m = compiled("dialect_taps").reflection;
    let (buffers, images) = (m.storage_buffers.expect("a storage buffer"), m.storage_images.expect("a storage image"));
    assert_eq!(buffers[0].glsl_binding, 1, "`@stage = 1` is the buffer's binding point");
    assert_eq!((images[0].image_unit, images[0].format.as_str()), (0, "rgba8"), "a bare `@stage` gets the first free image unit, a bare `@format` is rgba8");
    let ran = run_everywhere("dialect_taps", &plan);
    let unorm = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as i32;
    for (consumer, r) in &ran {
        let got = words(&r.resources["taps"]);
        let img = &r.resources["c_destTex"];
        for y in 0..h {
            for x in 0..w {
                let mut s = 0.0f32;
                let mut n = 0i32;
                for (i, wt) in weights.iter().enumerate() {
                    if (x >> i) & 1 == 1 {
                        s += wt;
                    }
                    if (y >> i) & 1 == 1 {
                        n += 1 << i;
                    }
                }
                let at = (y * w + x) as usize;
                assert_eq!(got[5 + at], (n as f32).to_bits(), "{}: bits of texel ({x}, {y})", consumer.name());
                let want = [unorm(s * gain), unorm((y % 3) as f32 / 2.0), unorm(0.25), 255];
                for c in 0..4 {
                    let d = (img[at * 4 + c] as i32 - want[c]).abs();
                    assert!(d <= 1, "{}: texel ({x}, {y}) channel {c} is {}, the CPU computes {}", consumer.name(), img[at * 4 + c], want[c]);
                }
            }
        }
        assert_eq!(&got[..5], &words(&[gain].iter().chain(&weights).flat_map(|f| f.to_le_bytes()).collect::<Vec<u8>>())[..], "{}: the inputs are untouched", consumer.name());
        eprintln!("gl dialect on {}: {} texels as the CPU computes them", consumer.name(), w * h);
    }
}

#[test]
fn a_plan_that_does_not_fit_names_what_is_wrong() {
    let c = compiled("histogram");
    let set = ShaderSet::from_compiled("histogram", &c, Target::Wgsl).unwrap();
    let plan = ComputePlan {
        name: "histogram".into(),
        entry: "histogram_cs".into(),
        workgroups: [1, 1, 1],
        buffers: vec![BufferInput { name: "samples".into(), bytes: vec![0; 6] }],
        images: vec![],
        readback: vec![],
        constants: vec![],
    };
    let e = umbrac::render::bind::compute::fit(&set.label, set.manifest().unwrap(), &plan).unwrap_err().to_string();
    assert!(e.contains("storage buffer `samples` is given 6 bytes; its layout takes 4 bytes and a whole number (at least one) of 4-byte elements"), "{e}");
    assert!(e.contains("storage buffer `histogram` is given no contents by the plan"), "{e}");
    // No compute on WebGL2 or GL 3.3: said so, by name.
    let e = consumers::run_compute(Consumer::WebGl2, &set, &plan).unwrap_err().to_string();
    assert!(e.contains("webgl2 runs no compute programs"), "{e}");
}


/// The light-space bounds of what a camera sees, reduced from its depth
/// buffer (`shaders/compute/depth_bounds.das`, the building block of
/// sample-distribution shadow maps), against the CPU: the count exactly,
/// the bounds within 1e-4 of the box's size (the GPU's matrix products
/// round differently from the CPU's).
#[test]
fn depth_bounds_match_the_cpu() {
    use glam::camera::rh::{proj::opengl, view::look_at_mat4};
    use glam::{Vec3, Vec4};
    let (w, h) = (61u32, 47u32);
    let proj = opengl::perspective(50f32.to_radians(), w as f32 / h as f32, 0.5, 30.0);
    let view = look_at_mat4(Vec3::new(3.0, 4.0, 6.0), Vec3::ZERO, Vec3::Y);
    let inv_view_proj = (proj * view).inverse();
    let light_view = look_at_mat4(Vec3::new(-4.0, 8.0, 2.0), Vec3::ZERO, Vec3::Y);
    // A depth buffer with a background (1.0) corner and a slope elsewhere.
    let depth: Vec<f32> = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            if x + y < 12 { 1.0 } else { 0.90 + 0.09 * (x as f32 / w as f32) * (y as f32 / h as f32) }
        })
        .collect();
    let unkey = |k: i32| -> f32 { f32::from_bits((if k >= 0 { k } else { k ^ 0x7FFF_FFFF }) as u32) };
    // The CPU's reduction, as the program computes it.
    let (mut lo, mut hi, mut count) = ([f32::MAX; 3], [f32::MIN; 3], 0u32);
    for (i, d) in depth.iter().enumerate() {
        if *d >= 1.0 {
            continue;
        }
        let (x, y) = (i as u32 % w, i as u32 / w);
        let uv = [(x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32];
        let world = inv_view_proj * Vec4::new(uv[0] * 2.0 - 1.0, uv[1] * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
        let light = light_view * (world.truncate() / world.w).extend(1.0);
        for c in 0..3 {
            lo[c] = lo[c].min(light[c]);
            hi[c] = hi[c].max(light[c]);
        }
        count += 1;
    }
    let mut view_bytes: Vec<u8> = [inv_view_proj.to_cols_array(), light_view.to_cols_array()].concat().iter().flat_map(|f| f.to_le_bytes()).collect();
    view_bytes.extend([w as i32, h as i32].iter().flat_map(|v| v.to_le_bytes()));
    view_bytes.resize(144, 0);
    let start: Vec<u8> = [i32::MAX, i32::MAX, i32::MAX, i32::MIN, i32::MIN, i32::MIN, 0].iter().flat_map(|v| v.to_le_bytes()).collect();
    let plan = ComputePlan {
        name: "depth bounds".into(),
        entry: "depth_bounds_cs".into(),
        workgroups: [w.div_ceil(8), h.div_ceil(8), 1],
        buffers: vec![BufferInput { name: "view".into(), bytes: view_bytes }, BufferInput { name: "bounds".into(), bytes: start }],
        images: vec![ImageInput { name: "depth".into(), width: w, height: h, layers: 1, texels: Some(depth.iter().flat_map(|d| d.to_le_bytes()).collect()) }],
        readback: vec!["bounds".into()],
        constants: vec![],
    };
    let ran = run_everywhere("depth_bounds", &plan);
    for (consumer, r) in &ran {
        let b = words(&r.resources["bounds"]);
        assert_eq!(b[6], count, "{}: pixels counted", consumer.name());
        for c in 0..3 {
            let (glo, ghi) = (unkey(b[c] as i32), unkey(b[3 + c] as i32));
            let tol = 1e-4 * (hi[c] - lo[c]).abs().max(1.0);
            assert!((glo - lo[c]).abs() <= tol && (ghi - hi[c]).abs() <= tol, "{}: axis {c}: [{glo}, {ghi}], the CPU computes [{}, {}]", consumer.name(), lo[c], hi[c]);
        }
        eprintln!("depth bounds on {}: lo {:?} hi {:?} over {count} pixels", consumer.name(), (0..3).map(|c| unkey(b[c] as i32)).collect::<Vec<_>>(), (0..3).map(|c| unkey(b[3 + c] as i32)).collect::<Vec<_>>());
    }
}

/// Whether `consumer`'s device has subgroup operations (wgpu's
/// `Features::SUBGROUP`, GL's GL_KHR_shader_subgroup; GL ES 3.1 never).
fn has_subgroups(consumer: Consumer) -> bool {
    match consumer {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => support::gpu::vulkan().is_some_and(|v| v.supports_subgroups()),
        Consumer::Gl430 => support::gpu::gl(consumer).is_some_and(|g| g.supports_subgroups().unwrap_or(false)),
        _ => false,
    }
}

/// `shaders/compute/NAME.das` compiled as it is (default targets) and
/// with `-D SUBGROUPS` for the targets with subgroups (glsl430, wgsl,
/// spirv); both must compile.
fn plain_and_subgroups(name: &str) -> (umbrac::Compilation, umbrac::Compilation) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("shaders/compute/{name}.das"));
    let plain = umbrac::compile_file(&path, &umbrac::Options::default());
    let with_subgroups = umbrac::Options {
        defines: vec![("SUBGROUPS".into(), None)],
        targets: vec![Target::Glsl430, Target::Wgsl, Target::Spirv],
        ..Default::default()
    };
    let subgroups = umbrac::compile_file(&path, &with_subgroups);
    for c in [&plain, &subgroups] {
        assert!(!c.has_errors(), "{name} does not compile:\n{}", c.render_diagnostics());
    }
    (plain, subgroups)
}

/// Runs `plan` on every compute consumer this machine has, each with the
/// form it can run (`subgroups` where it has subgroup operations, `plain`
/// elsewhere), and hands `check` the consumer, the shader set it ran, the
/// words of buffer `readback` and whether subgroups ran. A consumer that
/// is missing, or the Vulkan device where it takes no SPIR-V unchanged,
/// is skipped.
fn run_each_form(name: &str, (plain, subgroups): (&umbrac::Compilation, &umbrac::Compilation), plan: &ComputePlan, readback: &str, mut check: impl FnMut(Consumer, &ShaderSet, Vec<u32>, bool)) {
    for consumer in Consumer::COMPUTE {
        let ok = match consumer {
            Consumer::VulkanWgsl | Consumer::VulkanSpirv => support::gpu::vulkan().is_some(),
            _ => support::gpu::gl(consumer).is_some(),
        };
        if !ok {
            continue;
        }
        if consumer == Consumer::VulkanSpirv && !support::gpu::vulkan().is_some_and(|v| v.supports_passthrough()) {
            support::skip(format!("{name}: the Vulkan device takes no SPIR-V unchanged"));
            continue;
        }
        let sub = has_subgroups(consumer);
        if !sub {
            eprintln!("{name} on {}: the device has no subgroup operations; running the form without them", consumer.name());
        }
        let c = if sub { subgroups } else { plain };
        let target = consumer.target().expect("a compute consumer has a target");
        let set = ShaderSet::from_compiled(name, c.result.as_ref().unwrap(), target).unwrap_or_else(|e| panic!("{e}"));
        let r = match consumers::run_compute(consumer, &set, plan) {
            Ok((r, _)) => r,
            Err(e @ ExecError::Unavailable { .. }) => {
                support::skip(format!("{name} on {}: {e}", consumer.name()));
                continue;
            }
            Err(e) => panic!("{name} on {} ({}, subgroups: {sub}): {e}", consumer.name(), target.name()),
        };
        check(consumer, &set, words(&r.resources[readback]), sub);
    }
}

/// `shaders/compute/spec_reduce.das`: a sum and a maximum of values scaled
/// by a specialization constant, through atomics; with `-D SUBGROUPS`
/// (compiled for glsl430, wgsl and spirv) each subgroup reduces first and
/// one lane per subgroup adds. Each consumer with subgroups runs that
/// form, the others the plain one, and both must match the CPU exactly;
/// the count of atomic adds shows which form ran (fewer with subgroups).
#[test]
fn specialization_constant_atomics_and_subgroups_match_the_cpu() {
    let n = 3000usize;
    let data = values(n, 7, 1 << 16);
    let plan = ComputePlan {
        name: "spec_reduce".into(),
        entry: "reduce_cs".into(),
        workgroups: [n.div_ceil(64) as u32, 1, 1],
        buffers: vec![
            BufferInput { name: "input".into(), bytes: bytes(&[&[n as u32][..], &data].concat()) },
            BufferInput { name: "totals".into(), bytes: bytes(&[0, 0, 0]) },
        ],
        images: vec![],
        readback: vec!["totals".into()],
        constants: vec![],
    };
    let (plain, subgroups) = plain_and_subgroups("spec_reduce");
    // The CPU's answer, from the default the manifest reports.
    let spec = plain.result.as_ref().unwrap().reflection.specialization_constants.clone().expect("spec_reduce has a specialization constant");
    assert_eq!((spec[0].name.as_str(), spec[0].id, spec[0].ty.as_str()), ("SCALE", 0, "uint"));
    let scale = spec[0].default_bits;
    let sum = data.iter().fold(0u32, |s, v| s.wrapping_add(v.wrapping_mul(scale)));
    let largest = data.iter().max().unwrap() * scale;
    let invocations = (n.div_ceil(64) * 64) as u32;
    run_each_form("spec_reduce", (&plain, &subgroups), &plan, "totals", |consumer, set, t, sub| {
        assert_eq!(t[0], sum, "{}: the sum differs from the CPU's", consumer.name());
        assert_eq!(t[1], largest, "{}: the largest value differs from the CPU's", consumer.name());
        match sub {
            // One add per subgroup: at most one per invocation, at least
            // one per workgroup.
            true => assert!(t[2] < invocations && t[2] >= invocations / 64, "{}: {} subgroup adds for {invocations} invocations", consumer.name(), t[2]),
            false => assert_eq!(t[2], invocations, "{}: one add per invocation", consumer.name()),
        }
        eprintln!("spec_reduce on {}: matches the CPU (subgroups: {sub}, {} atomic adds)", consumer.name(), t[2]);
        // Another value of SCALE: WGSL's override and SPIR-V's
        // OpSpecConstant take it when the pipeline is made; the GL
        // consumers, whose GLSL holds the default, refuse to pretend.
        let other = ComputePlan { constants: vec![(0, 5.0)], ..plan.clone() };
        let settable = matches!(consumer, Consumer::VulkanWgsl | Consumer::VulkanSpirv);
        match (settable, consumers::run_compute(consumer, set, &other)) {
            (true, Ok((r, _))) => {
                let t = words(&r.resources["totals"]);
                let sum5 = data.iter().fold(0u32, |s, v| s.wrapping_add(v.wrapping_mul(5)));
                assert_eq!((t[0], t[1]), (sum5, data.iter().max().unwrap() * 5), "{}: SCALE = 5 set as a pipeline constant", consumer.name());
                eprintln!("spec_reduce on {}: SCALE = 5 matches the CPU", consumer.name());
            }
            (true, Err(e)) => panic!("spec_reduce on {} with SCALE = 5: {e}", consumer.name()),
            (false, Err(ExecError::Unsupported(_))) => {}
            (_, other) => panic!("spec_reduce on {}: a plan setting a specialization constant was not refused: {:?}", consumer.name(), other.map(|_| ())),
        }
    });
}

/// `shaders/compute/vk_reduce.das`, in daslang's Vulkan dialect: a
/// weighted sum and a count of odd values, the weight and the count
/// specialization constants (ids 3, 4), through atomics; with `-D
/// SUBGROUPS` each subgroup reduces first. Each compute consumer runs the
/// form it can (subgroups where it has them) and must match the CPU
/// exactly; on vulkan-wgsl both constants are also set by the plan.
#[test]
fn vulkan_dialect_reduce_matches_the_cpu() {
    let n = 1000usize;
    let data = values(n, 11, 1 << 20);
    let plan = ComputePlan {
        name: "vk_reduce".into(),
        entry: "vk_reduce".into(),
        workgroups: [n.div_ceil(32) as u32, 1, 1],
        buffers: vec![BufferInput { name: "values".into(), bytes: bytes(&data) }, BufferInput { name: "sums".into(), bytes: bytes(&[0, 0, 0]) }],
        images: vec![],
        readback: vec!["sums".into()],
        constants: vec![],
    };
    let (plain, subgroups) = plain_and_subgroups("vk_reduce");
    let spec = plain.result.as_ref().unwrap().reflection.specialization_constants.clone().expect("vk_reduce has specialization constants");
    let (weight, count) = (spec[0].default_bits, spec[1].default_bits as usize);
    assert_eq!((spec[0].id, spec[1].id, count), (3, 4, n));
    let expect = |weight: u32, count: usize| {
        let used = &data[..count];
        (used.iter().fold(0u32, |s, v| s.wrapping_add(v.wrapping_mul(weight))), used.iter().filter(|v| *v & 1 == 1).count() as u32)
    };
    let invocations = (n.div_ceil(32) * 32) as u32;
    run_each_form("vk_reduce", (&plain, &subgroups), &plan, "sums", |consumer, set, t, sub| {
        assert_eq!((t[0], t[1]), expect(weight, count), "{}: differs from the CPU", consumer.name());
        match sub {
            true => assert!(t[2] < invocations && t[2] >= invocations / 32, "{}: {} subgroup adds for {invocations} invocations", consumer.name(), t[2]),
            false => assert_eq!(t[2], invocations, "{}: one add per invocation", consumer.name()),
        }
        eprintln!("vk_reduce on {}: matches the CPU (subgroups: {sub}, {} atomic adds)", consumer.name(), t[2]);
        if consumer == Consumer::VulkanWgsl {
            let other = ComputePlan { constants: vec![(3, 11.0), (4, 600.0)], ..plan.clone() };
            let (r, _) = consumers::run_compute(consumer, set, &other).unwrap_or_else(|e| panic!("vk_reduce with WEIGHT = 11, COUNT = 600: {e}"));
            let t = words(&r.resources["sums"]);
            assert_eq!((t[0], t[1]), expect(11, 600), "vulkan-wgsl: WEIGHT = 11, COUNT = 600 set as pipeline constants");
        }
    });
}
