//! Compiling at scale: the 256 variants of
//! shaders/programs/shadow_variants.das (8 independent #ifdef axes,
//! shadow_variants.toml), in one run: `cargo bench --bench variants`.
//!
//! - cold `umbrac compile --variants` with `--jobs 1, 2, 3, 4`, interleaved
//!   round by round (a cache and output directory never used before, each
//!   time; the disk synced first): parallel efficiency,
//!   and the plot of variants per second against jobs
//!   (docs/images/variants-jobs.svg); and `--jobs 2` right after deleting
//!   the previous round's files;
//! - what a user does without `--variants`: one `umbrac compile -D ...`
//!   process per variant in a shell loop;
//! - warm: the same command again, into the directory of the previous run
//!   (what a build system reruns: its first rerun, and the median of the
//!   next), and into empty ones;
//! - in process, WGSL + SPIR-V of every variant on one thread: umbrac's
//!   library against naga_oil (bevy's composer, shader defs) on the WGSL
//!   counterpart (benches/naga_oil/, built here in release);
//! - a crate whose build.rs compiles the 256 variants through
//!   `umbrac::build`: a no-op `cargo build`, and the build script's own
//!   time when it reruns with every variant in the cache;
//! - `umbrac compile --watch`: from a saved edit to the new output.
//!
//! Each figure is the median of ROUNDS runs (`UMBRAC_BENCH_ROUNDS`, default
//! 5): wall time, and for child processes their CPU time (user + system,
//! from `getrusage`), which other jobs on a shared machine do not inflate.
//! The load average is printed with the table. Results: docs/performance.md
//! ("Compiling at scale"); the table also goes to target/perf/variants.md.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const PROG: &str = "shaders/programs/shadow_variants.das";
const SPEC: &str = "shaders/programs/shadow_variants.toml";
const UMBRAC: &str = env!("CARGO_BIN_EXE_umbrac");

#[derive(Clone, Copy, Debug)]
struct Sample {
    wall: f64,
    cpu: f64,
}

fn children_cpu() -> f64 {
    // SAFETY: getrusage only writes the struct it is given.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) };
    let t = |tv: libc::timeval| tv.tv_sec as f64 + tv.tv_usec as f64 * 1e-6;
    t(u.ru_utime) + t(u.ru_stime)
}

/// Runs a command to completion; its wall and CPU seconds.
fn timed(cmd: &mut Command) -> Sample {
    let cpu0 = children_cpu();
    let t0 = Instant::now();
    let out = cmd.stdout(Stdio::null()).stderr(Stdio::piped()).output().expect("run");
    let wall = t0.elapsed().as_secs_f64();
    assert!(out.status.success(), "{cmd:?} failed:\n{}", String::from_utf8_lossy(&out.stderr));
    Sample { wall, cpu: children_cpu() - cpu0 }
}

fn median(mut v: Vec<Sample>) -> Sample {
    v.sort_by(|a, b| a.wall.total_cmp(&b.wall));
    let wall = v[v.len() / 2].wall;
    v.sort_by(|a, b| a.cpu.total_cmp(&b.cpu));
    Sample { wall, cpu: v[v.len() / 2].cpu }
}

fn compile_cmd(out: &Path, cache: &Path, jobs: Option<usize>) -> Command {
    let mut c = Command::new(UMBRAC);
    c.args(["compile", PROG, "--variants", SPEC, "-o"]).arg(out).arg("--cache").arg(cache);
    if let Some(j) = jobs {
        c.arg("--jobs").arg(j.to_string());
    }
    c
}

fn fresh(dir: &Path) -> PathBuf {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).unwrap();
    dir.to_path_buf()
}

fn load() -> String {
    std::fs::read_to_string("/proc/loadavg").map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" ")).unwrap_or_else(|_| "?".into())
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    let rounds: usize = std::env::var("UMBRAC_BENCH_ROUNDS").ok().and_then(|r| r.parse().ok()).unwrap_or(5);
    let work = PathBuf::from("target/perf/variants");
    std::fs::create_dir_all(&work).unwrap();
    let load_before = load();
    let variants = umbrac::variants::Spec::parse_toml(&{
        let mut m = umbrac::SourceMap::new();
        m.add(SPEC, None, std::fs::read_to_string(SPEC).unwrap(), None);
        m
    }, 0)
    .unwrap()
    .expand()
    .unwrap();
    let n = variants.len();
    eprintln!("{n} variants, {rounds} rounds, load {load_before}");
    let machine_before = machine_speedup();

    // Cold runs get directories never used before (under `runs/`, removed
    // at the end): ext4 without a journal, as on this VM, searches past
    // every inode freed in the last minute or more (`recently_deleted`),
    // so a run right after deleting the previous run's 2,300 files spends
    // most of its time in the kernel. That case is measured on its own.
    let runs = work.join("runs");
    if runs.exists() {
        let _ = std::fs::rename(&runs, work.join(format!("runs-old-{}", std::process::id())));
    }
    let mut run_no = 0;
    let mut new_dir = |what: &str| {
        run_no += 1;
        let d = runs.join(format!("{run_no:04}-{what}"));
        std::fs::create_dir_all(&d).unwrap();
        d
    };

    // Cold, by jobs, the jobs interleaved round by round: the disk of this
    // VM drifts (writeback of earlier runs, inodes freed minutes before),
    // and each `--jobs` value then sees the same drift.
    // SAFETY: sync takes no arguments and cannot fail.
    unsafe { libc::sync() };
    let mut samples: Vec<Vec<Sample>> = vec![Vec::new(); 4];
    let (mut last_out, mut last_cache) = (PathBuf::new(), PathBuf::new());
    for _ in 0..rounds {
        for jobs in 1..=4 {
            let (out, cache) = (new_dir("out"), new_dir("cache"));
            samples[jobs - 1].push(timed(&mut compile_cmd(&out, &cache, Some(jobs))));
            (last_out, last_cache) = (out, cache);
        }
    }
    let mut by_jobs = Vec::new();
    for (i, runs) in samples.into_iter().enumerate() {
        let s = median(runs);
        eprintln!("cold --jobs {}: {:.1} ms wall, {:.1} ms CPU", i + 1, s.wall * 1e3, s.cpu * 1e3);
        by_jobs.push((i + 1, s));
    }
    // The same, each round right after removing the previous round's files.
    let after_delete = median(
        (0..=rounds)
            .map(|_| {
                let out = fresh(&work.join("out-deleted"));
                let cache = fresh(&work.join("cache-deleted"));
                timed(&mut compile_cmd(&out, &cache, Some(2)))
            })
            .skip(1)
            .collect(),
    );
    eprintln!("cold --jobs 2 after deleting: {:.1} ms", after_delete.wall * 1e3);

    // Warm: into the last cold run's directory (the first rerun reads the
    // outputs back and stamps them; later ones need not), and into empty ones.
    let warm_runs: Vec<Sample> = (0..rounds.max(3)).map(|_| timed(&mut compile_cmd(&last_out, &last_cache, None))).collect();
    let warm_first = warm_runs[0];
    let warm = median(warm_runs[1..].to_vec());
    let warm_empty = median((0..rounds).map(|_| timed(&mut compile_cmd(&new_dir("out-empty"), &last_cache, None))).collect());
    eprintln!("warm: {:.1} ms (first {:.1} ms; into an empty directory {:.1} ms)", warm.wall * 1e3, warm_first.wall * 1e3, warm_empty.wall * 1e3);

    // One process per variant, as a shell loop (`$1`: the output directory).
    let mut script = String::from("set -e\n");
    for v in &variants {
        let defines: String = v.defines.iter().map(|(n, val)| match val {
            Some(val) => format!(" -D {n}={val}"),
            None => format!(" -D {n}"),
        }).collect();
        script.push_str(&format!("{UMBRAC} compile {PROG}{defines} -o \"$1\"/{} --no-cache\n", v.name));
    }
    std::fs::write(work.join("loop.sh"), &script).unwrap();
    let shell_rounds = rounds.min(3);
    let shell = median((0..shell_rounds).map(|_| timed(Command::new("sh").arg(work.join("loop.sh")).arg(new_dir("loop")))).collect());
    eprintln!("shell loop: {:.1} ms", shell.wall * 1e3);

    // In process, the compile phase alone (no files written): every target,
    // one and two threads; then WGSL + SPIR-V on one thread against naga_oil.
    let all = Vec::new();
    let phase = in_process_umbrac(&variants, rounds.max(5) * 2, &all, &[1, 2]);
    let (phase1, phase2) = (phase[0], phase[1]);
    eprintln!("compile phase, every target: {phase1:.1} ms on 1 thread, {phase2:.1} ms on 2");
    let lib = in_process_umbrac(&variants, rounds, &[umbrac::Target::Wgsl, umbrac::Target::Spirv], &[1])[0];
    let oil = naga_oil(rounds);
    eprintln!("in process: umbrac {lib:.1} ms, naga_oil {}", oil.map_or("n/a".into(), |o| format!("{o:.1} ms")));

    let (noop, script_ms) = build_script(&work.join("crate"), rounds);
    let watch = watch_latency(&work.join("watch"), rounds.max(9));
    let load_after = load();
    let machine_after = machine_speedup();

    let j1 = by_jobs[0].1;
    let j2 = by_jobs[1].1;
    let mut t = String::new();
    t.push_str(&format!("{n} variants of `{PROG}`, median of {rounds} runs; load average {load_before} before, {load_after} after.\n\n"));
    t.push_str(&format!(
        "What the machine itself gave a second thread (pure arithmetic, 2 threads against 1): **{machine_before:.2}x** before, **{machine_after:.2}x** after; 2.0x is two free cores.\n\n"
    ));
    t.push_str("| measurement | wall | CPU | ratio | goal |\n|---|---|---|---|---|\n");
    for (jobs, s) in &by_jobs {
        t.push_str(&format!("| cold, `--jobs {jobs}` | {:.0} ms | {:.0} ms | {:.0} variants/s | |\n", s.wall * 1e3, s.cpu * 1e3, n as f64 / s.wall));
    }
    let eff = j1.wall / j2.wall;
    t.push_str(&format!("| whole command: `--jobs 2` over `--jobs 1` | | | **{eff:.2}x** | >= 1.8x: {} |\n", verdict(eff >= 1.8)));
    let phase_eff = phase1 / phase2;
    t.push_str(&format!(
        "| compile phase in process (no writes), every target: 1 thread / 2 threads | {phase1:.0} ms / {phase2:.0} ms | | **{phase_eff:.2}x** | >= 1.8x: {} |\n",
        verdict(phase_eff >= 1.8)
    ));
    let vs_loop = j2.wall / shell.wall;
    t.push_str(&format!(
        "| one `umbrac compile -D ...` process per variant, shell loop | {:.0} ms | {:.0} ms | batch (`--jobs 2`) / loop = **{vs_loop:.3}x** | <= 0.25x: {} |\n",
        shell.wall * 1e3,
        shell.cpu * 1e3,
        verdict(vs_loop <= 0.25)
    ));
    let warm_ratio = warm.wall / j2.wall;
    t.push_str(&format!(
        "| warm: the same command again (every variant in the cache, outputs as left), median of reruns 2-{} | {:.1} ms | {:.1} ms | warm / cold `--jobs 2` = **{:.3}x** (/ `--jobs 1`: {:.3}x) | <= 0.05x: {} |\n",
        rounds.max(3),
        warm.wall * 1e3,
        warm.cpu * 1e3,
        warm_ratio,
        warm.wall / j1.wall,
        verdict(warm_ratio <= 0.05)
    ));
    t.push_str(&format!(
        "| its first rerun (reads every output back, and stamps them) | {:.1} ms | {:.1} ms | {:.3}x | |\n",
        warm_first.wall * 1e3,
        warm_first.cpu * 1e3,
        warm_first.wall / j2.wall
    ));
    t.push_str(&format!("| warm, into an empty directory | {:.1} ms | {:.1} ms | {:.3}x | |\n", warm_empty.wall * 1e3, warm_empty.cpu * 1e3, warm_empty.wall / j2.wall));
    t.push_str(&format!(
        "| cold `--jobs 2`, right after deleting the previous run's files | {:.0} ms | {:.0} ms | {:.2}x the fresh-disk run | |\n",
        after_delete.wall * 1e3,
        after_delete.cpu * 1e3,
        after_delete.wall / j2.wall
    ));
    match oil {
        Some(o) => t.push_str(&format!("| in process, WGSL + SPIR-V, one thread: umbrac / naga_oil 0.23 | {lib:.0} ms / {o:.0} ms | | **{:.3}x** | |\n", lib / o)),
        None => t.push_str(&format!("| in process, WGSL + SPIR-V, one thread: umbrac (naga_oil not built) | {lib:.0} ms | | | |\n")),
    }
    t.push_str(&format!("| no-op `cargo build` of a crate whose build.rs compiles the {n} variants | {:.0} ms | | | |\n", noop * 1e3));
    t.push_str(&format!("| that build script rerun, every variant a cache hit (its own clock) | {script_ms:.1} ms | | | < 50 ms: {} |\n", verdict(script_ms < 50.0)));
    t.push_str(&format!("| `compile --watch`: saved edit to new outputs (median of {}) | {:.1} ms | | | |\n", watch.1, watch.0));
    println!("{t}");
    std::fs::write("target/perf/variants.md", &t).unwrap();
    for d in std::fs::read_dir(&work).into_iter().flatten().flatten() {
        let name = d.file_name().to_string_lossy().into_owned();
        if name == "runs" || name.starts_with("runs-old-") {
            let _ = std::fs::remove_dir_all(d.path());
        }
    }
    if let Err(e) = plot(&by_jobs, n) {
        eprintln!("plot: {e}");
    }
}

/// How much faster two threads of pure arithmetic finish the same work as
/// one, right now: what a second job can gain on this machine at best.
fn machine_speedup() -> f64 {
    fn spin(n: u64) -> u64 {
        let mut x = 0x9e3779b97f4a7c15u64;
        for i in 0..n {
            x = (x ^ i).wrapping_mul(0xff51afd7ed558ccd).rotate_left(17);
        }
        x
    }
    const N: u64 = 200_000_000;
    let t0 = Instant::now();
    std::hint::black_box(spin(2 * N));
    let one = t0.elapsed().as_secs_f64();
    let t0 = Instant::now();
    std::thread::scope(|s| {
        let a = s.spawn(|| std::hint::black_box(spin(N)));
        std::hint::black_box(spin(N));
        let _ = a.join();
    });
    one / t0.elapsed().as_secs_f64()
}

fn verdict(met: bool) -> &'static str {
    if met {
        "met"
    } else {
        "**missed**"
    }
}

/// The compile phase in process (`batch::compile_cached`, no cache, no
/// files): the median ms of `rounds` runs for each of `workers`, the
/// worker counts interleaved round by round (each sees the same drift of
/// the machine).
fn in_process_umbrac(variants: &[umbrac::variants::Variant], rounds: usize, targets: &[umbrac::Target], workers: &[usize]) -> Vec<f64> {
    let path = Path::new(PROG);
    let base = umbrac::Options { targets: targets.to_vec(), ..Default::default() };
    let mut times = vec![Vec::new(); workers.len()];
    for _ in 0..rounds {
        for (k, &w) in workers.iter().enumerate() {
            let units: Vec<umbrac::batch::Unit> = variants
                .iter()
                .map(|v| {
                    let mut opts = base.clone();
                    opts.defines = v.defines.clone();
                    umbrac::batch::Unit { path, opts, extra: String::new() }
                })
                .collect();
            let t0 = Instant::now();
            // Outputs hashed, as `--variants` has them hashed for variants.json.
            let hooks = umbrac::batch::Hooks { output_hashes: true, ..Default::default() };
            let (outcomes, _) = umbrac::batch::compile_cached(&units, w, None, hooks);
            times[k].push(t0.elapsed().as_secs_f64() * 1e3);
            assert!(outcomes.iter().all(|o| !o.failed()));
        }
    }
    times
        .into_iter()
        .map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect()
}

/// benches/naga_oil, built and run; its median in ms.
fn naga_oil(rounds: usize) -> Option<f64> {
    let dir = Path::new("benches/naga_oil");
    let built = Command::new(env!("CARGO")).args(["build", "--release", "-q"]).current_dir(dir).status().ok()?.success();
    if !built {
        eprintln!("benches/naga_oil did not build");
        return None;
    }
    let out = Command::new(dir.join("target/release/naga-oil-variants")).arg("benches/shadow_variants_equivalent.wgsl").arg(rounds.to_string()).output().ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let v: serde_json::Value = serde_json::from_str(text.trim()).ok()?;
    v["median_ms"].as_f64()
}

/// A crate whose build.rs compiles every variant through umbrac::build and
/// records its own time. Returns (no-op `cargo build` seconds, the build
/// script's median ms when rerun with a warm cache).
fn build_script(dir: &Path, rounds: usize) -> (f64, f64) {
    let repo = std::env::current_dir().unwrap();
    let dir = &repo.join(dir);
    std::fs::create_dir_all(dir.join("src")).unwrap();
    let manifest = format!(
        "[package]\nname = \"variants-bench\"\nversion = \"0.1.0\"\nedition = \"2021\"\npublish = false\n\n[workspace]\n\n[build-dependencies]\numbrac = {{ path = {:?}, default-features = false, features = [\"spec\"] }}\n\n# Build scripts and their dependencies are unoptimised by default.\n[profile.dev.build-override]\nopt-level = 3\n",
        repo.display().to_string()
    );
    std::fs::write(dir.join("Cargo.toml"), manifest).unwrap();
    let _ = std::fs::copy("Cargo.lock", dir.join("Cargo.lock"));
    for f in ["shadow_variants.das", "shadow_variants.toml"] {
        std::fs::copy(repo.join("shaders/programs").join(f), dir.join(f)).unwrap();
    }
    std::fs::write(
        dir.join("build.rs"),
        "fn main() {\n    let t = std::time::Instant::now();\n    umbrac::build::Build::new().variants_file(\"shadow_variants.das\", \"shadow_variants.toml\").bytemuck(false).run();\n    let ms = t.elapsed().as_secs_f64() * 1e3;\n    let mut log = std::fs::read_to_string(\"script-ms.txt\").unwrap_or_default();\n    log.push_str(&format!(\"{ms}\\n\"));\n    std::fs::write(\"script-ms.txt\", log).unwrap();\n}\n",
    )
    .unwrap();
    std::fs::write(dir.join("src/main.rs"), "include!(concat!(env!(\"OUT_DIR\"), \"/umbrac/shaders.rs\"));\nfn main() {\n    println!(\"{}\", shadow_variants::VARIANTS.len());\n}\n").unwrap();
    let cargo = || {
        let mut c = Command::new(env!("CARGO"));
        c.arg("build").arg("-q").current_dir(dir).env("CARGO_TARGET_DIR", dir.join("target"));
        for v in ["CARGO_MAKEFLAGS", "MAKEFLAGS", "MFLAGS", "CARGO_BUILD_TARGET_DIR"] {
            c.env_remove(v);
        }
        c
    };
    timed(&mut cargo());
    let noop = median((0..rounds).map(|_| timed(&mut cargo())).collect()).wall;
    let _ = std::fs::remove_file(dir.join("script-ms.txt"));
    let das = dir.join("shadow_variants.das");
    for _ in 0..rounds {
        // A new mtime reruns the script; the tokens, and so the keys, are the same.
        std::thread::sleep(Duration::from_millis(10));
        std::fs::File::options().write(true).open(&das).unwrap().set_modified(std::time::SystemTime::now()).unwrap();
        timed(&mut cargo());
    }
    let mut ms: Vec<f64> = std::fs::read_to_string(dir.join("script-ms.txt")).unwrap().lines().map(|l| l.parse().unwrap()).collect();
    ms.sort_by(f64::total_cmp);
    (noop, ms[ms.len() / 2])
}

/// `umbrac compile --watch` on the program (every target, no variants):
/// the median ms from writing an edit to the new WGSL on disk, and how many.
fn watch_latency(dir: &Path, edits: usize) -> (f64, usize) {
    let dir = fresh(dir);
    let prog = dir.join("w.das");
    let text = std::fs::read_to_string(PROG).unwrap();
    let marker = "(0.15 + 0.85 * ndotl * shadow)";
    assert!(text.contains(marker));
    std::fs::write(&prog, &text).unwrap();
    let mut child = Command::new(UMBRAC)
        .args(["compile", "--watch"])
        .arg(&prog)
        .arg("-o")
        .arg(dir.join("out"))
        .arg("--no-cache")
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let wgsl = dir.join("out/w.wgsl");
    let wait = |needle: &str| {
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            if std::fs::read_to_string(&wgsl).is_ok_and(|t| t.contains(needle)) {
                return;
            }
            assert!(Instant::now() < deadline, "watch did not write {needle}");
            std::thread::sleep(Duration::from_micros(500));
        }
    };
    wait("0.85f");
    let mut times = Vec::new();
    for i in 0..edits {
        // Two digits, the last not 0 (naga writes 0.5 as `0.5f`).
        let k = format!("0.{}{}", 1 + i / 9 % 8, 1 + i % 9);
        let edited = text.replace(marker, &format!("(0.15 + {k} * ndotl * shadow)"));
        std::thread::sleep(Duration::from_millis(150));
        let t0 = Instant::now();
        std::fs::write(&prog, edited).unwrap();
        wait(&format!("{k}f"));
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    let _ = child.kill();
    let _ = child.wait();
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], edits)
}

fn plot(by_jobs: &[(usize, Sample)], n: usize) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let path = "docs/images/variants-jobs.svg";
    let root = SVGBackend::new(path, (640, 400)).into_drawing_area();
    root.fill(&WHITE)?;
    let pts: Vec<(f64, f64)> = by_jobs.iter().map(|(j, s)| (*j as f64, n as f64 / s.wall)).collect();
    let ymax = pts.iter().map(|p| p.1).fold(0.0, f64::max) * 1.25;
    let mut chart = ChartBuilder::on(&root)
        .caption(format!("cold compile of {n} variants (all targets), 2-core machine"), ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(0.5..4.5, 0.0..ymax)?;
    chart.configure_mesh().x_desc("--jobs").y_desc("variants per second (wall)").x_labels(4).draw()?;
    chart.draw_series(LineSeries::new(pts.clone(), BLUE))?.label("measured").legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLUE));
    chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, BLUE.filled())))?;
    let one = pts[0].1;
    chart
        .draw_series(LineSeries::new([(1.0, one), (2.0, 2.0 * one), (4.0, 2.0 * one)], RED.mix(0.5)))?
        .label("ideal on 2 cores")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], RED.mix(0.5)));
    chart.configure_series_labels().background_style(WHITE.mix(0.8)).border_style(BLACK).position(SeriesLabelPosition::LowerRight).draw()?;
    root.present()?;
    eprintln!("wrote {path}");
    Ok(())
}
