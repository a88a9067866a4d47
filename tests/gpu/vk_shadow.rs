//! dasVulkan's shadow rung (the seed tutorial's origin, in daslang's Vulkan
//! dialect) drawn by every consumer with a Vulkan host's conventions
//! (`render::plan::vk_shadow`), checked against the GL tutorial's scene
//! where the two are comparable: the shadow mask and what the geometry
//! covers (their shading differs: bricks, tiles, sheen). Needs
//! `../shared/reference/daslang`.

use std::path::Path;

use image::RgbaImage;
use umbrac::render::consumers::{self, Consumer, Programs, Status};
use umbrac::render::{image_ops, reference, FrameParams, View};

use crate::support::{self as ci, gpu};

const W: u32 = 160;
const H: u32 = 120;

fn programs() -> Option<Programs> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang");
    let file = root.join("modules/dasVulkan/tutorials/08_shadow/shadow_tut_shaders.das");
    if !file.is_file() {
        ci::skip(format!("{} is not here", file.display()));
        return None;
    }
    let opts = umbrac::Options { daslang_root: Some(root), ..Default::default() };
    let c = umbrac::compile_file(&file, &opts);
    let result = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("did not compile:\n{}", c.render_diagnostics()));
    Some(Programs::from_compiled("shadow_tut_shaders.das", result).unwrap())
}

/// Pixels the geometry covers: not the clear colour (within rounding; the
/// rung's floor grout in shadow comes within a few levels of it).
fn coverage(image: &RgbaImage) -> Vec<bool> {
    let clear = umbrac::render::tutorial::CLEAR.map(|c| (c * 255.0).round() as i32);
    image.pixels().map(|p| (0..3).any(|i| (p[i] as i32 - clear[i]).abs() > 1)).collect()
}

fn image(status: Status, c: Consumer) -> Option<RgbaImage> {
    match status {
        Status::Rendered { image, .. } => Some(image),
        Status::Unavailable { why, install } => {
            ci::skip(format!("{}: {why} ({install})", c.name()));
            None
        }
        Status::Failed(e) => panic!("{}: {e}", c.name()),
    }
}

#[test]
fn the_origin_of_the_seed_renders_on_every_consumer() {
    let Some(programs) = programs() else { return };
    for t in [1.0f32, 4.0] {
        let p = FrameParams::new(t, W, H);
        let reference = reference::render_frame(&p);
        let ref_lit = reference::render(&p.with_view(View::Lit));
        let skip = &reference.outside_shadow_map;
        let inside = |m: Vec<bool>| m.into_iter().zip(skip).map(|(m, s)| m && !s).collect::<Vec<_>>();
        let ref_shadow = inside(image_ops::shadow_mask(&reference.image, &ref_lit));
        let ref_cover = coverage(&reference.image);
        let mut first: Option<(Consumer, RgbaImage)> = None;
        for c in [Consumer::VulkanWgsl, Consumer::VulkanSpirv, Consumer::WgpuGl, Consumer::Gl330, Consumer::Gles300, Consumer::WebGl2] {
            let Some(img) = image(consumers::render(c, &programs, &p), c) else { continue };
            let Some(lit) = image(consumers::render(c, &programs, &p.with_view(View::Lit)), c) else { continue };
            let shadow = inside(image_ops::shadow_mask(&img, &lit));
            let shadow_iou = image_ops::iou(&shadow, &ref_shadow);
            let cover_iou = image_ops::iou(&coverage(&img), &ref_cover);
            // The check sees orientation: the picture upside down fails it.
            let flipped_iou = image_ops::iou(&coverage(&image::imageops::flip_vertical(&img)), &ref_cover);
            let vs_first = first.as_ref().map(|(_, f)| image_ops::diff_masked(f, &img, 8, Some(skip)));
            let out = gpu::artifacts_dir("vk-shadow-tests").join(format!("{}_t{t}.png", c.name()));
            image_ops::save_png(&image_ops::side_by_side(&[&img, &lit, &reference.image]), &out).unwrap();
            eprintln!(
                "t = {t} {}: shadow IoU {shadow_iou:.3}, coverage IoU {cover_iou:.4} (upside down {flipped_iou:.3}), vs {}: {} ({})",
                c.name(),
                first.as_ref().map_or("-", |(f, _)| f.name()),
                vs_first.as_ref().map_or("-".to_string(), |s| s.to_string()),
                out.display()
            );
            // The runner's reference bounds (docs/runner.md, "Tolerances").
            assert!(shadow_iou >= 0.9, "{} t = {t}: shadow IoU {shadow_iou}", c.name());
            assert!(cover_iou >= 0.99, "{} t = {t}: coverage IoU {cover_iou}", c.name());
            assert!(flipped_iou < 0.9, "{} t = {t}: coverage IoU upside down {flipped_iou}", c.name());
            if let Some(s) = vs_first {
                assert!(s.fraction_over <= 0.002, "{} t = {t} differs from the first consumer: {s}", c.name());
            }
            first.get_or_insert((c, img));
        }
    }
}

/// wgpu's Vulkan backend numbers a passthrough module's descriptors by
/// their place in the layout. The compiler leaves the rung no gaps (its
/// sampler halves at 7 - 11, after the bindings 0 - 6 of group 0); a
/// manifest with one (the last half moved to 13) is refused by name on
/// `vulkan-spirv` rather than bound wrongly.
#[test]
fn spirv_passthrough_refuses_a_binding_gap_by_name() {
    let Some(mut programs) = programs() else { return };
    let r = programs.spirv.reflection.as_mut().expect("SPIR-V has a manifest");
    let halves: Vec<(u32, u32)> = r.samplers.iter().map(|s| (s.group, s.sampler_binding)).collect();
    assert_eq!(halves, (7..12).map(|b| (0, b)).collect::<Vec<_>>(), "the sampler halves follow group 0's bindings 0 - 6");
    r.samplers.last_mut().unwrap().sampler_binding = 13;
    match consumers::render(Consumer::VulkanSpirv, &programs, &FrameParams::new(1.0, W, H)) {
        Status::Failed(e) => assert!(e.to_string().contains("binding 13") && e.to_string().contains("no gaps"), "{e}"),
        Status::Unavailable { why, install } => ci::skip(format!("vulkan-spirv: {why} ({install})")),
        Status::Rendered { .. } => panic!("a manifest with a binding gap rendered through passthrough"),
    }
}
