//! The shadow technique scenes (shaders/techniques/, docs/gallery.md)
//! against their CPU reference, at 160 x 120, on the wgpu runner (Vulkan)
//! and on the GL 3.3 consumer.
//!
//! Tolerances, per technique and frame:
//! - a pixel differs when a channel differs by more than `DELTA` = 8/255;
//!   at most `max_fraction` of all pixels may differ (the table below:
//!   the filtered techniques soften the outline the reference decides
//!   exactly, the unfiltered ones alias along it; measured 0.01 - 0.26 %
//!   on lavapipe and llvmpipe, allowed 1 %);
//! - the shadow masks (pixels darker by more than 24/255 in luma than the
//!   reference's fully lit frame) must overlap with IoU >= `MIN_IOU` = 0.85,
//!   and the reference's mask must hold at least 40 pixels, so the check
//!   is about a visible shadow.
//!
//! Without a Vulkan adapter or an EGL GL 3.3 context the tests print why
//! and pass, unless `CI=true`, where they fail.

use crate::support;

use support::gpu;
use umbrac::render::image_ops;
use umbrac::render::techniques::{self, reference, Technique};
use umbrac::render::{Consumer, Executor, FrameParams, ShaderSet};
use umbrac::Target;

const W: u32 = 160;
const H: u32 = 120;
const DELTA: u8 = 8;
const MIN_IOU: f64 = 0.85;
const TIMES: [f32; 2] = [1.0, 4.0];

/// Largest fraction of differing pixels allowed, per technique.
fn max_fraction(t: Technique) -> f64 {
    match t {
        Technique::Spot => 0.01,
        Technique::Pcf { .. } => 0.01,
        Technique::Cascades => 0.01,
        Technique::Proj => 0.01,
        Technique::Cull => 0.01,
        Technique::Rgba8Depth => 0.01,
    }
}

fn judge(t: Technique, consumer: &str, time: f32, image: &image::RgbaImage, r: &reference::TechRef) -> Option<String> {
    let stats = image_ops::diff(image, &r.image, DELTA);
    let gpu_mask = image_ops::shadow_mask(image, &r.lit);
    let ref_mask = image_ops::shadow_mask(&r.image, &r.lit);
    let iou = image_ops::iou(&gpu_mask, &ref_mask);
    let shadow = image_ops::count(&ref_mask);
    eprintln!("{} on {consumer} t={time}: {stats}; IoU {iou:.3}; reference shadow {shadow} px", t.name());
    if stats.fraction_over <= max_fraction(t) && iou >= MIN_IOU && shadow >= 40 {
        return None;
    }
    let path = gpu::artifacts_dir("technique-tests").join(format!("{}-{consumer}-t{time}.png", t.name()));
    let diff = image_ops::diff_image(image, &r.image, None);
    image_ops::save_png(&image_ops::side_by_side(&[image, &r.image, &diff]), &path).unwrap();
    Some(format!(
        "{} on {consumer} at t = {time}: {stats} (max {:.2}%), IoU {iou:.3} (min {MIN_IOU}), reference shadow {shadow} px; see {}",
        t.name(),
        100.0 * max_fraction(t),
        path.display()
    ))
}

fn check(t: Technique) {
    let compiled = t.compile().unwrap_or_else(|e| panic!("{e}"));
    let mut failures = Vec::new();
    let frames: Vec<(f32, FrameParams, reference::TechRef)> = TIMES
        .iter()
        .map(|&time| {
            let p = FrameParams::new(time, W, H);
            (time, p, reference::render(t, &p))
        })
        .collect();
    // One plan per frame, run by each executor.
    let mut run = |consumer: &str, e: &dyn Fn(&umbrac::render::plan::FramePlan) -> Result<image::RgbaImage, String>| {
        for (time, p, reference) in &frames {
            let image = e(&techniques::plan(t, p)).unwrap_or_else(|e| panic!("{} on {consumer}: {e}", t.name()));
            failures.extend(judge(t, consumer, *time, &image, reference));
        }
    };
    if let Some(r) = gpu::vulkan() {
        let set = ShaderSet::from_compiled(t.name(), &compiled, Target::Wgsl).unwrap();
        let program = r.prepare(&set, &techniques::plan(t, &frames[0].1)).unwrap_or_else(|e| panic!("{}: {e}", t.name()));
        run("wgpu", &|plan| r.run(&program, plan).map(|x| x.into_image()).map_err(|e| e.to_string()));
    }
    if let Some(gl) = gpu::gl(Consumer::Gl330) {
        let set = ShaderSet::from_compiled(t.name(), &compiled, Target::Glsl330).unwrap();
        let program = gl.prepare(&set, &techniques::plan(t, &frames[0].1)).unwrap_or_else(|e| panic!("{} on GL 3.3: {e}", t.name()));
        run("gl330", &|plan| gl.run(&program, plan).map(|x| x.into_image()).map_err(|e| e.to_string()));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn spot_light_with_manual_compare() {
    check(Technique::Spot);
}

#[test]
fn pcf_offset_table_nine_taps() {
    check(Technique::Pcf { taps: 9 });
}

#[test]
fn pcf_offset_table_smaller_variants() {
    for taps in [1, 2, 4] {
        check(Technique::Pcf { taps });
    }
}

#[test]
fn three_cascades() {
    check(Technique::Cascades);
}

#[test]
fn projective_lookup() {
    check(Technique::Proj);
}

#[test]
fn front_face_culling_without_bias() {
    check(Technique::Cull);
}

#[test]
fn rgba8_encoded_depth() {
    check(Technique::Rgba8Depth);
}

/// The same plans in WebGL2 (the page runs any plan, not only the
/// tutorial's): three shadow passes and an array of shadow samplers, and
/// depth encoded into an RGBA8 target read without compare. WebGL2 has no
/// clamp-to-border; these scenes do not use it.
#[test]
fn technique_scenes_run_in_webgl2() {
    use umbrac::render::exec::webgl::WebGl;
    let Some(page) = support::or_skip(WebGl::find(), "no WebGL2 consumer") else { return };
    let mut failures = Vec::new();
    for t in [Technique::Cascades, Technique::Rgba8Depth] {
        let compiled = t.compile().unwrap_or_else(|e| panic!("{e}"));
        let set = ShaderSet::from_compiled(t.name(), &compiled, Target::Gles300).unwrap();
        let p = FrameParams::new(TIMES[1], W, H);
        let plan = techniques::plan(t, &p);
        let program = page.prepare(&set, &plan).unwrap_or_else(|e| panic!("{} in WebGL2: {e}", t.name()));
        let image = page.run(&program, &plan).unwrap_or_else(|e| panic!("{} in WebGL2: {e}", t.name())).into_image();
        failures.extend(judge(t, "webgl2", TIMES[1], &image, &reference::render(t, &p)));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
