//! dasVulkan's single-pass tutorials drawn on every consumer with their
//! host's values (`render::plan::vk_tutorials`), each pixel checked
//! against what the host expects there. Needs `../shared/reference/daslang`.

use std::path::Path;

use umbrac::render::consumers::{self, Consumer, Programs};
use umbrac::render::plan::vk_tutorials::{self, triangle_expected};
use umbrac::render::ExecError;

use crate::support::{self as ci, gpu};

fn programs(rel: &str) -> Option<Programs> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang");
    let file = root.join("modules/dasVulkan/tutorials").join(rel);
    if !file.is_file() {
        ci::skip(format!("{} is not here", file.display()));
        return None;
    }
    let opts = umbrac::Options { daslang_root: Some(root), ..Default::default() };
    let c = umbrac::compile_file(&file, &opts);
    let result = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{rel} did not compile:\n{}", c.render_diagnostics()));
    Some(Programs::from_compiled(rel, result).unwrap())
}

/// 01: the spinning triangle at two angles. Inside (by a barycentric
/// margin) each pixel is the interpolated vertex colour within 2/255,
/// outside it is the clear colour; pixels on the edges are not compared.
/// The red vertex is at the top at angle 0 (Vulkan's orientation): a
/// consumer that flipped the picture fails at most pixels.
#[test]
fn triangle_draws_on_every_consumer() {
    let Some(programs) = programs("01_triangle/triangle_tut_shaders.das") else { return };
    let (w, h) = (64u32, 48u32);
    for angle in [0.0f32, 0.9] {
        let plan = vk_tutorials::triangle(angle, w, h);
        for c in [Consumer::VulkanWgsl, Consumer::VulkanSpirv, Consumer::WgpuGl, Consumer::Gl330, Consumer::Gles300, Consumer::WebGl2] {
            let set = programs.for_consumer(c).expect("a drawing consumer has a program");
            let image = match consumers::run(c, set, &plan) {
                Ok((r, _)) => r.into_image(),
                Err(e @ ExecError::Unavailable { .. }) => {
                    ci::skip(format!("{}: {e}", c.name()));
                    continue;
                }
                Err(e) => panic!("{} angle {angle}: {e}", c.name()),
            };
            let out = gpu::artifacts_dir("vk-tutorial-tests").join(format!("triangle_{}_{angle}.png", c.name()));
            umbrac::render::image_ops::save_png(&image, &out).unwrap();
            let (mut inside, mut outside, mut wrong) = (0, 0, Vec::new());
            for (x, y, p) in image.enumerate_pixels() {
                let Some(rgb) = triangle_expected(angle, w, h, x, y, 0.02) else { continue };
                if rgb == [0.0; 3] {
                    outside += 1;
                } else {
                    inside += 1;
                }
                let off = (0..3).map(|i| (p[i] as f32 - rgb[i] * 255.0).abs()).fold(0.0, f32::max);
                if off > 2.0 {
                    wrong.push((x, y, p.0, rgb));
                }
            }
            eprintln!("triangle {} angle {angle}: {inside} inside, {outside} outside, {} wrong ({})", c.name(), wrong.len(), out.display());
            assert!(inside > 200 && outside > 200, "{inside} / {outside}");
            assert!(wrong.is_empty(), "{} angle {angle}: {} pixels wrong, first {:?}", c.name(), wrong.len(), &wrong[..wrong.len().min(4)]);
        }
    }
}
