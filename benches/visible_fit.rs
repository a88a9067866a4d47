//! The light box fitted by a compute pass (`--fit visible`) against the
//! tutorial's fixed box and the box fitted on the CPU from the scene's
//! bounds (`--fit tight`, the sweep's), over an animation: per frame, the
//! shadow error against the CPU ray-cast reference and the frame time.
//!
//!     cargo bench --bench visible_fit      # docs/images/visible-fit.svg, target/perf/visible_fit.md
//!
//! Frame times are wall-clock times of a whole frame as `umbrac render`
//! draws it (for `visible`: the depth pre-pass and its read-back, the
//! dispatch and its read-back, then the frame), round-robin over the three
//! fits so that load changes hit them alike; median of the samples.

#[path = "support/mod.rs"]
mod support;

use std::fmt::Write as _;

use support::*;
use umbrac::render::exec::wgpu::WgpuExecutor;
use umbrac::render::{image_ops, reference, visible, Executor, Fit, FrameParams, SceneExecutor, Setup, ShaderSet, View};

const W: u32 = 640;
const H: u32 = 480;
/// The animation: 12 frames, half a second apart (the sun turns 0.3 rad
/// and the cube 0.35 rad between frames).
const FRAMES: usize = 12;
const STEP: f32 = 0.5;
const FITS: [Fit; 3] = [Fit::Fixed, Fit::Tight, Fit::Visible];
const WARMUP: usize = 2;
const SAMPLES: usize = 7;

struct Row {
    t: f32,
    /// Per fit: misclassified % of geometry pixels, the frame times, the
    /// box's half-extent across the light and its depth along it.
    fits: Vec<(f64, Timing, f32, f32)>,
}

fn main() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    std::fs::create_dir_all("target/perf").unwrap();
    std::fs::create_dir_all("docs/images").unwrap();
    let r: &WgpuExecutor = umbrac::render::consumers::vulkan().expect("a Vulkan adapter (lavapipe: apt-get install mesa-vulkan-drivers)");
    let opts = umbrac::Options { targets: vec![umbrac::Target::Wgsl], ..Default::default() };
    let c = umbrac::compile_source("shaders/shadow.das", SHADOW_DAS, &opts);
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let program = r.prepare_scene(&ShaderSet::from_compiled("shaders/shadow.das", c.result.as_ref().unwrap(), umbrac::Target::Wgsl).unwrap()).unwrap();
    let reduction = visible::program(umbrac::Target::Wgsl).unwrap();
    let params = |t: f32, fit: Fit| {
        let mut p = FrameParams::new(t, W, H);
        p.setup = Setup::default();
        p.setup.shadow.fit = fit;
        p
    };
    // One frame as `umbrac render` draws it.
    let frame = |p: &FrameParams| -> image::RgbaImage {
        if p.setup.shadow.fit == Fit::Visible {
            visible::render(r, &program, &reduction, p).unwrap().into_image()
        } else {
            r.draw_scene(&program, p).unwrap()
        }
    };
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let mut rows = Vec::new();
    for i in 0..FRAMES {
        let t = i as f32 * STEP;
        // The truth: the reference's shadow mask over the pixels showing geometry.
        let base = params(t, Fit::Fixed);
        let truth = reference::render_frame(&base);
        let ref_lit = reference::render(&base.with_view(View::Lit));
        let ref_mask = image_ops::shadow_mask(&truth.image, &ref_lit);
        let bg = image::Rgba([10u8, 13, 23, 255]);
        let geometry: Vec<bool> = ref_lit.pixels().map(|p| *p != bg).collect();
        let n = geometry.iter().filter(|g| **g).count().max(1);
        let gpu_lit = r.draw_scene(&program, &base.with_view(View::Lit)).unwrap();
        let mut fits = Vec::new();
        for fit in FITS {
            let p = params(t, fit);
            let mask = image_ops::shadow_mask(&frame(&p), &gpu_lit);
            let wrong = mask.iter().zip(&ref_mask).zip(&geometry).filter(|((a, b), g)| **g && a != b).count();
            let measured = if fit == Fit::Visible { visible::measure(r, &program, &reduction, &p).unwrap() } else { p };
            let proj = umbrac::render::scene::Frame::of(&measured).light_proj;
            // An orthographic projection scales x by 1 / half-extent, z by -2 / depth.
            let (half, depth) = (1.0 / proj.x_axis.x, 2.0 / proj.z_axis.z.abs());
            fits.push((wrong as f64 / n as f64 * 100.0, Timing { samples: Vec::new() }, half, depth));
        }
        for _ in 0..WARMUP {
            for fit in FITS {
                std::hint::black_box(frame(&params(t, fit)));
            }
        }
        for _ in 0..SAMPLES {
            for (k, fit) in FITS.iter().enumerate() {
                let p = params(t, *fit);
                let start = std::time::Instant::now();
                std::hint::black_box(frame(&p));
                fits[k].1.samples.push(start.elapsed());
            }
        }
        eprintln!(
            "t = {t}: {}",
            FITS.iter().zip(&fits).map(|(f, (e, tm, h, d))| format!("{} {e:.3} % {:.1} ms half {h:.2} depth {d:.2}", f.name(), tm.median() * 1e3)).collect::<Vec<_>>().join(", ")
        );
        rows.push(Row { t, fits });
    }
    let mut md = String::new();
    writeln!(
        md,
        "{} cores, load average at the start {}; {} on wgpu/Vulkan; {W}x{H}, shadow map 1024, 3x3 PCF, cube and floor in the map; t = 0 to {} in steps of {STEP} s. Error: pixels showing geometry whose lit/shadowed class differs from the CPU ray-cast reference's. Frame time: {WARMUP} warm-up and {SAMPLES} frames per fit and time, round-robin, median ms.\n",
        std::thread::available_parallelism().map_or(0, |n| n.get()),
        load.split_whitespace().take(3).collect::<Vec<_>>().join(" "),
        r.adapter_name(),
        (FRAMES - 1) as f32 * STEP
    )
    .unwrap();
    writeln!(md, "| t (s) | fixed: error %, ms | tight (CPU): error %, ms, half-extent, depth | visible (compute): error %, ms, half-extent, depth |").unwrap();
    writeln!(md, "|---|---|---|---|").unwrap();
    for row in &rows {
        let f = &row.fits;
        writeln!(
            md,
            "| {} | {:.3}, {:.2} | {:.3}, {:.2}, {:.3}, {:.3} | {:.3}, {:.2}, {:.3}, {:.3} |",
            row.t,
            f[0].0,
            f[0].1.median() * 1e3,
            f[1].0,
            f[1].1.median() * 1e3,
            f[1].2,
            f[1].3,
            f[2].0,
            f[2].1.median() * 1e3,
            f[2].2,
            f[2].3
        )
        .unwrap();
    }
    type Fitted = (f64, Timing, f32, f32);
    let mean = |k: usize, g: &dyn Fn(&Fitted) -> f64| rows.iter().map(|r| g(&r.fits[k])).sum::<f64>() / rows.len() as f64;
    writeln!(md, "\nMeans over the animation:\n").unwrap();
    for (k, fit) in FITS.iter().enumerate() {
        writeln!(
            md,
            "- {}: error {:.3} %, frame {:.2} ms, half-extent {:.3}, depth {:.3}",
            fit.name(),
            mean(k, &|f| f.0),
            mean(k, &|f| f.1.median() * 1e3),
            mean(k, &|f| f.2 as f64),
            mean(k, &|f| f.3 as f64)
        )
        .unwrap();
    }
    // Where the visible fit's time goes, at t = 2: the pre-pass with its
    // read-back, the dispatch with its upload and read-back, the frame.
    let p = params(2.0, Fit::Visible);
    let pre = umbrac::render::plan::tutorial::camera_depth_plan(&p);
    let depths = match r.run(&program, &pre).unwrap() {
        umbrac::render::Readback::Depth { depths, .. } => depths,
        _ => unreachable!("a depth target comes back as depths"),
    };
    let dispatch = visible::compute_plan(&p, &depths);
    let measured = visible::measure(r, &program, &reduction, &p).unwrap();
    let parts = [
        ("depth pre-pass + read-back", wall(15, || r.run(&program, &pre).unwrap())),
        ("dispatch (upload, reduce, read back)", wall(15, || r.run_compute(&reduction, &dispatch).unwrap())),
        ("frame with the fitted box", wall(15, || r.draw_scene(&program, &measured).unwrap())),
    ];
    writeln!(md, "\nWhere `visible`'s frame time goes (t = 2, 15 runs each, median (p10-p90) ms):\n").unwrap();
    for (what, t) in &parts {
        writeln!(md, "- {what}: {:.2} ({:.2}-{:.2})", t.median() * 1e3, t.p10() * 1e3, t.p90() * 1e3).unwrap();
    }
    plot(&rows).unwrap();
    println!("{md}");
    std::fs::write("target/perf/visible_fit.md", &md).unwrap();
}

/// Wall-clock times of `n` runs of `f` after [`WARMUP`] runs.
fn wall<T>(n: usize, mut f: impl FnMut() -> T) -> Timing {
    for _ in 0..WARMUP {
        std::hint::black_box(f());
    }
    let samples = (0..n)
        .map(|_| {
            let start = std::time::Instant::now();
            std::hint::black_box(f());
            start.elapsed()
        })
        .collect();
    Timing { samples }
}

fn plot(rows: &[Row]) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let path = "docs/images/visible-fit.svg";
    let root = SVGBackend::new(path, (820, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(320);
    let tmax = rows.last().map_or(1.0, |r| r.t as f64) + 0.25;
    let styles = [(RGBColor(200, 60, 40), "fixed +-4 box"), (RGBColor(40, 90, 200), "tight (CPU, scene bounds)"), (RGBColor(30, 160, 90), "visible (DSL compute pass)")];
    let emax = rows.iter().flat_map(|r| r.fits.iter().map(|f| f.0)).fold(0.0, f64::max) * 2.0;
    let emin = rows.iter().flat_map(|r| r.fits.iter().map(|f| f.0.max(1e-3))).fold(f64::INFINITY, f64::min) * 0.5;
    let mut chart = ChartBuilder::on(&top)
        .caption("shadow error over the animation (640x480, lavapipe)", ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(-0.25..tmax, (emin..emax).log_scale())?;
    chart.configure_mesh().x_desc("scene time (s)").y_desc("misclassified pixels (%, log)").draw()?;
    for (k, (colour, name)) in styles.iter().enumerate() {
        let colour = *colour;
        let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.t as f64, r.fits[k].0.max(1e-3))).collect();
        chart.draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))?.label(*name).legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
        // Open rings for `visible`: it lies on `tight` where they agree.
        chart.draw_series(pts.iter().map(|&p| if k == 2 { Circle::new(p, 6, colour.stroke_width(2)) } else { Circle::new(p, 3, colour.filled()) }))?;
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).position(SeriesLabelPosition::UpperRight).draw()?;
    let tmax_ms = rows.iter().flat_map(|r| r.fits.iter().map(|f| f.1.median() * 1e3)).fold(0.0, f64::max) * 1.15;
    let mut chart = ChartBuilder::on(&bottom)
        .caption("frame time (median)", ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(-0.25..tmax, 0.0..tmax_ms)?;
    chart.configure_mesh().x_desc("scene time (s)").y_desc("ms").draw()?;
    for (k, (colour, name)) in styles.iter().enumerate() {
        let colour = *colour;
        let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.t as f64, r.fits[k].1.median() * 1e3)).collect();
        chart.draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))?.label(*name).legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
        // Open rings for `visible`: it lies on `tight` where they agree.
        chart.draw_series(pts.iter().map(|&p| if k == 2 { Circle::new(p, 6, colour.stroke_width(2)) } else { Circle::new(p, 3, colour.filled()) }))?;
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).position(SeriesLabelPosition::LowerRight).draw()?;
    root.present()?;
    eprintln!("wrote {path}");
    Ok(())
}
