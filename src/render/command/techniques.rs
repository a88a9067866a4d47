//! `umbrac render --scene NAME`: the technique scenes on the command line.

use std::path::{Path, PathBuf};
use std::time::Instant;

use image::RgbaImage;

use super::RenderOptions;
use crate::render::consumers::{self, Consumer};
use crate::render::exec::{ExecError, Executor};
use crate::render::image_ops;
use crate::render::program::ShaderSet;
use crate::render::scene::{FrameParams, View};
use crate::render::techniques::{self, reference, Technique};

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

/// Prepares the technique's program for its plan, then times frames.
fn draw<E: Executor>(e: &E, set: &ShaderSet, technique: Technique, params: &FrameParams) -> Result<(RgbaImage, f64, String), String> {
    let plan = techniques::plan(technique, params);
    let prepared = e.prepare(set, &plan).map_err(|e| e.to_string())?;
    let (image, ms) = timed(|| e.run(&prepared, &plan).map(|r| r.into_image()).map_err(|e: ExecError| e.to_string()))?;
    Ok((image, ms, e.device_name()))
}

pub fn run(args: &RenderOptions) -> Result<(), String> {
    let name = args.scene.as_deref().unwrap_or_default();
    if ![1, 2, 4, 9].contains(&args.pcf_taps) {
        return Err(format!("--pcf-taps {} must be 1, 2, 4 or 9", args.pcf_taps));
    }
    let technique = Technique::parse(name, args.pcf_taps)
        .ok_or_else(|| format!("unknown --scene `{name}` (the scenes are spot, pcf, cascades, proj, cull, rgba8-depth)"))?;
    if args.view != View::Final || args.frames.is_some() {
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
    let c = args.consumer;
    let target = c.target().ok_or("the CPU reference of a technique scene is --reference")?;
    let set = ShaderSet::from_compiled(technique.name(), &compiled, target)?;
    let (image, ms, device) = match c {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => draw(consumers::vulkan().map_err(|e| e.to_string())?, &set, technique, &params)?,
        Consumer::WgpuGl => draw(consumers::wgpu_gl().map_err(|e| e.to_string())?, &set, technique, &params)?,
        #[cfg(feature = "gl")]
        Consumer::Gl330 | Consumer::Gles300 => {
            let _ = consumers::wgpu_gl();
            draw(&crate::render::exec::gl::GlExecutor::new(c).map_err(|e| e.to_string())?, &set, technique, &params)?
        }
        Consumer::WebGl2 => draw(&crate::render::exec::webgl::WebGl::find().map_err(|e| e.to_string())?, &set, technique, &params)?,
        other => return Err(format!("{} cannot draw the technique scenes here", other.name())),
    };
    let device = format!("{} on {device}", c.name());
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
