//! `umbrac render --scene NAME`: the technique scenes on the command line.

use std::path::{Path, PathBuf};
use std::time::Instant;

use image::RgbaImage;

use super::args::{BackendArg, RenderArgs, ViewArg};
use crate::render::gpu::{Backend, Renderer};
use crate::render::image_ops;
use crate::render::scene::FrameParams;

use crate::render::techniques::{reference, wgpu_host, Technique};

/// Frames timed after the warm-up frame.
const TIMED_FRAMES: u32 = 5;

fn sibling(out: &Path, suffix: &str) -> PathBuf {
    let stem = out.file_stem().map_or("frame".into(), |s| s.to_string_lossy().into_owned());
    out.with_file_name(format!("{stem}.{suffix}.png"))
}

/// Renders a warm-up frame (pipelines compile in the driver), then times
/// `TIMED_FRAMES` more; returns the last image and the mean milliseconds.
fn timed(mut frame: impl FnMut() -> Result<RgbaImage, String>) -> Result<(RgbaImage, f64), String> {
    let mut image = frame()?;
    let start = Instant::now();
    for _ in 0..TIMED_FRAMES {
        image = frame()?;
    }
    Ok((image, start.elapsed().as_secs_f64() * 1000.0 / TIMED_FRAMES as f64))
}

pub fn run(args: &RenderArgs) -> Result<(), String> {
    let name = args.scene.as_deref().unwrap_or_default();
    if ![1, 2, 4, 9].contains(&args.pcf_taps) {
        return Err(format!("--pcf-taps {} must be 1, 2, 4 or 9", args.pcf_taps));
    }
    let technique = Technique::parse(name, args.pcf_taps)
        .ok_or_else(|| format!("unknown --scene `{name}` (the scenes are spot, pcf, cascades, proj, cull, rgba8-depth)"))?;
    if args.view != ViewArg::Final || args.frames.is_some() {
        return Err("technique scenes render the final view of one frame (no --view, no --frames)".into());
    }
    if args.shadow_size == 0 || args.shadow_size > 16384 {
        return Err(format!("--shadow-size {} must be between 1 and 16384", args.shadow_size));
    }
    let (width, height) = args.size;
    let mut params = FrameParams::new(args.time, width, height);
    params.shadow_size = args.shadow_size;
    let save = |image: &RgbaImage, path: &Path| image_ops::save_png(image, path);

    if args.reference {
        let r = reference::render(technique, &params);
        save(&r.image, &args.out)?;
        println!("wrote {} (CPU reference of the {} scene)", args.out.display(), technique.name());
        return Ok(());
    }
    let compiled = technique.compile()?;
    let (image, ms, device) = match args.backend {
        BackendArg::Vulkan | BackendArg::Gl => {
            let backend = if args.backend == BackendArg::Vulkan { Backend::Vulkan } else { Backend::Gl };
            let renderer = Renderer::new(backend).map_err(|e| e.to_string())?;
            let host = wgpu_host::TechRenderer::new(&renderer);
            let program = host.prepare(technique, &compiled)?;
            let (image, ms) = timed(|| host.draw(&program, &params))?;
            (image, ms, format!("wgpu {} on {}", backend.name(), renderer.adapter_name()))
        }
        #[cfg(feature = "gl")]
        BackendArg::Gl330 | BackendArg::Gles300 => {
            use crate::render::gl::{GlApi, GlRenderer};
            use crate::render::techniques::gl_host;
            let api = if args.backend == BackendArg::Gl330 { GlApi::Gl330 } else { GlApi::Gles300 };
            let r = GlRenderer::new(api).map_err(|e| e.to_string())?;
            let program = gl_host::prepare(&r, technique, &compiled)?;
            let result = timed(|| gl_host::draw(&r, &program, &params));
            gl_host::release(&r, program);
            let (image, ms) = result?;
            (image, ms, format!("{} on {}", api.name(), r.adapter_name()))
        }
        #[cfg(not(feature = "gl"))]
        BackendArg::Gl330 | BackendArg::Gles300 => return Err("built without the `gl` feature".into()),
    };
    save(&image, &args.out)?;
    println!(
        "wrote {} ({} scene, {}x{}, shadow map {}, {device}): {ms:.1} ms per frame (mean of {TIMED_FRAMES} after a warm-up, readback included)",
        args.out.display(),
        technique.name(),
        width,
        height,
        args.shadow_size
    );
    if args.compare {
        let r = reference::render(technique, &params);
        let stats = image_ops::diff(&image, &r.image, 8);
        let masks = (image_ops::shadow_mask(&image, &r.lit), image_ops::shadow_mask(&r.image, &r.lit));
        println!("vs CPU reference (delta 8/255): {stats}; shadow IoU {:.3}", image_ops::iou(&masks.0, &masks.1));
        save(&r.image, &sibling(&args.out, "ref"))?;
        save(&image_ops::diff_image(&image, &r.image, None), &sibling(&args.out, "diff"))?;
    }
    Ok(())
}
