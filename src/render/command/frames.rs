//! Writing what the runner renders: one PNG, or an animation's frames and
//! GIF, and the `--compare` images against the CPU reference.

use std::path::Path;
use std::time::Instant;

use super::{Progress, RenderOptions};
use crate::render::scene::{FrameParams, View};
use crate::render::{image_ops, reference};

pub fn frame_times(args: &RenderOptions) -> Vec<f32> {
    match args.frames {
        None => vec![args.time],
        Some(n) => (0..n).map(|i| args.time + i as f32 / args.fps).collect(),
    }
}

pub fn write_frames(
    args: &RenderOptions,
    times: &[f32],
    mut render: impl FnMut(&FrameParams) -> Result<image::RgbaImage, String>,
    base: FrameParams,
    progress: &mut dyn Progress,
) -> Result<(), String> {
    if args.frames.is_none() {
        let started = Instant::now();
        let image = render(&base)?;
        let ms = started.elapsed().as_secs_f64() * 1e3;
        image_ops::save_png(&image, &args.out)?;
        eprintln!(
            "wrote {} ({}x{}, t = {}, view {}, {ms:.1} ms)",
            args.out.display(),
            image.width(),
            image.height(),
            base.time,
            base.view.name()
        );
        if args.compare {
            compare(&image, &base, &args.out)?;
        }
        return Ok(());
    }
    progress.start(times.len());
    let mut images = Vec::with_capacity(times.len());
    for (i, &t) in times.iter().enumerate() {
        let image = render(&FrameParams { time: t, ..base })?;
        let path = args.out_dir.join(format!("frame_{i:04}.png"));
        image_ops::save_png(&image, &path)?;
        images.push(image);
        progress.frame_done();
    }
    progress.encoding();
    let gif = args.out_dir.join("animation.gif");
    image_ops::save_gif(&images, args.fps, &gif)?;
    progress.finish();
    eprintln!(
        "wrote {} frames to {}/frame_0000.png .. frame_{:04}.png and {}",
        images.len(),
        args.out_dir.display(),
        images.len() - 1,
        gif.display()
    );
    Ok(())
}

fn compare(image: &image::RgbaImage, params: &FrameParams, out: &Path) -> Result<(), String> {
    let reference = reference::render_frame(params);
    let skip = (params.view == View::Final).then_some(reference.outside_shadow_map.as_slice());
    let stats = image_ops::diff_masked(image, &reference.image, DELTA, skip);
    let masked = skip.map_or(0, image_ops::count);
    println!("vs CPU reference (delta {DELTA}/255, {masked} pixels outside the sun's box skipped): {stats}");
    let stem = out.with_extension("");
    let ref_path = stem.with_extension("ref.png");
    let diff_path = stem.with_extension("diff.png");
    image_ops::save_png(&reference.image, &ref_path)?;
    image_ops::save_png(&image_ops::diff_image(image, &reference.image, skip), &diff_path)?;
    eprintln!("wrote {} and {}", ref_path.display(), diff_path.display());
    Ok(())
}

/// The colour difference (out of 255) above which `--compare` counts a pixel.
pub const DELTA: u8 = 8;

