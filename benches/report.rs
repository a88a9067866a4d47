//! The measurements behind docs/performance.md that criterion does not make:
//!
//!     cargo bench --bench report -- scaling   # compile time vs source size, docs/images/compile-scaling.svg
//!     cargo bench --bench report -- frames    # generated vs hand-written WGSL frame time (lavapipe)
//!     cargo bench --bench report -- spirv     # SPIR-V instructions per entry point, generated vs hand
//!     cargo bench --bench report -- sweep     # shadow speed vs error, docs/images/shadow-sweep.svg
//!     cargo bench --bench report -- ab        # tutorial vs tuned and what each saving buys, interleaved
//!     cargo bench --bench report -- all
//!
//! Each prints markdown tables; they are also written to target/perf/NAME.md.
//! Frame times are wall-clock times of `the wgpu executor's `run`` (encode, submit,
//! render, read back), median of many frames after warm-up, with the 10th
//! and 90th percentiles.

#[path = "support/mod.rs"]
mod support;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use support::*;
use umbrac::render::image_ops;
use umbrac::render::reference;
use umbrac::render::exec::wgpu::{WgpuExecutor, WgpuProgram};
use umbrac::render::{hand, DepthFormat, Filter, Fit, FrameParams, SceneExecutor, Setup, ShaderSet, View};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let modes: Vec<&str> = if args.is_empty() || args.iter().any(|a| a == "all") {
        vec!["scaling", "spirv", "frames", "ab", "sweep"]
    } else {
        args.iter().map(|s| s.as_str()).collect()
    };
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    std::fs::create_dir_all("target/perf").unwrap();
    std::fs::create_dir_all("docs/images").unwrap();
    // One Vulkan device for the whole run.
    let gpu = || -> &'static WgpuExecutor { umbrac::render::consumers::vulkan().expect("a Vulkan adapter (lavapipe: apt-get install mesa-vulkan-drivers)") };
    for mode in modes {
        let md = match mode {
            "scaling" => scaling(),
            "spirv" => spirv(),
            "frames" => frames(gpu()),
            "ab" => ab(gpu()),
            "sweep" => sweep(gpu()),
            other => {
                eprintln!("unknown mode {other}: scaling, spirv, frames, ab, sweep, all");
                std::process::exit(2);
            }
        };
        println!("{md}");
        std::fs::write(format!("target/perf/{mode}.md"), &md).unwrap();
    }
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("model name")).map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string()))
        .unwrap_or_default();
    format!("{} cores ({cpu}), shared with other jobs", std::thread::available_parallelism().map_or(0, |n| n.get()))
}

// ---------------------------------------------------------------- scaling

fn scaling() -> String {
    let factors = [1usize, 2, 5, 10, 20, 35, 50, 75, 100];
    let mut rows = Vec::new();
    for &f in &factors {
        let src = scaled_source(f);
        // Fewer samples for the big ones; each sample is one compile.
        let samples = if f <= 10 { 40 } else if f <= 50 { 15 } else { 9 };
        let fe = time(2, samples, 1, || umbrac_front_end(&src));
        let all = time(2, samples, 1, || umbrac_all_targets(&src));
        eprintln!("scaling {f}x: {} bytes, front end {:.3} ms, all {:.3} ms", src.len(), fe.median() * 1e3, all.median() * 1e3);
        rows.push((f, src.len(), fe, all));
    }
    let fit = |ys: &[(f64, f64)]| {
        let n = ys.len() as f64;
        let (sx, sy) = ys.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
        let (mx, my) = (sx / n, sy / n);
        let sxy: f64 = ys.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = ys.iter().map(|p| (p.0 - mx).powi(2)).sum();
        let syy: f64 = ys.iter().map(|p| (p.1 - my).powi(2)).sum();
        let slope = sxy / sxx;
        (slope, my - slope * mx, sxy * sxy / (sxx * syy))
    };
    let fe_pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.1 as f64 / 1e3, r.2.median() * 1e3)).collect();
    let all_pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.1 as f64 / 1e3, r.3.median() * 1e3)).collect();
    let (fe_slope, fe_icpt, fe_r2) = fit(&fe_pts);
    let (all_slope, all_icpt, all_r2) = fit(&all_pts);

    let mut md = String::new();
    writeln!(md, "### Compile time vs source size\n\nMachine: {}.\n", machine()).unwrap();
    writeln!(md, "| size | bytes | front end ms (p10-p90) | all outputs ms (p10-p90) | all outputs us/KB |").unwrap();
    writeln!(md, "|---|---|---|---|---|").unwrap();
    for (f, bytes, fe, all) in &rows {
        writeln!(
            md,
            "| {f}x | {bytes} | {:.3} ({:.3}-{:.3}) | {:.3} ({:.3}-{:.3}) | {:.1} |",
            fe.median() * 1e3,
            fe.p10() * 1e3,
            fe.p90() * 1e3,
            all.median() * 1e3,
            all.p10() * 1e3,
            all.p90() * 1e3,
            all.median() * 1e6 / (*bytes as f64 / 1e3)
        )
        .unwrap();
    }
    writeln!(
        md,
        "\nLeast-squares lines: front end {fe_slope:.4} ms/KB + {fe_icpt:.3} ms (R^2 = {fe_r2:.4}); all outputs {all_slope:.4} ms/KB + {all_icpt:.3} ms (R^2 = {all_r2:.4})."
    )
    .unwrap();
    plot_scaling(&fe_pts, &all_pts, (fe_slope, fe_icpt), (all_slope, all_icpt)).unwrap();
    md
}

fn plot_scaling(fe: &[(f64, f64)], all: &[(f64, f64)], fe_line: (f64, f64), all_line: (f64, f64)) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let path = "docs/images/compile-scaling.svg";
    let root = SVGBackend::new(path, (720, 440)).into_drawing_area();
    root.fill(&WHITE)?;
    let xmax = fe.iter().chain(all).map(|p| p.0).fold(0.0, f64::max) * 1.05;
    let ymax = fe.iter().chain(all).map(|p| p.1).fold(0.0, f64::max) * 1.1;
    let mut chart = ChartBuilder::on(&root)
        .caption("umbrac compile time vs source size (1x..100x shadow.das)", ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(0.0..xmax, 0.0..ymax)?;
    chart.configure_mesh().x_desc("source size (KB)").y_desc("median thread CPU time (ms)").draw()?;
    for (pts, line, colour, name) in [(all, all_line, RED, "all 10 outputs + reflection"), (fe, fe_line, BLUE, "front end (2 validated modules)")] {
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, colour.filled())))?.label(name).legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
        chart.draw_series(LineSeries::new([(0.0, line.1), (xmax, line.1 + line.0 * xmax)], colour.mix(0.5)))?;
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.8)).border_style(BLACK).position(SeriesLabelPosition::UpperLeft).draw()?;
    root.present()?;
    eprintln!("wrote {path}");
    Ok(())
}

// ---------------------------------------------------------------- SPIR-V

/// Instructions of a SPIR-V module: (total, inside function bodies).
fn count_spirv(words: &[u32]) -> (usize, usize) {
    let (mut total, mut body, mut inside) = (0, 0, false);
    let mut i = 5;
    while i < words.len() {
        let op = words[i] & 0xffff;
        let len = (words[i] >> 16).max(1) as usize;
        total += 1;
        match op {
            54 => inside = true, // OpFunction
            56 => {
                inside = false; // OpFunctionEnd
                body += 1;
            }
            _ if inside => body += 1,
            _ => {}
        }
        i += len;
    }
    (total, body)
}

fn spv_for_entry(module: &naga::Module, info: &naga::valid::ModuleInfo, entry: &str, stage: naga::ShaderStage) -> Vec<u32> {
    let options = umbrac::emit::spirv::options(module);
    let pipeline = naga::back::spv::PipelineOptions { shader_stage: stage, entry_point: entry.to_string() };
    naga::back::spv::write_vec(module, info, &options, Some(&pipeline)).expect("SPIR-V")
}

fn spirv() -> String {
    let lowered = umbrac_all_modules(SHADOW_DAS);
    let (hand_module, hand_info) = naga_front_end(hand::WGSL);
    let compiled = umbrac_all_targets(SHADOW_DAS);
    let mut md = String::new();
    writeln!(md, "### SPIR-V instructions per entry point\n").unwrap();
    writeln!(md, "naga's SPIR-V backend with umbrac's writer options, one module per entry point (`PipelineOptions`), for umbrac's GPU module of shaders/shadow.das and for the hand-written shaders/hand/shadow.wgsl parsed by naga.\n").unwrap();
    writeln!(md, "| entry point | umbrac: all / in functions | hand: all / in functions | ratio (in functions) |").unwrap();
    writeln!(md, "|---|---|---|---|").unwrap();
    for ep in &lowered.gpu.entry_points {
        let a = count_spirv(&spv_for_entry(&lowered.gpu, &lowered.gpu_info, &ep.name, ep.stage));
        let b = count_spirv(&spv_for_entry(&hand_module, &hand_info, &ep.name, ep.stage));
        writeln!(md, "| {} | {} / {} | {} / {} | {:.2} |", ep.name, a.0, a.1, b.0, b.1, a.1 as f64 / b.1 as f64).unwrap();
    }
    let shipped = compiled.result.as_ref().unwrap().artifact("shadow.spv").unwrap();
    let words: Vec<u32> = shipped.contents.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    let hand_all = naga::back::spv::write_vec(&hand_module, &hand_info, &umbrac::emit::spirv::options(&hand_module), None).unwrap();
    let (a, b) = (count_spirv(&words), count_spirv(&hand_all));
    writeln!(md, "| whole module (shipped `shadow.spv`) | {} / {} | {} / {} | {:.2} |", a.0, a.1, b.0, b.1, a.1 as f64 / b.1 as f64).unwrap();
    md
}

// ---------------------------------------------------------------- frames

const FW: u32 = 640;
const FH: u32 = 480;

fn compiled_set(defines: Vec<(String, Option<String>)>) -> ShaderSet {
    let opts = umbrac::Options { targets: vec![umbrac::Target::Wgsl], defines, ..Default::default() };
    let c = umbrac::compile_source("shaders/shadow.das", SHADOW_DAS, &opts);
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    ShaderSet::from_compiled("shaders/shadow.das", c.result.as_ref().unwrap(), umbrac::Target::Wgsl).unwrap()
}

/// Frame times of several (program, params) pairs, measured round-robin so
/// that load changes on the shared machine hit all of them alike.
fn interleaved(r: &WgpuExecutor, cases: &[(&WgpuProgram, FrameParams)], warmup: usize, frames: usize) -> Vec<Timing> {
    for _ in 0..warmup {
        for (p, params) in cases {
            r.draw_scene(p, params).unwrap();
        }
    }
    let mut samples = vec![Vec::with_capacity(frames); cases.len()];
    for _ in 0..frames {
        for (i, (p, params)) in cases.iter().enumerate() {
            let t = std::time::Instant::now();
            std::hint::black_box(r.draw_scene(p, params).unwrap());
            samples[i].push(t.elapsed());
        }
    }
    samples.into_iter().map(|samples| Timing { samples }).collect()
}

fn ms(t: &Timing) -> String {
    format!("{:.2} ({:.2}-{:.2})", t.median() * 1e3, t.p10() * 1e3, t.p90() * 1e3)
}

fn frames(r: &WgpuExecutor) -> String {
    let generated = r.prepare_scene(&compiled_set(Vec::new())).unwrap();
    let handwritten = r.prepare_scene(&hand::shader_set()).unwrap();
    let mut md = String::new();
    writeln!(md, "### Frame time: generated vs hand-written WGSL\n\n{} on {}; {FW}x{FH}, shadow map 1024, t = 2; 10 warm-up rounds, 120 frames each, interleaved. Median (p10-p90), ms; on a shared machine the 10th percentile is the steadiest estimate of the undisturbed frame.\n", machine(), r.adapter_name()).unwrap();
    writeln!(md, "| run | umbrac WGSL | hand WGSL | ratio of medians | ratio of p10 |").unwrap();
    writeln!(md, "|---|---|---|---|---|").unwrap();
    let params = FrameParams::new(2.0, FW, FH);
    for run in 1..=3 {
        let t = interleaved(r, &[(&generated, params), (&handwritten, params)], 10, 120);
        writeln!(md, "| {run} | {} | {} | {:.3} | {:.3} |", ms(&t[0]), ms(&t[1]), t[0].median() / t[1].median(), t[0].p10() / t[1].p10()).unwrap();
    }
    md
}

// ---------------------------------------------------------------- sweep

const SWEEP_TIMES: [f32; 4] = [0.5, 2.0, 4.0, 6.0];

/// Per-time data shared by every configuration: the reference and the GPU's
/// own unshadowed image (an empty shadow map: every compare passes,
/// whatever the filter or fit).
struct Truth {
    params: FrameParams,
    reference: reference::RefFrame,
    ref_mask: Vec<bool>,
    gpu_lit: image::RgbaImage,
    geometry: Vec<bool>,
}

fn truths(r: &WgpuExecutor, base: &WgpuProgram, sw: u32, sh: u32) -> Vec<Truth> {
    SWEEP_TIMES
        .iter()
        .map(|&t| {
            let params = FrameParams::new(t, sw, sh);
            let reference = reference::render_frame(&params);
            let ref_lit = reference::render(&params.with_view(View::Lit));
            let ref_mask = image_ops::shadow_mask(&reference.image, &ref_lit);
            let gpu_lit = r.draw_scene(base, &params.with_view(View::Lit)).unwrap();
            let bg = image::Rgba([10u8, 13, 23, 255]);
            let geometry = ref_lit.pixels().map(|p| *p != bg).collect();
            Truth { params, reference, ref_mask, gpu_lit, geometry }
        })
        .collect()
}

/// Shadow error of a configuration: (fraction of geometry pixels whose
/// lit/shadowed class differs from the reference; the same counting only
/// pixels inside the tutorial's +-4 light box; mean colour error in 1/255
/// over geometry pixels), averaged over the sweep's times.
fn shadow_error(r: &WgpuExecutor, program: &WgpuProgram, setup: Setup, shadow_size: u32, truths: &[Truth]) -> (f64, f64, f64) {
    let (mut mis, mut mis_in, mut col) = (0.0, 0.0, 0.0);
    for tr in truths {
        let mut p = tr.params;
        p.setup = setup;
        p.shadow_size = shadow_size;
        let img = r.draw_scene(program, &p).unwrap();
        let mask = image_ops::shadow_mask(&img, &tr.gpu_lit);
        let skip: Vec<bool> = tr.geometry.iter().map(|g| !g).collect();
        let n = tr.geometry.iter().filter(|g| **g).count().max(1);
        let wrong = mask.iter().zip(&tr.ref_mask).zip(&tr.geometry).filter(|((a, b), g)| **g && a != b).count();
        mis += wrong as f64 / n as f64;
        let inside = |i: usize| tr.geometry[i] && !tr.reference.outside_shadow_map[i];
        let n_in = (0..mask.len()).filter(|&i| inside(i)).count().max(1);
        let wrong_in = (0..mask.len()).filter(|&i| inside(i) && mask[i] != tr.ref_mask[i]).count();
        mis_in += wrong_in as f64 / n_in as f64;
        col += image_ops::diff_masked(&img, &tr.reference.image, 0, Some(&skip)).mean;
    }
    let k = truths.len() as f64;
    (mis / k, mis_in / k, col / k)
}

#[derive(Clone, Copy)]
struct Config {
    size: u32,
    setup: Setup,
}

impl Config {
    fn label(&self) -> String {
        let s = &self.setup.shadow;
        format!("{} {} {} {}{}", self.size, s.filter.name(), s.fit.name(), s.depth.name(), if s.casters_only { " casters" } else { "" })
    }
}

struct Row {
    cfg: Config,
    time: Timing,
    mis: f64,
    mis_in: f64,
    col: f64,
}

fn with(size: u32, filter: Filter, fit: Fit, depth: DepthFormat, casters_only: bool) -> Config {
    let mut setup = Setup::default();
    setup.shadow.filter = filter;
    setup.shadow.fit = fit;
    setup.shadow.depth = depth;
    setup.shadow.casters_only = casters_only;
    Config { size, setup }
}

fn sweep(r: &WgpuExecutor) -> String {
    let mut configs = Vec::new();
    for size in [256, 512, 1024, 2048, 4096] {
        for filter in Filter::ALL {
            for fit in [Fit::Fixed, Fit::Tight] {
                for casters in [false, true] {
                    configs.push(with(size, filter, fit, DepthFormat::Depth32Float, casters));
                }
            }
        }
    }
    for depth in [DepthFormat::Depth16, DepthFormat::Depth24Plus] {
        for (fit, casters) in [(Fit::Fixed, false), (Fit::Tight, true)] {
            for size in [512, 1024, 2048] {
                configs.push(with(size, Filter::Pcf3x3, fit, depth, casters));
            }
        }
    }
    let mut programs: BTreeMap<(u32, u32), WgpuProgram> = BTreeMap::new();
    let base = r.prepare_scene(&compiled_set(Vec::new())).unwrap();
    let truths = truths(r, &base, FW, FH);
    let mut rows = Vec::new();
    for (i, cfg) in configs.iter().enumerate() {
        let key = (cfg.setup.shadow.filter.radius(), cfg.size);
        let program = programs.entry(key).or_insert_with(|| r.prepare_scene(&compiled_set(cfg.setup.defines(cfg.size))).unwrap());
        let (mis, mis_in, col) = shadow_error(r, program, cfg.setup, cfg.size, &truths);
        let mut p = FrameParams::new(2.0, FW, FH);
        p.setup = cfg.setup;
        p.shadow_size = cfg.size;
        let time = interleaved(r, &[(program, p)], 3, 15).remove(0);
        eprintln!("[{}/{}] {}: {:.2} ms, misclassified {:.3}%, colour {:.3}", i + 1, configs.len(), cfg.label(), time.median() * 1e3, mis * 100.0, col);
        rows.push(Row { cfg: *cfg, time, mis, mis_in, col });
    }
    let tutorial = rows.iter().find(|r| r.cfg.size == 1024 && r.cfg.setup == Setup::default()).unwrap();
    let mut md = String::new();
    writeln!(md, "### Shadow speed vs error\n\n{} on {}; {FW}x{FH}. Error: against the CPU reference at t = {SWEEP_TIMES:?} (mean over the four), over every pixel showing geometry (no pixel skipped). Frame time: t = 2, 3 warm-up, 15 frames, median (p10-p90) ms.\n", machine(), r.adapter_name()).unwrap();
    writeln!(md, "| shadow map | filter | fit | depth | casters only | frame ms | misclassified % | inside +-4 box % | mean colour error /255 |").unwrap();
    writeln!(md, "|---|---|---|---|---|---|---|---|---|").unwrap();
    for row in &rows {
        let s = &row.cfg.setup.shadow;
        let mark = if std::ptr::eq(row, tutorial) { " **(tutorial)**" } else { "" };
        writeln!(
            md,
            "| {}{mark} | {} | {} | {} | {} | {} | {:.3} | {:.3} | {:.3} |",
            row.cfg.size,
            s.filter.name(),
            s.fit.name(),
            s.depth.name(),
            if s.casters_only { "yes" } else { "no" },
            ms(&row.time),
            row.mis * 100.0,
            row.mis_in * 100.0,
            row.col
        )
        .unwrap();
    }
    // Candidates: at most half the tutorial's misclassification and colour
    // error, and a median frame time no higher.
    let mut good: Vec<&Row> = rows
        .iter()
        .filter(|r| r.mis <= tutorial.mis * 0.5 && r.col <= tutorial.col * 0.5 && r.time.median() <= tutorial.time.median())
        .collect();
    good.sort_by(|a, b| a.mis.partial_cmp(&b.mis).unwrap());
    writeln!(md, "\nTutorial: {:.3} % misclassified, colour error {:.3}, {} ms. Configurations with at most half of both errors and a median frame time no higher (sweep timings, not interleaved; see the A/B table):\n", tutorial.mis * 100.0, tutorial.col, ms(&tutorial.time)).unwrap();
    for g in good.iter().take(12) {
        writeln!(md, "- {}: {:.3} %, {:.3}, {} ms", g.cfg.label(), g.mis * 100.0, g.col, ms(&g.time)).unwrap();
    }
    plot_sweep(&rows, tutorial).unwrap();
    md
}

fn plot_sweep(rows: &[Row], tutorial: &Row) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let path = "docs/images/shadow-sweep.svg";
    let root = SVGBackend::new(path, (820, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let xmax = rows.iter().map(|r| r.time.median() * 1e3).fold(0.0, f64::max) * 1.2;
    let xmin = rows.iter().map(|r| r.time.median() * 1e3).fold(f64::INFINITY, f64::min) * 0.8;
    let ymax = rows.iter().map(|r| r.mis * 100.0).fold(0.0, f64::max) * 1.5;
    let ymin = rows.iter().map(|r| (r.mis * 100.0).max(1e-3)).fold(f64::INFINITY, f64::min) * 0.7;
    let mut chart = ChartBuilder::on(&root)
        .caption("shadow error vs frame time (640x480, lavapipe)", ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d((xmin..xmax).log_scale(), (ymin..ymax).log_scale())?;
    chart.configure_mesh().x_desc("frame time, median (ms, log)").y_desc("pixels misclassified lit/shadowed (%, log)").draw()?;
    let groups = [
        (Fit::Fixed, false, RGBColor(200, 60, 40), "fixed box, cube + floor in map"),
        (Fit::Fixed, true, RGBColor(240, 150, 40), "fixed box, casters only"),
        (Fit::Tight, false, RGBColor(40, 90, 200), "tight box, cube + floor in map"),
        (Fit::Tight, true, RGBColor(30, 160, 90), "tight box, casters only"),
    ];
    for (fit, casters, colour, name) in groups {
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.cfg.setup.shadow.fit == fit && r.cfg.setup.shadow.casters_only == casters)
            .map(|r| (r.time.median() * 1e3, (r.mis * 100.0).max(1e-3)))
            .collect();
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, colour.filled())))?.label(name).legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
    }
    let t = (tutorial.time.median() * 1e3, tutorial.mis.max(1e-5) * 100.0);
    chart.draw_series([Cross::new(t, 9, BLACK.stroke_width(2))])?.label("tutorial (1024, 3x3, fixed)").legend(|(x, y)| Cross::new((x + 10, y), 5, BLACK.stroke_width(2)));
    if let Some(tuned) = rows.iter().find(|r| r.cfg.size == Setup::TUNED_SHADOW_SIZE && r.cfg.setup == Setup::tuned()) {
        let p = (tuned.time.median() * 1e3, (tuned.mis * 100.0).max(1e-3));
        chart.draw_series([TriangleMarker::new(p, 9, BLACK.filled())])?.label("tuned (--quality tuned)").legend(|(x, y)| TriangleMarker::new((x + 10, y), 5, BLACK.filled()));
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).position(SeriesLabelPosition::UpperRight).draw()?;
    root.present()?;
    eprintln!("wrote {path}");
    Ok(())
}

// ---------------------------------------------------------------- A/B

fn ab(r: &WgpuExecutor) -> String {
    let tutorial_prog = r.prepare_scene(&compiled_set(Vec::new())).unwrap();
    let tuned = Setup::tuned();
    let size = Setup::TUNED_SHADOW_SIZE;
    let tuned_prog = r.prepare_scene(&compiled_set(tuned.defines(size))).unwrap();
    let base = FrameParams::new(2.0, FW, FH);
    let variants: Vec<(&str, Setup)> = vec![
        ("tutorial", Setup::default()),
        ("tutorial + casters only", { let mut s = Setup::default(); s.shadow.casters_only = true; s }),
        ("tutorial + tight fit", { let mut s = Setup::default(); s.shadow.fit = Fit::Tight; s }),
        ("tutorial + tight fit + casters only", { let mut s = Setup::default(); s.shadow.fit = Fit::Tight; s.shadow.casters_only = true; s }),
        ("tuned (tight fit + casters only + 2x2 filter)", tuned),
    ];
    let cases: Vec<(&WgpuProgram, FrameParams)> = variants
        .iter()
        .map(|(_, s)| {
            let mut p = base;
            p.setup = *s;
            p.shadow_size = size;
            (if *s == tuned { &tuned_prog } else { &tutorial_prog }, p)
        })
        .collect();
    let truths = truths(r, &tutorial_prog, FW, FH);
    let mut md = String::new();
    writeln!(md, "### Tutorial vs tuned, and what each part saves\n\n{} on {}; {FW}x{FH}, shadow map {size}, t = 2; 10 warm-up rounds, 60 frames each, interleaved. Errors as in the sweep.\n", machine(), r.adapter_name()).unwrap();
    writeln!(md, "| configuration | frame ms | vs tutorial | misclassified % | inside +-4 box % | mean colour error /255 |").unwrap();
    writeln!(md, "|---|---|---|---|---|---|").unwrap();
    let times = interleaved(r, &cases, 10, 60);
    for (i, (name, s)) in variants.iter().enumerate() {
        let (mis, mis_in, col) = shadow_error(r, cases[i].0, *s, size, &truths);
        writeln!(md, "| {name} | {} | {:.3} | {:.3} | {:.3} | {:.3} |", ms(&times[i]), times[i].median() / times[0].median(), mis * 100.0, mis_in * 100.0, col).unwrap();
    }
    md
}

#[allow(dead_code)]
fn exists(p: &str) -> bool {
    Path::new(p).exists()
}
