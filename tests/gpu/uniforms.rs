//! Twenty loose uniforms of mixed types (`bool`, `bool2`, `bool3`, `int`,
//! `uint`, `uint2`, `float[9]`, `float2[3]`, `int[4]`, `float3[2]`,
//! `float2x2`, `float3x2`, `float4x2`, `float3x3`, `float4x4`, ...), read in
//! both stages of `shaders/features/include/loose_uniforms.das`, drawn on
//! all six consumers (wgpu WGSL, wgpu SPIR-V, wgpu's GL backend, GL 3.3,
//! GLES 3.0, WebGL2) and compared pixel by pixel with the same formula
//! evaluated on the CPU: every padded member of the WGSL/SPIR-V buffer,
//! every plain GLSL uniform and its `glUniform*` call, and the blocks form
//! (`--gl-uniforms blocks`) on the GL consumers, must agree.
//!
//! Tolerance: 2/255 per channel at every pixel (the formula is smooth and
//! stays inside [0, 1]; the consumers differ from the CPU only in float
//! rounding and the 8-bit quantisation).

use crate::support;

use glam::{Mat2, Mat3, Vec2, Vec3, Vec4};
use image::RgbaImage;
use umbrac::render::plan::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, Shape, TargetId, Unset, Value, Values};
use umbrac::render::{Executor, ShaderSet};
use umbrac::{GlUniforms, Options, Target};

const W: u32 = 64;
const H: u32 = 48;
const TOLERANCE: u8 = 2;

const PROGRAM: &str = include_str!("../../shaders/features/include/loose_uniforms.das");

/// The values the frame sets (every uniform but `u_scale`, which keeps its
/// default of 1.0 from the source).
struct Uniforms {
    offset: Vec2,
    tint: Vec3,
    color: Vec4,
    flip: bool,
    mask: [bool; 2],
    count: i32,
    index: u32,
    weights: [f32; 9],
    taps: [Vec2; 3],
    /// float3x2: three columns of two rows.
    shear: [Vec2; 3],
    rot: Mat2,
    basis: Mat3,
    /// A quarter turn about z: the triangle still covers the target.
    model: glam::Mat4,
    steps: [i32; 4],
    gains: [Vec3; 2],
    bias: f32,
    levels: [u32; 2],
    on: [bool; 3],
    /// float4x2: four columns of two rows.
    mix: [Vec2; 4],
}

fn uniforms() -> Uniforms {
    Uniforms {
        offset: Vec2::new(0.1, -0.05),
        tint: Vec3::new(0.2, 0.4, 0.6),
        color: Vec4::new(0.3, 0.5, 0.7, 1.0),
        flip: true,
        mask: [false, true],
        count: 3,
        index: 1,
        weights: std::array::from_fn(|i| 0.01 * (i + 1) as f32),
        taps: [Vec2::new(0.1, 0.2), Vec2::new(0.3, 0.4), Vec2::new(0.5, 0.6)],
        shear: [Vec2::new(0.5, 0.1), Vec2::new(-0.1, 0.4), Vec2::new(0.2, 0.3)],
        rot: Mat2::from_cols(Vec2::new(0.0, 0.5), Vec2::new(-0.5, 0.0)),
        basis: Mat3::from_cols(Vec3::new(1.0, 0.0, 0.1), Vec3::new(0.0, 0.8, 0.0), Vec3::new(0.1, 0.0, 0.9)),
        model: glam::Mat4::from_rotation_z(std::f32::consts::FRAC_PI_2),
        steps: [1, 2, 3, 4],
        gains: [Vec3::splat(0.05), Vec3::new(0.1, 0.0, 0.05)],
        bias: 0.5,
        levels: [2, 3],
        on: [true, false, true],
        mix: [Vec2::new(0.2, 0.1), Vec2::new(0.0, 0.3), Vec2::new(0.1, 0.1), Vec2::new(0.3, 0.0)],
    }
}

fn bools(v: &[bool]) -> Value {
    let words: Vec<u32> = v.iter().map(|&b| b as u32).collect();
    Value::from_words(&format!("bool{}", v.len()), &words).expect("a bool vector")
}

fn columns(cols: &[Vec2]) -> Value {
    let words: Vec<f32> = cols.iter().flat_map(|c| c.to_array()).collect();
    Value::floats(Shape::Matrix { columns: cols.len() as u8, rows: 2 }, &words)
}

fn values(u: &Uniforms) -> Values {
    Values::new()
        .with("u_offset", Value::vec2(u.offset))
        .with("u_tint", Value::vec3(u.tint))
        .with("u_color", Value::vec4(u.color))
        .with("u_flip", Value::bool(u.flip))
        .with("u_mask", bools(&u.mask))
        .with("u_count", Value::int(u.count))
        .with("u_index", Value::uint(u.index))
        .with("u_weights", Value::array(u.weights.iter().map(|&w| Value::float(w)).collect()))
        .with("u_taps", Value::array(u.taps.iter().map(|&t| Value::vec2(t)).collect()))
        .with("u_shear", columns(&u.shear))
        .with("u_rot", Value::floats(Shape::Matrix { columns: 2, rows: 2 }, &u.rot.to_cols_array()))
        .with("u_basis", Value::floats(Shape::Matrix { columns: 3, rows: 3 }, &u.basis.to_cols_array()))
        .with("u_model", Value::mat4(u.model))
        .with("u_steps", Value::array(u.steps.iter().map(|&s| Value::int(s)).collect()))
        .with("u_gains", Value::array(u.gains.iter().map(|&g| Value::vec3(g)).collect()))
        .with("u_bias", Value::float(u.bias))
        .with("u_levels", Value::from_words("uint2", &u.levels).unwrap())
        .with("u_on", bools(&u.on))
        .with("u_mix", columns(&u.mix))
}

fn plan(vertex: &str, fragment: &str) -> FramePlan {
    let mut plan = FramePlan {
        scene: "twenty loose uniforms".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: TargetId(0),
        required: Vec::new(),
        // Every uniform must be set by the plan or by its default.
        unset: Unset::Error,
    };
    let image = plan.add_target("image", W, H, Format::Rgba8);
    plan.passes.push(Pass {
        name: "uniforms".into(),
        vertex: vertex.into(),
        fragment: Some(fragment.into()),
        color: Some(Attachment { target: image, clear: [0.0, 0.0, 0.0, 1.0] }),
        more_colors: Vec::new(),
        depth: None,
        cull: Cull::None,
        depth_bias: false,
        textures: Vec::new(),
        values: values(&uniforms()),
        draws: vec![Draw { geometry: Geometry::Vertices(3), values: Values::new() }],
    });
    plan.readback = image;
    plan
}

/// The fragment colour the program computes at a point of clip space.
fn formula(u: &Uniforms, ndc: Vec2) -> Vec3 {
    // gl_Position = u_model * (a_pos * u_scale, 0, 1) with u_scale = 1:
    // a_pos is the point `u_model` turns onto ndc.
    let a = u.model.inverse().transform_point3(ndc.extend(0.0)).truncate();
    let v_p = u.shear[0] * a.x + u.shear[1] * a.y + u.shear[2] + u.offset;
    let v_m = u.rot * a;
    let v_k = u.weights[0] + u.weights[8] * u.count as f32 + if u.flip { 0.25 } else { 0.0 } + u.steps[3] as f32 * 0.01;
    let s: f32 = u.weights.iter().sum();
    let t = u.taps[u.index as usize].x + u.taps[2].y;
    let c = u.basis * u.tint;
    let g = u.gains[1] * u.bias;
    let q = Vec2::new(v_p.x, v_m.y);
    // A row vector times a float4x2: one component per column.
    let mx = Vec4::from_array(std::array::from_fn(|j| q.dot(u.mix[j])));
    let mut on = if u.mask[1] { 0.05 } else { 0.0 };
    if u.on[0] {
        on += 0.1;
    }
    if u.on[2] {
        on += 0.2;
    }
    let lv = (u.levels[0] + u.levels[1]) as f32 * 0.01;
    let base = u.color.truncate() * 0.5 + c * 0.1 + g;
    let rgb = base
        + Vec3::new(v_p.x, v_p.y, v_k) * 0.25
        + Vec3::new(mx.x, mx.y + on, mx.z + lv) * 0.1
        + Vec3::splat(t * 0.1 + s * 0.02 + u.steps[1] as f32 * 0.01);
    rgb.clamp(Vec3::ZERO, Vec3::ONE)
}

/// The expected picture, top row first (as the executors read back).
fn expected() -> RgbaImage {
    let u = uniforms();
    RgbaImage::from_fn(W, H, |x, row| {
        let y = H - 1 - row;
        let ndc = Vec2::new((x as f32 + 0.5) / W as f32 * 2.0 - 1.0, (y as f32 + 0.5) / H as f32 * 2.0 - 1.0);
        let c = formula(&u, ndc);
        let b = |v: f32| (v * 255.0).round() as u8;
        image::Rgba([b(c.x), b(c.y), b(c.z), 255])
    })
}

/// The largest channel difference and where, or `None` within tolerance.
fn compare(got: &RgbaImage, want: &RgbaImage) -> Option<String> {
    let mut worst = (0u8, 0, 0);
    for (x, y, p) in got.enumerate_pixels() {
        let q = want.get_pixel(x, y);
        let d = (0..3).map(|i| p[i].abs_diff(q[i])).max().unwrap();
        if d > worst.0 {
            worst = (d, x, y);
        }
    }
    (worst.0 > TOLERANCE).then(|| {
        let (_, x, y) = worst;
        format!("{}/255 off at ({x}, {y}): got {:?}, the CPU gives {:?}", worst.0, got.get_pixel(x, y).0, want.get_pixel(x, y).0)
    })
}

fn compiled(gl_uniforms: GlUniforms) -> umbrac::Compiled {
    let opts = Options { gl_uniforms, ..Options::default() };
    let c = umbrac::compile_source("loose_uniforms.das", PROGRAM, &opts);
    let diagnostics = c.render_diagnostics();
    c.result.filter(|_| diagnostics.is_empty()).unwrap_or_else(|| panic!("the program does not compile:\n{diagnostics}"))
}

fn draw<E: Executor>(e: &E, consumer: &str, compiled: &umbrac::Compiled, target: Target) -> RgbaImage {
    let set = ShaderSet::from_compiled(consumer, compiled, target).unwrap();
    let plan = plan("loose_vs", "loose_fs");
    let prepared = e.prepare(&set, &plan).unwrap_or_else(|e| panic!("{consumer} refuses the program: {e}"));
    e.run(&prepared, &plan).unwrap_or_else(|e| panic!("{consumer} fails to draw it: {e}")).into_image()
}

/// Every consumer draws the CPU's picture.
#[test]
fn twenty_mixed_loose_uniforms_agree_on_every_consumer() {
    let want = expected();
    // The formula varies over the picture: a constant one would hide a
    // varying that every consumer got wrong alike.
    assert_ne!(want.get_pixel(0, 0), want.get_pixel(W - 1, H - 1));
    let plain = compiled(GlUniforms::Plain);
    let blocks = compiled(GlUniforms::Blocks);
    let mut drawn: Vec<(String, RgbaImage)> = Vec::new();
    if let Some(r) = support::gpu::vulkan() {
        drawn.push(("wgpu WGSL".into(), draw(r, "wgpu WGSL", &plain, Target::Wgsl)));
        if r.supports_passthrough() {
            drawn.push(("wgpu SPIR-V".into(), draw(r, "wgpu SPIR-V", &plain, Target::Spirv)));
        } else {
            support::skip("the Vulkan device lacks PASSTHROUGH_SHADERS: raw SPIR-V not run");
        }
    }
    if let Some(r) = support::gpu::wgpu_gl() {
        drawn.push(("wgpu GL".into(), draw(r, "wgpu GL", &plain, Target::Wgsl)));
    }
    #[cfg(feature = "gl")]
    for consumer in [umbrac::render::Consumer::Gl330, umbrac::render::Consumer::Gles300] {
        let target = consumer.target().expect("a GL consumer runs GLSL");
        if let Some(r) = support::gpu::gl(consumer) {
            drawn.push((consumer.name().into(), draw(&r, consumer.name(), &plain, target)));
            let name = format!("{} (blocks)", consumer.name());
            drawn.push((name.clone(), draw(&r, &name, &blocks, target)));
        }
    }
    if let Some(page) = support::or_skip(umbrac::render::exec::webgl::WebGl::find(), "no WebGL2 consumer") {
        drawn.push(("webgl2".into(), draw(&page, "webgl2", &plain, Target::Gles300)));
    }
    let dir = support::gpu::artifacts_dir("uniforms");
    want.save(dir.join("cpu.png")).unwrap();
    let mut failures = Vec::new();
    for (name, image) in &drawn {
        image.save(dir.join(format!("{}.png", name.replace([' ', '(', ')'], "_")))).unwrap();
        if let Some(why) = compare(image, &want) {
            failures.push(format!("{name}: {why}"));
        }
    }
    eprintln!("{} consumers drew the twenty uniforms: {}", drawn.len(), drawn.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>().join(", "));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The CPU formula is what the program says: a value changed in the plan
/// changes the picture (the comparison above cannot pass by accident).
#[test]
fn a_changed_uniform_changes_the_picture() {
    let Some(r) = support::gpu::vulkan() else { return };
    let plain = compiled(GlUniforms::Plain);
    let set = ShaderSet::from_compiled("wgpu WGSL", &plain, Target::Wgsl).unwrap();
    let mut p = plan("loose_vs", "loose_fs");
    // `u_flip` false: v_k drops by 0.25, so blue by 0.0625 (16/255).
    p.passes[0].values.set("u_flip", Value::bool(false));
    let prepared = r.prepare(&set, &p).unwrap();
    let image = r.run(&prepared, &p).unwrap().into_image();
    let why = compare(&image, &expected()).expect("the picture must change");
    assert!(why.contains("16/255") || why.contains("15/255") || why.contains("17/255"), "{why}");
}
