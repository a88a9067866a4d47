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

/// The consumers every tutorial is drawn on.
const DRAWING: [Consumer; 6] = [Consumer::VulkanWgsl, Consumer::VulkanSpirv, Consumer::WgpuGl, Consumer::Gl330, Consumer::Gles300, Consumer::WebGl2];

/// `plan` drawn on `c` from `programs`, saved as `NAME_CONSUMER.png` among
/// the test artifacts (returned with its path); `None` (skipped) where the
/// consumer is unavailable here.
fn draw(c: Consumer, programs: &Programs, plan: &umbrac::render::plan::FramePlan, name: &str) -> Option<(image::RgbaImage, std::path::PathBuf)> {
    let set = programs.for_consumer(c).expect("a drawing consumer has a program");
    let image = match consumers::run(c, set, plan) {
        Ok((r, _)) => r.into_image(),
        Err(e @ ExecError::Unavailable { .. }) => {
            ci::skip(format!("{}: {e}", c.name()));
            return None;
        }
        Err(e) => panic!("{name} on {}: {e}", c.name()),
    };
    let out = gpu::artifacts_dir("vk-tutorial-tests").join(format!("{name}_{}.png", c.name()));
    umbrac::render::image_ops::save_png(&image, &out).unwrap();
    Some((image, out))
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
        for c in DRAWING {
            let Some((image, out)) = draw(c, &programs, &plan, &format!("triangle_{angle}")) else { continue };
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

/// 04 (cube), 05 (instancing: nine cubes in one instanced draw, offset,
/// colour and phase per instance) and 09 (MSAA, one sample here), with
/// their camera block (and, 04 and 09, the push-constant model matrix and
/// a stand-in texture), at two times. Every pixel the host's math puts
/// inside a face (by a pixel) must be drawn, every pixel outside every
/// cube by as much must be the clear colour; drawn with back faces culled
/// the picture must not change away from the edges (the front-face rule);
/// there the consumers agree with the first within 8/255 on at least
/// 99.8 % of the pixels.
#[test]
fn cube_instancing_and_msaa_draw_on_every_consumer() {
    use umbrac::render::plan::vk_tutorials::{self as vt, cube, cube_covers, instancing, instancing_covers};
    use umbrac::render::plan::{Cull, FramePlan};
    type Case = (&'static str, &'static str, Box<dyn Fn(f32, u32, u32, Cull) -> FramePlan>, fn(f32, u32, u32, u32, u32, f32) -> Option<bool>);
    let cases: Vec<Case> = vec![
        ("04_cube/cube_tut_shaders.das", vt::CUBE_VS, Box::new(|t, w, h, c| cube(vt::CUBE_VS, vt::CUBE_FS, t, w, h, c)), cube_covers),
        ("05_instancing/instancing_tut_shaders.das", vt::INSTANCING_VS, Box::new(instancing), instancing_covers),
        ("09_msaa/msaa_tut_shaders.das", vt::MSAA_VS, Box::new(|t, w, h, c| cube(vt::MSAA_VS, vt::MSAA_FS, t, w, h, c)), cube_covers),
    ];
    let (w, h) = (64u32, 48u32);
    for (file, vs, make, covers) in &cases {
        let Some(programs) = programs(file) else { return };
        for t in [0.0f32, 2.5] {
            let plan = make(t, w, h, Cull::None);
            let culled = make(t, w, h, Cull::Back);
            let edges: Vec<bool> = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| covers(t, w, h, x, y, 1.0).is_none()).collect();
            let mut first: Option<(Consumer, image::RgbaImage)> = None;
            for c in DRAWING {
                let Some((image, out)) = draw(c, &programs, &plan, &format!("{vs}_{t}")) else { continue };
                let set = programs.for_consumer(c).expect("a drawing consumer has a program");
                let back = consumers::run(c, set, &culled).unwrap_or_else(|e| panic!("{file} on {} culled: {e}", c.name())).0.into_image();
                let cull_diff = umbrac::render::image_ops::diff_masked(&image, &back, 8, Some(&edges));
                assert!(cull_diff.over == 0, "{vs} on {} t = {t}: culling back faces changed the picture (front faces the wrong way): {cull_diff}", c.name());
                let (mut covered, mut empty, mut wrong) = (0, 0, Vec::new());
                for (x, y, p) in image.enumerate_pixels() {
                    let Some(expect) = covers(t, w, h, x, y, 1.0) else { continue };
                    let drawn = p[0] > 2 || p[1] > 2 || p[2] > 2;
                    if expect {
                        covered += 1;
                    } else {
                        empty += 1;
                    }
                    if drawn != expect {
                        wrong.push((x, y, expect));
                    }
                }
                let vs_first = first.as_ref().map(|(_, f)| umbrac::render::image_ops::diff_masked(f, &image, 8, Some(&edges)));
                eprintln!(
                    "{vs} {} t = {t}: {covered} covered, {empty} empty, {} wrong; vs {}: {} ({})",
                    c.name(),
                    wrong.len(),
                    first.as_ref().map_or("-", |(f, _)| f.name()),
                    vs_first.as_ref().map_or("-".into(), |s| s.to_string()),
                    out.display()
                );
                assert!(covered > 100 && empty > 100, "{covered} / {empty}");
                assert!(wrong.is_empty(), "{vs} on {} t = {t}: {} pixels wrong, first {:?}", c.name(), wrong.len(), &wrong[..wrong.len().min(4)]);
                if let Some(s) = vs_first {
                    assert!(s.fraction_over <= 0.002, "{vs} on {} t = {t} differs from the first consumer: {s}", c.name());
                }
                first.get_or_insert((c, image));
            }
        }
    }
}
