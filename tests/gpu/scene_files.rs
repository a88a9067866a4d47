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
