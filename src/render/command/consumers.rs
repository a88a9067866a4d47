//! `umbrac render --backend gl330|gles300` and `--compare-backends`.

use std::path::Path;

use super::program::compile_program;
use super::RenderOptions;
use crate::render::consumers::{self, Consumer, Programs, Status};
use crate::render::image_ops;
use crate::render::scene::FrameParams;

/// The difference (out of 255) above which the comparison counts a pixel.
pub const DELTA: u8 = 8;

fn compile(file: Option<&Path>, daslang_root: Option<&Path>) -> Result<(String, crate::Compiled), String> {
    if let Some(ext @ ("wgsl" | "spv")) = file.and_then(|p| p.extension()).and_then(|e| e.to_str()) {
        return Err(format!("--compare-backends runs every target of a .das program, not a .{ext} file"));
    }
    match compile_program(file, &crate::Options { daslang_root: daslang_root.map(Path::to_path_buf), ..Default::default() }) {
        (name, Some(compiled)) => Ok((name, compiled)),
        (name, None) => Err(format!("{name} did not compile")),
    }
}

pub(super) fn compare_backends(args: &RenderOptions, params: FrameParams) -> Result<(), String> {
    let (name, compiled) = compile(args.file.as_deref(), args.daslang_root.as_deref())?;
    let programs = Programs::from_compiled(&name, &compiled)?;
    eprintln!(
        "{name} at t = {}, {}x{}, shadow map {}, view {}:",
        params.time,
        params.width,
        params.height,
        params.shadow_size,
        params.view.name()
    );
    let stem = args.out.with_extension("");
    let mut results = Vec::new();
    let mut failed = Vec::new();
    for c in Consumer::ALL {
        let status = consumers::render(c, &programs, &params);
        match &status {
            Status::Rendered { image, device, ms } => {
                let path = stem.with_extension(format!("{}.png", c.name()));
                image_ops::save_png(image, &path)?;
                println!("  {:<13} {} on {device}: {ms:.0} ms, {}", c.name(), c.description(), path.display());
            }
            Status::Unavailable { why, install } => {
                println!("  {:<13} unavailable: {why}\n  {:<13} to install: {install}", c.name(), "");
            }
            Status::Failed(e) => {
                println!("  {:<13} FAILED: {e}", c.name());
                failed.push(c.name());
            }
        }
        results.push((c, status));
    }
    // Where each differs from the first consumer that rendered (red: the
    // difference x4), to look at.
    let first = results.iter().find_map(|(c, s)| s.image().map(|i| (*c, i.clone())));
    if let Some((base, base_image)) = first {
        for (c, s) in results.iter().filter(|(c, _)| *c != base) {
            if let Some(image) = s.image() {
                let path = stem.with_extension(format!("{}.diff.png", c.name()));
                image_ops::save_png(&image_ops::diff_image(&base_image, image, None), &path)?;
            }
        }
        eprintln!("wrote OUT.CONSUMER.diff.png: each consumer's difference from {}", base.name());
    }
    let all: Vec<(&str, &image::RgbaImage)> = results.iter().filter_map(|(c, s)| Some((c.name(), s.image()?))).collect();
    let strip = stem.with_extension("all.png");
    image_ops::save_png(&image_ops::labelled_strip(&all), &strip)?;
    eprintln!("wrote {}: every rendered image, left to right in the order above, each under its consumer's name", strip.display());
    let pairs = consumers::pairwise(&results, &params, DELTA);
    println!();
    print!("{}", consumers::table(&pairs, DELTA));
    if pairs.iter().any(|p| p.masked) {
        let skipped = params.width as usize * params.height as usize - pairs.iter().find(|p| p.masked).map_or(0, |p| p.stats.pixels);
        println!("\n* pixels outside the sun's box skipped ({skipped}): the shadow map has no data there (docs/runner.md)");
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(format!("{} failed", failed.join(", ")))
    }
}
