//! `umbrac render --fit visible`: the light box fitted each frame to the
//! receivers a DSL compute pass finds in the camera's depth buffer
//! (`umbrac::render::visible`), on wgpu/Vulkan from the WGSL and from the
//! SPIR-V, and on an OpenGL 4.3 core context from the GLSL 430. The measured bounds must lie inside what the CPU knows the
//! camera can see, the box must be tighter than the tutorial's +-4, and
//! the shadow no worse against the CPU ray-cast reference than the fixed
//! box's.

use glam::{Vec3, Vec4Swizzles};
use umbrac::render::exec::wgpu::{WgpuExecutor, WgpuProgram};
use umbrac::render::scene::Frame;
use umbrac::render::{image_ops, reference, setup, visible, Consumer, Fit, FrameParams, SceneExecutor, Setup, ShaderSet, View};
use umbrac::Target;

use crate::support;

const SCENE: &str = include_str!("../../shaders/shadow.das");
const W: u32 = 320;
const H: u32 = 240;

fn scene(r: &WgpuExecutor, target: Target) -> WgpuProgram {
    let opts = umbrac::Options { targets: vec![target], ..Default::default() };
    let c = umbrac::compile_source("shaders/shadow.das", SCENE, &opts);
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    r.prepare_scene(&ShaderSet::from_compiled("shadow", c.result.as_ref().unwrap(), target).unwrap()).unwrap()
}

fn params(t: f32, fit: Fit) -> FrameParams {
    let mut p = FrameParams::new(t, W, H);
    p.setup = Setup::default();
    p.setup.shadow.fit = fit;
    p
}

/// Pixels whose lit/shadowed class differs from the reference's, over the
/// pixels showing geometry.
fn misclassified(gpu: &image::RgbaImage, gpu_lit: &image::RgbaImage, p: &FrameParams) -> usize {
    let truth = reference::render_frame(p);
    let ref_lit = reference::render(&p.with_view(View::Lit));
    let (a, b) = (image_ops::shadow_mask(gpu, gpu_lit), image_ops::shadow_mask(&truth.image, &ref_lit));
    a.iter().zip(&b).filter(|(x, y)| x != y).count()
}

/// The light-space bounds of what the CPU knows can be seen: the floor
/// clipped to the camera's frustum, and the cube.
fn cpu_receivers(f: &Frame) -> (Vec3, Vec3) {
    let mut pts = setup::visible_floor(f.floor_model, f.proj * f.view);
    pts.extend(setup::cube_corners(f.cube_model));
    pts.iter().map(|p| (f.light_view * p.extend(1.0)).xyz()).fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(p), hi.max(p)))
}

#[test]
fn visible_fit_is_tighter_and_no_worse_than_the_fixed_box() {
    let Some(vk) = support::gpu::vulkan() else { return };
    let wgsl = scene(vk, Target::Wgsl);
    let reduction = visible::program(Target::Wgsl).unwrap();
    for t in [0.0f32, 2.0] {
        let fixed = params(t, Fit::Fixed);
        let vis = params(t, Fit::Visible);
        let measured = visible::measure(vk, &wgsl, &reduction, &vis).unwrap();
        let (lo, hi) = measured.visible_bounds.expect("the camera sees the scene");
        // Inside what the CPU knows is visible (1 % of its extent to spare
        // for the depth buffer's rounding), and not a sliver of it.
        let (clo, chi) = cpu_receivers(&Frame::of(&vis));
        let slack = (chi - clo) * 0.01;
        assert!(lo.cmpge(clo - slack).all() && hi.cmple(chi + slack).all(), "t = {t}: measured {lo}..{hi}, the CPU's visible receivers {clo}..{chi}");
        assert!((hi - lo).cmpgt((chi - clo) * 0.5).all(), "t = {t}: measured {lo}..{hi} covers little of {clo}..{chi}");
        // Tighter than +-4 across the light: the projection's x and y scale
        // is 1 / half-extent.
        let (fp, vp) = (Frame::of(&fixed).light_proj, Frame::of(&measured).light_proj);
        let (fixed_half, vis_half) = (1.0 / fp.x_axis.x, 1.0 / vp.x_axis.x);
        assert!((1.0 / vp.y_axis.y - vis_half).abs() < 1e-4, "square texels");
        assert!(vis_half < fixed_half, "t = {t}: the visible box's half-extent {vis_half} is not below the fixed {fixed_half}");
        // The shadow against the reference.
        let lit = vk.draw_scene(&wgsl, &fixed.with_view(View::Lit)).unwrap();
        let fixed_img = vk.draw_scene(&wgsl, &fixed).unwrap();
        let vis_img = visible::render(vk, &wgsl, &reduction, &vis).unwrap().into_image();
        let (fe, ve) = (misclassified(&fixed_img, &lit, &fixed), misclassified(&vis_img, &lit, &vis));
        eprintln!("t = {t}: half-extent fixed {fixed_half}, visible {vis_half:.3}; misclassified pixels of {W}x{H}: fixed {fe}, visible {ve}");
        assert!(ve <= fe, "t = {t}: the visible box misclassifies {ve} pixels, the fixed one {fe}");
        if t == 0.0 {
            image_ops::save_png(&vis_img, &support::gpu::artifacts_dir("visible_fit").join("t0.png")).unwrap();
        }
    }
}

/// The SPIR-V (passed through unchanged) measures what the WGSL measures.
#[test]
fn visible_fit_from_spirv_matches_wgsl() {
    let Some(vk) = support::gpu::vulkan() else { return };
    if !vk.supports_passthrough() {
        support::skip("visible fit from SPIR-V: the Vulkan device takes no SPIR-V unchanged");
        return;
    }
    let p = params(2.0, Fit::Visible);
    let from = |target| visible::measure(vk, &scene(vk, target), &visible::program(target).unwrap(), &p).unwrap().visible_bounds.unwrap();
    let ((wlo, whi), (slo, shi)) = (from(Target::Wgsl), from(Target::Spirv));
    let tol = (whi - wlo).max_element() * 1e-4;
    assert!((wlo - slo).abs().max_element() <= tol && (whi - shi).abs().max_element() <= tol, "WGSL {wlo}..{whi}, SPIR-V {slo}..{shi}");
}

/// On an OpenGL 4.3 core context, from the GLSL 430: the bounds the WGSL
/// measures on Vulkan, and the shadow no worse than the fixed box's (a
/// sampler without clamp-to-border, as GL 4.3 frames had before, shadows
/// everything outside the box and fails this).
#[cfg(feature = "gl")]
#[test]
fn visible_fit_on_gl430_matches_vulkan() {
    use umbrac::render::Executor;
    let (Some(vk), Some(gl)) = (support::gpu::vulkan(), support::gpu::gl(Consumer::Gl430)) else { return };
    let p = params(2.0, Fit::Visible);
    let (wlo, whi) = visible::measure(vk, &scene(vk, Target::Wgsl), &visible::program(Target::Wgsl).unwrap(), &p).unwrap().visible_bounds.unwrap();
    let opts = umbrac::Options { targets: vec![Target::Glsl430], ..Default::default() };
    let c = umbrac::compile_source("shaders/shadow.das", SCENE, &opts);
    let set = ShaderSet::from_compiled("shadow", c.result.as_ref().unwrap(), Target::Glsl430).unwrap();
    let prepared = gl.prepare_scene(&set).unwrap();
    let reduction = visible::program(Target::Glsl430).unwrap();
    let (glo, ghi) = visible::measure(&gl, &prepared, &reduction, &p).unwrap().visible_bounds.unwrap();
    let tol = (whi - wlo).max_element() * 1e-3;
    assert!((wlo - glo).abs().max_element() <= tol && (whi - ghi).abs().max_element() <= tol, "Vulkan {wlo}..{whi}, GL 4.3 {glo}..{ghi}");
    let fixed = params(2.0, Fit::Fixed);
    let lit = gl.run(&prepared, &umbrac::render::plan::tutorial::plan(&fixed.with_view(View::Lit))).unwrap().into_image();
    let fixed_img = gl.run(&prepared, &umbrac::render::plan::tutorial::plan(&fixed)).unwrap().into_image();
    let vis_img = visible::render(&gl, &prepared, &reduction, &p).unwrap().into_image();
    // `consumers::run` draws the scene's plans on GL 4.3 the same way.
    let (again, _) = umbrac::render::consumers::run(Consumer::Gl430, &set, &umbrac::render::plan::tutorial::plan(&fixed)).unwrap();
    assert!(again.into_image() == fixed_img, "consumers::run on gl430 draws another picture");
    let (fe, ve) = (misclassified(&fixed_img, &lit, &fixed), misclassified(&vis_img, &lit, &p));
    eprintln!("gl430 t = 2: misclassified pixels of {W}x{H}: fixed {fe}, visible {ve}");
    assert!(ve <= fe, "the visible box misclassifies {ve} pixels on GL 4.3, the fixed one {fe}");
}

/// Consumers without compute refuse `--fit visible` by name.
#[test]
fn visible_fit_names_consumers_without_compute() {
    for c in [Consumer::Gl330, Consumer::Gles300, Consumer::WebGl2, Consumer::WgpuGl] {
        let opts = umbrac::render::command::RenderOptions {
            consumer: c,
            setup: params(0.0, Fit::Visible).setup,
            out: support::gpu::artifacts_dir("visible_fit").join("never.png"),
            ..Default::default()
        };
        let e = umbrac::render::command::run(&opts, &mut umbrac::render::command::Quiet).unwrap_err();
        assert!(e.contains(&format!("{} runs no compute programs", c.name())), "{e}");
        assert!(!opts.out.exists(), "nothing written");
    }
    assert!(visible::check_consumer(Consumer::VulkanWgsl).is_ok() && visible::check_consumer(Consumer::VulkanSpirv).is_ok());
    assert!(visible::check_consumer(Consumer::Gl430).is_ok());
    let opts = umbrac::render::command::RenderOptions { scene: Some("spot".into()), setup: params(0.0, Fit::Visible).setup, ..Default::default() };
    let e = umbrac::render::command::run(&opts, &mut umbrac::render::command::Quiet).unwrap_err();
    assert!(e.contains("--fit visible fits the tutorial scene's sun box"), "{e}");
    let e = visible::check_consumer(Consumer::Gles310).unwrap_err();
    assert!(e.contains("gles310 does not run it"), "{e}");
}
