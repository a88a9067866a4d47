//! `umbrac render FILE` for any program: drawn from a scene file
//! (`--scene FILE.toml`), or from the scene inferred for it (one of its
//! programs: `--program VS[:FS]`), on one consumer or, with
//! `--compare-backends`, on every one with the same inputs.

use std::path::Path;
use std::time::Instant;

use image::RgbaImage;

use super::frames::{frame_times, write_frames};
use super::program::compile_program;
use super::{Progress, RenderOptions};
use crate::render::consumers::{self, Consumer, Programs, Status};
use crate::render::exec::{ExecError, Executor};
use crate::render::image_ops::{self, DiffStats};
use crate::render::plan::scene_file::{FrameInputs, ScenePlanner};
use crate::render::program::ShaderSet;
use crate::render::scene::FrameParams;
use crate::scene::{self, Scene};
use crate::Target;

/// The difference (out of 255, any channel) above which `--compare-backends`
/// counts a pixel as differing.
pub const DELTA: u8 = 8;

/// Whether `umbrac render` draws this run from a scene (a file, a chosen
/// program, or a .das program that is not a shadow scene's).
pub(super) fn wants_scene(opts: &RenderOptions) -> bool {
    if opts.scene_file.is_some() || opts.program.is_some() {
        return true;
    }
    let Some(file) = opts.file.as_deref().filter(|f| f.extension().is_some_and(|x| x == "das")) else {
        return false;
    };
    let c = crate::compile_file(file, &crate::Options { daslang_root: opts.daslang_root.clone(), ..Default::default() });
    // A program that does not compile goes the shadow scene's way, which
    // prints its diagnostics.
    match c.result.as_ref().filter(|_| !c.has_errors()) {
        Some(compiled) => !is_shadow_scene(&compiled.reflection),
        None => false,
    }
}

/// A program the shadow scenes draw: the tutorial's entry points, or
/// dasVulkan's shadow rung's.
fn is_shadow_scene(r: &crate::Reflection) -> bool {
    use crate::render::scene as s;
    let has = |n: &str| r.entry_points.iter().any(|e| e.name == n);
    (has(s::SHADOW_VS) && has(s::MAIN_VS) && has(s::MAIN_FS)) || has(crate::render::plan::vk_shadow::MAIN_VS)
}

/// The scene of `compiled`: the scene file's, or the inferred one of the
/// chosen (else the first) program.
pub fn scene_for(opts: &RenderOptions, name: &str, r: &crate::Reflection) -> Result<ScenePlanner, String> {
    if let Some(path) = &opts.scene_file {
        let text = std::fs::read_to_string(path).map_err(|e| format!("reading {}: {e}", path.display()))?;
        let file = path.display().to_string();
        let scene = Scene::parse(&file, &text)?;
        // What does not fit the program is placed in the file too.
        let label = format!("{name} with {file}");
        return ScenePlanner::new(&label, scene, r, path.parent())
            .map_err(|e| scene::locate(&file, &text, e.strip_prefix(&format!("{label}: ")).unwrap_or(&e)));
    }
    let scene = match opts.program.as_deref() {
        None => Scene::infer(r),
        Some(p) => {
            let (vs, fs) = match p.split_once(':') {
                Some((v, f)) => (v.to_string(), f.to_string()),
                None => scene::infer::programs(r).into_iter().find(|(v, _)| v == p).ok_or_else(|| {
                    let all: Vec<String> = scene::infer::programs(r).iter().map(|(v, f)| format!("{v}:{f}")).collect();
                    format!("--program {p}: {name} has no program with that vertex entry point (its programs: {})", all.join(", "))
                })?,
            };
            Scene::infer_program(r, &vs, &fs)
        }
    }
    .map_err(|e| format!("{name}: {e}"))?;
    ScenePlanner::new(name, scene, r, None)
}

fn compile(opts: &RenderOptions, targets: Vec<Target>) -> Result<(String, crate::Compiled), String> {
    if let Some(ext @ ("wgsl" | "spv")) = opts.file.as_deref().and_then(|p| p.extension()).and_then(|e| e.to_str()) {
        return Err(format!("a scene draws a .das program compiled in process, not a .{ext} file"));
    }
    let o = crate::Options { targets, daslang_root: opts.daslang_root.clone(), ..Default::default() };
    let (name, compiled) = match compile_program(opts.file.as_deref(), &o) {
        (name, Some(c)) => (name, c),
        (name, None) => return Err(format!("{name} did not compile")),
    };
    // A lone fragment program: drawn with a full-screen vertex program appended.
    let (Some(vs), Some(file)) = (scene::infer::fullscreen_vertex(&compiled.reflection), opts.file.as_deref()) else {
        return Ok((name, compiled));
    };
    let text = std::fs::read_to_string(file).map_err(|e| format!("reading {}: {e}", file.display()))?;
    let c = crate::compile_source(&name, &format!("{text}{vs}"), &o);
    if c.has_errors() {
        return Err(format!("{name} with a full-screen vertex program appended did not compile:\n{}", c.render_diagnostics()));
    }
    c.result.map(|compiled| (name.clone(), compiled)).ok_or_else(|| format!("{name}: no outputs"))
}

fn inputs(p: &FrameParams, opts: &RenderOptions) -> FrameInputs {
    let frame = ((p.time - opts.time) * opts.fps).round().max(0.0) as u32;
    FrameInputs { time: p.time, frame, width: p.width, height: p.height }
}

/// One consumer: a PNG, or an animation.
pub(super) fn run(opts: &RenderOptions, progress: &mut dyn Progress) -> Result<(), String> {
    if opts.compare_backends {
        return compare_backends(opts);
    }
    if opts.reference || opts.compare {
        return Err("the CPU reference draws the shadow scenes only: a scene's program has none (--compare-backends compares the consumers)".into());
    }
    let target = opts.consumer.target().ok_or_else(|| format!("{} runs no compiled program", opts.consumer.name()))?;
    let (name, compiled) = compile(opts, vec![target])?;
    let planner = scene_for(opts, &name, &compiled.reflection)?;
    let set = ShaderSet::from_compiled(&name, &compiled, target)?;
    let c = opts.consumer;
    match c {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => draw(consumers::vulkan().map_err(|e| e.to_string())?, &set, &planner, opts, progress),
        Consumer::WgpuGl => draw(consumers::wgpu_gl().map_err(|e| e.to_string())?, &set, &planner, opts, progress),
        #[cfg(feature = "gl")]
        Consumer::Gl330 | Consumer::Gles300 | Consumer::Gl430 => {
            let _ = consumers::wgpu_gl();
            draw(&crate::render::exec::gl::GlExecutor::new(c).map_err(|e| e.to_string())?, &set, &planner, opts, progress)
        }
        Consumer::WebGl2 => draw(&crate::render::exec::webgl::WebGl::find().map_err(|e| e.to_string())?, &set, &planner, opts, progress),
        other => Err(format!("{} cannot draw here ({})", other.name(), other.description())),
    }
}

fn draw<E: Executor>(e: &E, set: &ShaderSet, planner: &ScenePlanner, opts: &RenderOptions, progress: &mut dyn Progress) -> Result<(), String> {
    let (width, height) = opts.size;
    let params = FrameParams::new(opts.time, width, height);
    let prepared = e.prepare(set, &planner.plan(&inputs(&params, opts))?).map_err(|e| e.to_string())?;
    eprintln!("rendering {} ({}) on {}: {}", planner.label, set.target.name(), opts.consumer.name(), e.device_name());
    let times = frame_times(opts);
    write_frames(
        opts,
        &times,
        |p| {
            let plan = planner.plan(&inputs(p, opts))?;
            e.run(&prepared, &plan).map(|r| r.into_image()).map_err(|e: ExecError| e.to_string())
        },
        params,
        progress,
    )
}

/// What every consumer drew of one scene frame.
pub struct Comparison {
    pub results: Vec<(Consumer, Status)>,
    /// Every pair of drawn images, compared with [`DELTA`].
    pub pairs: Vec<(Consumer, Consumer, DiffStats)>,
}

/// Draws `planner`'s frame `f` with `programs` on every consumer that runs
/// compiled programs (every one but the CPU reference), the same plan on
/// each, and compares every pair.
pub fn compare(programs: &Programs, planner: &ScenePlanner, f: &FrameInputs) -> Result<Comparison, String> {
    Ok(compare_many(&[(programs, planner, *f)])?.pop().expect("one job, one comparison"))
}

/// [`compare`] for several frames, with every WebGL2 frame drawn in one
/// browser (its start is most of a small frame's time).
pub fn compare_many(jobs: &[(&Programs, &ScenePlanner, FrameInputs)]) -> Result<Vec<Comparison>, String> {
    let plans = jobs.iter().map(|(_, planner, f)| planner.plan(f)).collect::<Result<Vec<_>, String>>()?;
    let mut results: Vec<Vec<(Consumer, Status)>> = jobs.iter().map(|_| Vec::new()).collect();
    for c in Consumer::ALL {
        if c == Consumer::WebGl2 {
            let webgl = match crate::render::exec::webgl::WebGl::find() {
                Ok(w) => w,
                Err(e) => {
                    results.iter_mut().for_each(|r| r.push((c, e.clone().into())));
                    continue;
                }
            };
            let started = Instant::now();
            let batch: Vec<(&ShaderSet, &crate::render::plan::FramePlan)> =
                jobs.iter().zip(&plans).map(|((p, _, _), plan)| (p.for_consumer(c).expect("WebGL2 runs GLSL ES"), plan)).collect();
            let outs = webgl.run_batch(&batch);
            let ms = started.elapsed().as_secs_f64() * 1e3;
            for (r, out) in results.iter_mut().zip(outs) {
                let status = match out {
                    Ok(readback) => Status::Rendered { image: readback.into_image(), device: webgl.device_name(), ms: ms / jobs.len() as f64 },
                    Err(e) => e.into(),
                };
                r.push((c, status));
            }
            continue;
        }
        for (((programs, _, _), plan), r) in jobs.iter().zip(&plans).zip(results.iter_mut()) {
            let Some(set) = programs.for_consumer(c) else { continue };
            let started = Instant::now();
            let status = match consumers::run(c, set, plan) {
                Ok((out, device)) => Status::Rendered { image: out.into_image(), device, ms: started.elapsed().as_secs_f64() * 1e3 },
                Err(e) => e.into(),
            };
            r.push((c, status));
        }
    }
    Ok(results
        .into_iter()
        .map(|results| {
            let mut pairs = Vec::new();
            for (i, (a, sa)) in results.iter().enumerate() {
                for (b, sb) in &results[i + 1..] {
                    if let (Some(ia), Some(ib)) = (sa.image(), sb.image()) {
                        pairs.push((*a, *b, image_ops::diff_masked(ia, ib, DELTA, None)));
                    }
                }
            }
            Comparison { results, pairs }
        })
        .collect())
}

fn compare_backends(opts: &RenderOptions) -> Result<(), String> {
    let (name, compiled) = compile(opts, vec![Target::Wgsl, Target::Spirv, Target::Glsl330, Target::Gles300])?;
    let planner = scene_for(opts, &name, &compiled.reflection)?;
    let programs = Programs::from_compiled(&name, &compiled)?;
    let (width, height) = opts.size;
    eprintln!("{} at t = {}, {width}x{height}:", planner.label, opts.time);
    let cmp = compare(&programs, &planner, &FrameInputs { time: opts.time, frame: 0, width, height })?;
    let stem = opts.out.with_extension("");
    let mut failed = Vec::new();
    for (c, status) in &cmp.results {
        match status {
            Status::Rendered { image, device, ms } => {
                let path = stem.with_extension(format!("{}.png", c.name()));
                image_ops::save_png(image, &path)?;
                println!("  {:<13} {} on {device}: {ms:.0} ms, {}", c.name(), c.description(), path.display());
            }
            Status::Unavailable { why, install } => println!("  {:<13} unavailable: {why}\n  {:<13} to install: {install}", c.name(), ""),
            Status::Failed(e) => {
                println!("  {:<13} FAILED: {e}", c.name());
                failed.push(c.name());
            }
        }
    }
    let drawn: Vec<(&str, &RgbaImage)> = cmp.results.iter().filter_map(|(c, s)| Some((c.name(), s.image()?))).collect();
    if let Some((base, base_image)) = drawn.first() {
        for (c, image) in &drawn[1..] {
            image_ops::save_png(&image_ops::diff_image(base_image, image, None), &stem.with_extension(format!("{c}.diff.png")))?;
        }
        eprintln!("wrote OUT.CONSUMER.diff.png: each consumer's difference from {base}");
        let strip = stem.with_extension("all.png");
        image_ops::save_png(&image_ops::labelled_strip(&drawn), &strip)?;
        eprintln!("wrote {}: every drawn image, left to right in the order above", strip.display());
    }
    println!();
    print!("{}", table(&cmp.pairs));
    if failed.is_empty() {
        Ok(())
    } else {
        Err(format!("{} failed", failed.join(", ")))
    }
}

/// The pairs as a Markdown table.
pub fn table(pairs: &[(Consumer, Consumer, DiffStats)]) -> String {
    let mut s = format!("| pair | pixels differing by more than {DELTA}/255 | max | mean |\n|---|---|---|---|\n");
    for (a, b, d) in pairs {
        s.push_str(&format!("| {} vs {} | {} of {} ({:.3} %) | {} | {:.3} |\n", a.name(), b.name(), d.over, d.pixels, 100.0 * d.fraction_over, d.max, d.mean));
    }
    s
}

/// Where `--watch` would look, for a scene run: the scene file too.
pub fn scene_path(opts: &RenderOptions) -> Option<&Path> {
    opts.scene_file.as_deref()
}
