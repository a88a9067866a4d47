//! Every emitted target on the consumer it is meant for, on the same frame,
//! at 160 x 120: WGSL and SPIR-V on wgpu/Vulkan, WGSL on wgpu's GL backend,
//! GLSL 330 on an OpenGL 3.3 core context, GLSL ES 3.00 on an OpenGL ES 3.0
//! context and in WebGL2 (headless chromium), and the CPU reference.
//!
//! A consumer that is not installed is skipped with a message, except with
//! `CI=true`, where that fails the test.
//!
//! Tolerances (also in docs/targets.md):
//! - GPU consumers against each other: at most `GPU_MAX_FRACTION` = 0.5 %
//!   of pixels differ by more than `DELTA` = 8/255 in a channel (no pixel
//!   skipped: they all run the same shadow-map lookups, edge texels
//!   included);
//! - each GPU consumer against the CPU reference: the runner's rule, at most
//!   0.75 % of compared pixels differ by more than 8/255, pixels showing
//!   floor outside the sun's box skipped (the reference marks them), and
//!   the shadow masks overlap with IoU >= 0.9.

use crate::support;

use std::collections::BTreeMap;

use image::RgbaImage;
use support::gpu;
use umbrac::render::consumers::{self, Consumer, Programs, Status};
use umbrac::render::gl::{GlApi, GlError};
use umbrac::render::glsl_set::GlslSet;
use umbrac::render::webgl::WebGl;
use umbrac::render::{image_ops, reference, FrameParams, View};

const W: u32 = 160;
const H: u32 = 120;
const DELTA: u8 = 8;
const GPU_MAX_FRACTION: f64 = 0.005;
const REF_MAX_FRACTION: f64 = 0.0075;
const MIN_SHADOW_IOU: f64 = 0.9;

const SCENE: &str = include_str!("../../shaders/shadow.das");

fn programs() -> Programs {
    Programs::compile_source("shaders/shadow.das", SCENE).unwrap()
}

/// A consumer's image, `None` (with a message) when it is not installed.
fn image_of(c: Consumer, programs: &Programs, p: &FrameParams) -> Option<RgbaImage> {
    match consumers::render(c, programs, p) {
        Status::Rendered { image, device, ms } => {
            eprintln!("{} ({device}): {ms:.0} ms", c.name());
            Some(image)
        }
        Status::Unavailable { why, install } => {
            support::skip(format!("{} is unavailable: {why} (install: {install})", c.name()));
            None
        }
        Status::Failed(e) => panic!("{} failed: {e}", c.name()),
    }
}

#[test]
fn every_consumer_draws_the_same_frame() {
    let programs = programs();
    let t = 2.0;
    let p = FrameParams::new(t, W, H);
    let lit = p.with_view(View::Lit);
    let reference = reference::render_frame(&p);
    let ref_lit = reference::render(&lit);
    let skip = &reference.outside_shadow_map;
    let inside = |m: Vec<bool>| m.into_iter().zip(skip).map(|(m, s)| m && !s).collect::<Vec<_>>();
    let ref_shadow = inside(image_ops::shadow_mask(&reference.image, &ref_lit));

    let mut images: BTreeMap<Consumer, RgbaImage> = BTreeMap::new();
    let mut failures = Vec::new();
    for c in Consumer::ALL.into_iter().filter(|c| c.is_gpu()) {
        let Some(image) = image_of(c, &programs, &p) else { continue };
        let Some(image_lit) = image_of(c, &programs, &lit) else { continue };
        let stats = image_ops::diff_masked(&image, &reference.image, DELTA, Some(skip));
        let iou = image_ops::iou(&inside(image_ops::shadow_mask(&image, &image_lit)), &ref_shadow);
        eprintln!("{} vs reference: {stats}; shadow IoU {iou:.3}", c.name());
        let diff = image_ops::diff_image(&image, &reference.image, Some(skip));
        let out = gpu::artifacts_dir("consumer-tests").join(format!("{}_t{t}.png", c.name()));
        image_ops::save_png(&image_ops::side_by_side(&[&image, &reference.image, &diff]), &out).unwrap();
        if stats.fraction_over > REF_MAX_FRACTION || iou < MIN_SHADOW_IOU {
            failures.push(format!("{} vs reference: {stats}; shadow IoU {iou:.3} ({})", c.name(), out.display()));
        }
        images.insert(c, image);
    }
    let list: Vec<_> = images.iter().collect();
    for (i, (a, ia)) in list.iter().enumerate() {
        for (b, ib) in &list[i + 1..] {
            let stats = image_ops::diff(ia, ib, DELTA);
            eprintln!("{} vs {}: {stats}", a.name(), b.name());
            if stats.fraction_over > GPU_MAX_FRACTION {
                failures.push(format!("{} vs {}: {stats}", a.name(), b.name()));
            }
        }
    }
    assert!(failures.is_empty(), "consumers disagree:\n{}", failures.join("\n"));
    assert!(!images.is_empty(), "no GPU consumer is available at all");
}

/// The scene written another way draws the same frame on every GPU
/// consumer: its PCF helper taking the shadow map as a sampler parameter
/// (the same code after lowering: identical pixels), and its PCF loop
/// unrolled into `textureCompareOffset` taps (the same texels, found by
/// offset instead of by coordinate arithmetic: no pixel off by more than
/// 1/255; measured identical on all six. Taps that ignored the offset
/// make 15 pixels differ by up to 54/255).
#[test]
fn rewritten_scenes_draw_the_same_frame_on_every_consumer() {
    let usual = programs();
    let variants = [
        ("sampler parameter", support::shadow_scene_with_sampler_parameter(), 0, 0.0),
        ("texel offsets", support::shadow_scene_with_texel_offsets(), 1, 0.0),
        // `* 2.0 * 0.5` may round one way or the other: within 1/255.
        ("uniform defaults", support::shadow_scene_with_uniform_defaults(), 1, 0.0),
    ];
    let variants: Vec<_> = variants
        .iter()
        .map(|(what, text, delta, max_fraction)| (*what, Programs::compile_source("variant.das", text).unwrap_or_else(|e| panic!("{what}: {e}")), *delta, *max_fraction))
        .collect();
    let p = FrameParams::new(2.0, W, H);
    let mut failures = Vec::new();
    let mut drawn = 0;
    for c in Consumer::ALL.into_iter().filter(|c| c.is_gpu()) {
        // The usual frame once per consumer, against each rewrite.
        let Some(a) = image_of(c, &usual, &p) else { continue };
        for (what, variant, delta, max_fraction) in &variants {
            let Some(b) = image_of(c, variant, &p) else { continue };
            let stats = image_ops::diff(&a, &b, *delta);
            eprintln!("{what} on {}: {stats}", c.name());
            if stats.fraction_over > *max_fraction {
                failures.push(format!("{what} on {}: {stats}", c.name()));
            }
            drawn += 1;
        }
    }
    assert!(drawn > 0, "no GPU consumer is available at all");
    assert!(failures.is_empty(), "a rewritten scene changed the picture:\n{}", failures.join("\n"));
}

/// The ES outputs' sampler precision, removed in two steps: the
/// `precision highp sampler2DShadow;` preamble line only, then also the
/// `highp` on the sampler's declaration.
fn without_preamble(text: &str) -> String {
    text.lines().filter(|l| l.trim() != "precision highp sampler2DShadow;").collect::<Vec<_>>().join("\n") + "\n"
}

fn without_any_sampler_precision(text: &str) -> String {
    without_preamble(text).replace("uniform highp sampler2DShadow", "uniform sampler2DShadow")
}

fn gles_set() -> GlslSet {
    programs().gles300
}

#[test]
fn the_es_outputs_declare_sampler_precision() {
    let set = gles_set();
    let (file, text) = set.entry("main_fs").unwrap();
    assert!(text.lines().any(|l| l.trim() == "precision highp sampler2DShadow;"), "{file} lacks the preamble:\n{text}");
    assert!(text.contains("uniform highp sampler2DShadow"), "{file}: naga's declaration changed:\n{text}");
    // The edits below really remove every precision for the sampler.
    let stripped = without_any_sampler_precision(text);
    assert!(!stripped.contains("highp sampler2DShadow"), "{stripped}");
}

#[test]
fn es_sampler_precision_matters_on_gles() {
    let Some(r) = gpu::gl(GlApi::Gles300) else { return };
    let p = FrameParams::new(2.0, W, H);
    let intact = r.render(&gles_set(), &p).expect("the ES output as emitted renders");
    let stats = image_ops::diff_masked(&intact, &reference::render(&p), DELTA, Some(&reference::render_frame(&p).outside_shadow_map));
    assert!(stats.fraction_over <= REF_MAX_FRACTION, "{stats}");

    // Without the preamble line the declaration's own `highp` still gives
    // the sampler a precision: it compiles and renders the same picture.
    let preamble_only = r.render(&gles_set().map_sources(without_preamble), &p).expect("naga's `uniform highp` is enough");
    assert_eq!(image_ops::diff(&intact, &preamble_only, 0).over, 0);

    // Without any precision for sampler2DShadow the ES compiler refuses.
    match r.prepare(&gles_set().map_sources(without_any_sampler_precision)) {
        Err(GlError::Compile { file, log }) => {
            eprintln!("{file}: {log}");
            assert!(file.starts_with("main_fs"), "{file}");
            assert!(log.to_lowercase().contains("precision"), "{log}");
        }
        Err(e) => panic!("expected a compile error, got: {e}"),
        Ok(_) => panic!("an ES 3.00 sampler2DShadow without precision compiled"),
    }

    // Desktop GLSL 330 has no precision rules at all: its output carries none.
    let glsl330 = programs().glsl330;
    assert!(glsl330.files.values().all(|t| !t.contains("precision highp sampler2DShadow")));
}

#[test]
fn es_sampler_precision_matters_in_webgl2() {
    let Some(tools) = support::or_skip(WebGl::find(), "no WebGL2 consumer") else { return };
    let p = FrameParams::new(2.0, W, H);
    let preamble_only = tools.render(&gles_set().map_sources(without_preamble), &p).expect("naga's `uniform highp` is enough");
    let stats = image_ops::diff_masked(
        &preamble_only.image,
        &reference::render(&p),
        DELTA,
        Some(&reference::render_frame(&p).outside_shadow_map),
    );
    assert!(stats.fraction_over <= REF_MAX_FRACTION, "{stats}");
    let err = tools.render(&gles_set().map_sources(without_any_sampler_precision), &p).expect_err("no precision compiled in WebGL2");
    eprintln!("webgl2: {err}");
    assert!(err.contains("main_fs") && err.contains("does not compile"), "{err}");
    assert!(err.to_lowercase().contains("precision"), "{err}");
}

#[test]
fn gl_contexts_bind_what_the_reflection_names() {
    let Some(r) = gpu::gl(GlApi::Gl330) else { return };
    // A block renamed in the manifest but not in the shader is an error
    // that names it, not a black picture.
    let mut set = programs().glsl330;
    set.reflection.uniform_blocks[0].glsl_block = "nowhere_block".into();
    let err = r.prepare(&set).err().expect("a missing block must not bind").to_string();
    assert!(err.contains("nowhere_block"), "{err}");
    // So is an attribute location the driver disagrees with.
    let mut set = programs().glsl330;
    for e in &mut set.reflection.entry_points {
        for i in &mut e.inputs {
            if i.name == "a_normal" {
                i.location = 5;
            }
        }
    }
    let err = r.prepare(&set).err().expect("a wrong location must not bind").to_string();
    assert!(err.contains("location"), "{err}");
}
