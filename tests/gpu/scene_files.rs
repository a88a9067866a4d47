//! The built-in shadow scenes as scene files (shaders/scenes/): the
//! tutorial's shadow scene (`shadow.toml`, against `render::plan::tutorial`)
//! and the six technique scenes (`<name>.toml`, against
//! `render::techniques`), each drawn from its file and from its built-in
//! plan at the same times, on the wgpu runner (Vulkan) and on the GL 3.3
//! consumer, at 160 x 120.
//!
//! Tolerances:
//! - every value both plans set the main pass's first draw (camera, light,
//!   cascade matrices; not `u_model`, whose meshes differ in size) agrees
//!   within `1e-4` (the files give rates in degrees to 8 digits);
//! - a pixel differs when a channel differs by more than `DELTA` = 8/255;
//!   at most `MAX_SHARE` = 0.1 % of the pixels may differ (measured: none,
//!   the largest difference 1/255, on lavapipe and llvmpipe). Meshes and
//!   matrices are the same up to float rounding (the files' cube is the
//!   [-0.5, 0.5] cube scaled 1.1 where the built-in one is [-1, 1] scaled
//!   0.55, and the floor's quad is split along the other diagonal), so
//!   all that may differ is a few pixels on edges and shadow outlines;
//! - the file's two frames differ in at least `MIN_MOTION` = 10 % of the
//!   pixels (measured 42 %): the file animates, it is not a still.
//!
//! Without a Vulkan adapter or an EGL GL 3.3 context the image tests print
//! why and pass, unless `CI=true`, where they fail.

use std::path::{Path, PathBuf};

use crate::support::gpu;
use umbrac::render::image_ops;
use umbrac::render::plan::scene_file::{FrameInputs, ScenePlanner};
use umbrac::render::plan::{tutorial, FramePlan};
use umbrac::render::techniques::{self, Technique};
use umbrac::render::{Consumer, Executor, FrameParams, ShaderSet};
use umbrac::scene::Scene;
use umbrac::Target;

const W: u32 = 160;
const H: u32 = 120;
const DELTA: u8 = 8;
const MAX_SHARE: f64 = 0.001;
const MIN_MOTION: f64 = 0.1;
const TIMES: [f32; 2] = [1.0, 4.0];

/// One scene: its file's name, its program, its built-in plan.
struct Case {
    name: &'static str,
    compiled: umbrac::Compiled,
    builtin: Box<dyn Fn(&FrameParams) -> FramePlan>,
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn cases() -> Vec<Case> {
    let shadow = umbrac::compile_file(&root().join("shaders/shadow.das"), &umbrac::Options::default());
    assert!(!shadow.has_errors(), "{}", shadow.render_diagnostics());
    let mut out = vec![Case { name: "shadow", compiled: shadow.result.unwrap(), builtin: Box::new(tutorial::plan) }];
    for t in Technique::ALL {
        let compiled = t.compile().unwrap_or_else(|e| panic!("{e}"));
        out.push(Case { name: t.name(), compiled, builtin: Box::new(move |p| techniques::plan(t, p)) });
    }
    out
}

fn scene_path(name: &str) -> PathBuf {
    root().join("shaders/scenes").join(format!("{name}.toml"))
}

fn planner(c: &Case) -> ScenePlanner {
    let path = scene_path(c.name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let scene = Scene::parse(&path.display().to_string(), &text).unwrap_or_else(|e| panic!("{e}"));
    ScenePlanner::new(c.name, scene, &c.compiled.reflection, path.parent()).unwrap_or_else(|e| panic!("{e}"))
}

fn plans(c: &Case, p: &ScenePlanner, time: f32) -> (FramePlan, FramePlan) {
    let file = p.plan(&FrameInputs { time, frame: 0, width: W, height: H }).unwrap_or_else(|e| panic!("{e}"));
    (file, (c.builtin)(&FrameParams::new(time, W, H)))
}

/// Every scene file plans the built-in scene's numbers: each value of the
/// main pass's first draw that both set, `u_model` aside. No GPU needed.
#[test]
fn scene_files_set_the_builtin_scenes_values() {
    let mut failures = Vec::new();
    for c in cases() {
        let p = planner(&c);
        for time in TIMES {
            let (file, builtin) = plans(&c, &p, time);
            let main = |plan: &FramePlan| plan.passes.iter().find(|x| x.name == "main").cloned().expect("a main pass");
            let (f, b) = (main(&file), main(&builtin));
            assert_eq!(file.passes.len(), builtin.passes.len(), "{}: passes", c.name);
            let mut compared = 0;
            for name in b.value_names(&b.draws[0]) {
                let (Some(fv), Some(bv)) = (f.value(&f.draws[0], &name), b.value(&b.draws[0], &name)) else { continue };
                if name == "u_model" {
                    continue;
                }
                compared += 1;
                let worst = fv.as_f32().iter().zip(bv.as_f32()).map(|(x, y)| (x - y).abs()).fold(0.0f32, f32::max);
                if fv.words.len() != bv.words.len() || worst > 1e-4 {
                    failures.push(format!("{} at t = {time}: `{name}` differs by {worst}: file {:?}, built-in {:?}", c.name, fv.as_f32(), bv.as_f32()));
                }
            }
            assert!(compared >= 4, "{}: only {compared} values compared", c.name);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn check_on(consumer: &str, c: &Case, p: &ScenePlanner, draw: &dyn Fn(&FramePlan) -> image::RgbaImage, failures: &mut Vec<String>) {
    let mut frames = Vec::new();
    for time in TIMES {
        let (file, builtin) = plans(c, p, time);
        let (a, b) = (draw(&file), draw(&builtin));
        let stats = image_ops::diff(&a, &b, DELTA);
        eprintln!("{} on {consumer} t={time}: file vs built-in {stats}", c.name);
        if stats.fraction_over > MAX_SHARE {
            let path = gpu::artifacts_dir("scene-files").join(format!("{}-{consumer}-t{time}.png", c.name));
            let diff = image_ops::diff_image(&a, &b, None);
            image_ops::save_png(&image_ops::side_by_side(&[&a, &b, &diff]), &path).unwrap();
            failures.push(format!("{} on {consumer} at t = {time}: file vs built-in {stats} (max {:.2}%); see {}", c.name, 100.0 * MAX_SHARE, path.display()));
        }
        frames.push(a);
    }
    let motion = image_ops::diff(&frames[0], &frames[1], DELTA).fraction_over;
    eprintln!("{} on {consumer}: the file's frames differ in {:.1}% of the pixels", c.name, 100.0 * motion);
    if motion < MIN_MOTION {
        failures.push(format!("{} on {consumer}: the file's frames at t = {:?} differ in {:.2}% of the pixels: it does not move", c.name, TIMES, 100.0 * motion));
    }
}

#[test]
fn scene_files_draw_the_builtin_scenes() {
    let vulkan = gpu::vulkan();
    let gl = gpu::gl(Consumer::Gl330);
    let mut failures = Vec::new();
    for c in cases() {
        let p = planner(&c);
        if let Some(r) = vulkan {
            let set = ShaderSet::from_compiled(c.name, &c.compiled, Target::Wgsl).unwrap();
            let draw = |plan: &FramePlan| {
                let program = r.prepare(&set, plan).unwrap_or_else(|e| panic!("{} on Vulkan: {e}", c.name));
                r.run(&program, plan).unwrap_or_else(|e| panic!("{} on Vulkan: {e}", c.name)).into_image()
            };
            check_on("vulkan", &c, &p, &draw, &mut failures);
        }
        if let Some(gl) = &gl {
            let set = ShaderSet::from_compiled(c.name, &c.compiled, Target::Glsl330).unwrap();
            let draw = |plan: &FramePlan| {
                let program = gl.prepare(&set, plan).unwrap_or_else(|e| panic!("{} on GL 3.3: {e}", c.name));
                gl.run(&program, plan).unwrap_or_else(|e| panic!("{} on GL 3.3: {e}", c.name)).into_image()
            };
            check_on("gl330", &c, &p, &draw, &mut failures);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The preview page's scene.js computes each file's conventions (its
/// camera, its light, the first draw's transform) to the numbers the
/// native planner sets the main pass's first draw, within 1e-4: the page
/// reads the same `scene` JSON. Needs `node` (else skipped).
#[test]
fn the_pages_scene_js_computes_the_same_values() {
    use std::process::Command;
    if !Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success()) {
        crate::support::skip("node is not here (.ci/run installs it)");
        return;
    }
    const SCRIPT: &str = "const [url, json, time, w, h] = process.argv.slice(1);
const m = await import(url);
const scene = JSON.parse(json);
const t = Number(time);
const conv = m.conventions(scene.camera, { time: t, frame: 0, width: Number(w), height: Number(h) }, scene.light);
const main = scene.passes.find((p) => p.name === 'main');
const d = m.drawConventions(conv, main.draws[0].transform, t);
const out = {};
for (const [k, v] of Object.entries({ ...scene.values, ...main.values, ...main.draws[0].values })) {
  const x = m.conventionValue(v, d);
  if (x) out[k] = x;
}
console.log(JSON.stringify(out));";
    let url = format!("file://{}", root().join("web/preview/scene.js").display());
    let mut failures = Vec::new();
    for c in cases() {
        let p = planner(&c);
        for time in TIMES {
            let o = Command::new("node")
                .args(["--input-type=module", "-e", SCRIPT, &url, &p.scene.to_json().to_string(), &time.to_string(), &W.to_string(), &H.to_string()])
                .output()
                .unwrap();
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            let js: serde_json::Map<String, serde_json::Value> = serde_json::from_slice(&o.stdout).unwrap();
            let plan = p.plan(&FrameInputs { time, frame: 0, width: W, height: H }).unwrap();
            let main = plan.passes.iter().find(|x| x.name == "main").unwrap();
            assert!(js.len() >= 5, "{}: {js:?}", c.name);
            for (name, v) in &js {
                let native = main.value(&main.draws[0], name).unwrap_or_else(|| panic!("{}: `{name}` unset natively", c.name)).as_f32();
                let page: Vec<f32> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap() as f32).collect();
                let worst = native.iter().zip(&page).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
                if page.len() < native.len() || worst > 1e-4 {
                    failures.push(format!("{} t = {time}: `{name}` native {native:?}, scene.js {page:?}", c.name));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// shaders/scenes/deferred.toml: a G-buffer pass writes albedo, normal and
/// position (shaders/programs/deferred.das, output locations 0..2) into
/// three targets at once (`color` as a list), a lighting pass reads them
/// onto the screen. Drawn on every consumer at 96 x 72 (the screen, and
/// each target shown with `output`):
/// - the consumers agree pairwise: at most 1 % of the pixels differ by more
///   than `any::DELTA` (as the two-pass scene of tests/gpu/any_program.rs);
/// - each target holds what its location wrote: every albedo texel is the
///   cube's, the floor's or the clear (0 with alpha 0), each at least 5 %
///   of them; under the floor's texels the normal target holds (0, 1, 0)
///   and the position target y = 0 (both stored biased, within 2/255);
///   under the cube's, a unit normal (length within 0.05) and a position
///   above the floor;
/// - the screen is lit: over 30 % of it brighter than the sky, and it
///   differs from the albedo target at over 30 % of the pixels.
#[test]
fn the_deferred_scene_writes_three_targets_and_lights_them_on_every_consumer() {
    use umbrac::render::command::any;
    use umbrac::render::consumers::{Programs, Status};
    let path = root().join("shaders/programs/deferred.das");
    let c = umbrac::compile_file(&path, &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("deferred.das", compiled).unwrap();
    let scene_file = scene_path("deferred");
    let text = std::fs::read_to_string(&scene_file).unwrap();
    let scene = Scene::parse(&scene_file.display().to_string(), &text).unwrap_or_else(|e| panic!("{e}"));
    let outputs = ["screen", "albedo", "normal", "position"];
    let planners: Vec<ScenePlanner> = outputs
        .iter()
        .map(|o| {
            let mut s = scene.clone();
            s.output = o.to_string();
            ScenePlanner::new(o, s, &compiled.reflection, scene_file.parent()).unwrap_or_else(|e| panic!("{e}"))
        })
        .collect();
    let f = FrameInputs { time: 1.0, frame: 0, width: 96, height: 72 };
    let jobs: Vec<_> = planners.iter().map(|p| (&programs, p, f)).collect();
    let comparisons = any::compare_many(&jobs).unwrap_or_else(|e| panic!("{e}"));
    for (o, cmp) in outputs.iter().zip(&comparisons) {
        for (a, b, d) in &cmp.pairs {
            assert!(d.fraction_over <= 0.01, "{o}: {} vs {}: {:.4} of the pixels over {}/255\n{}", a.name(), b.name(), d.fraction_over, any::DELTA, any::table(&cmp.pairs));
        }
    }
    let mut drawn = 0;
    for (i, (consumer, _)) in comparisons[0].results.iter().enumerate() {
        let images: Vec<&image::RgbaImage> = outputs
            .iter()
            .zip(&comparisons)
            .filter_map(|(o, cmp)| match &cmp.results[i].1 {
                Status::Rendered { image, .. } => Some(image),
                Status::Unavailable { why, .. } => {
                    crate::support::skip(format!("{}: {why}", consumer.name()));
                    None
                }
                Status::Failed(e) => panic!("deferred.toml (output {o}) on {}: {e}", consumer.name()),
            })
            .collect();
        let [screen, albedo, normal, position] = images[..] else { continue };
        for (o, img) in outputs.iter().zip(&images) {
            image_ops::save_png(img, &gpu::artifacts_dir("scene-files").join(format!("deferred-{o}.{}.png", consumer.name()))).unwrap();
        }
        check_gbuffer(consumer.name(), screen, albedo, normal, position);
        drawn += 1;
    }
    eprintln!("the deferred scene drawn on {drawn} consumers");
}

/// The G-buffer's texels against what deferred.das writes (see the test above).
fn check_gbuffer(consumer: &str, screen: &image::RgbaImage, albedo: &image::RgbaImage, normal: &image::RgbaImage, position: &image::RgbaImage) {
    let byte = |x: f32| (x * 255.0).round() as i32;
    let near = |p: &image::Rgba<u8>, want: [i32; 4], tol: i32| (0..4).all(|k| (p[k] as i32 - want[k]).abs() <= tol);
    let cube = [byte(0.9), byte(0.45), byte(0.2), 255];
    let floor = [byte(0.35), byte(0.45), byte(0.6), 255];
    let n = albedo.pixels().len();
    let (mut cubes, mut floors, mut clears) = (0, 0, 0);
    let decode = |p: &image::Rgba<u8>, k: usize| p[k] as f32 / 255.0 * 2.0 - 1.0;
    for ((a, nm), pos) in albedo.pixels().zip(normal.pixels()).zip(position.pixels()) {
        if near(a, floor, 1) {
            floors += 1;
            assert!(near(nm, [128, 255, 128, 255], 2), "{consumer}: a floor texel's normal is {nm:?}, not (0, 1, 0)");
            assert!((pos[1] as i32 - 128).abs() <= 2 && pos[3] == 255, "{consumer}: a floor texel's position is {pos:?}, not at y = 0");
        } else if near(a, cube, 1) {
            cubes += 1;
            let len = (0..3).map(|k| decode(nm, k).powi(2)).sum::<f32>().sqrt();
            assert!((len - 1.0).abs() <= 0.05, "{consumer}: a cube texel's normal {nm:?} is {len} long");
            assert!(pos[1] as i32 >= 127 && pos[3] == 255, "{consumer}: a cube texel's position {pos:?} is below the floor");
        } else {
            assert!(near(a, [0, 0, 0, 0], 0), "{consumer}: an albedo texel {a:?} is neither the cube's, the floor's nor the clear");
            clears += 1;
        }
    }
    for (what, count) in [("cube", cubes), ("floor", floors), ("clear", clears)] {
        assert!(count * 20 >= n, "{consumer}: {count} of {n} albedo texels are the {what}'s");
    }
    let sky = [byte(0.05), byte(0.06), byte(0.1), 255];
    let lit = screen.pixels().filter(|p| !near(p, sky, 2) && p[0] as i32 + p[1] as i32 + p[2] as i32 > 60).count();
    assert!(lit * 10 >= n * 3, "{consumer}: {lit} of {n} screen pixels are lit");
    let differs = image_ops::diff(screen, albedo, DELTA).fraction_over;
    assert!(differs >= 0.3, "{consumer}: the screen differs from the albedo target at only {:.1} % of the pixels", 100.0 * differs);
}
