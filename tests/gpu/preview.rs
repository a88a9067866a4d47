//! `umbrac preview` in headless chromium (web/preview-drive.mjs): the page
//! draws the program with WebGL2 and WebGPU, a save on disk changes the
//! picture without a reload, and a broken save shows its diagnostics over
//! the last good picture (docs/preview.md).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::support::preview::PreviewServer;
use crate::support::skip;

/// A channel of a pixel may be this far (of 255) from the exact value:
/// rounding of the 8-bit conversion, and SwiftShader's interpolation.
const TOLERANCE: i32 = 2;

const MAIN: &str = r#"#include "tint.das"
var @uniform u_blue : float = 0.25
var @inout v_uv : float2
var @out f_color : float4

[fragment_program]
def preview_fs {
    f_color = float4(tint(v_uv), 1.0)
}
"#;

/// The included file the test saves over: the picture is (r, g, b) of the
/// uv; the edit mirrors red.
const TINT: &str = "def tint(uv : float2) : float3 {\n    return float3(uv.x, uv.y, u_blue)\n}\n";
const TINT_EDITED: &str = "def tint(uv : float2) : float3 {\n    return float3(1.0 - uv.x, uv.y, u_blue)\n}\n";
const TINT_BROKEN: &str = "def tint(uv : float2) : float3 {\n    return float3(uv.x, uv.y, nope)\n}\n";

fn web_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("web")
}

/// Whether node, chromium and playwright-core are here (else skipped).
pub(crate) fn browser_ready() -> bool {
    let chromium = std::env::var_os("UMBRAC_CHROMIUM").map_or_else(|| PathBuf::from("/usr/bin/chromium"), PathBuf::from);
    let node = Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success());
    let playwright = web_dir().join("node_modules/playwright-core/package.json").is_file();
    if node && chromium.is_file() && playwright {
        return true;
    }
    skip(format!(
        "the preview page needs node ({node}), {} ({}) and playwright-core in web/node_modules ({playwright}); .ci/run installs them",
        chromium.display(),
        chromium.is_file()
    ));
    false
}

/// The page's state after each step (the first picture, then one per save)
/// and its pictures, rows bottom first.
pub(crate) struct Step {
    pub(crate) state: serde_json::Value,
    pub(crate) webgl2: Option<Vec<u8>>,
    pub(crate) webgpu: Option<Vec<u8>>,
}

fn drive(server: &PreviewServer, saved: &Path, saves: &[&str], out: &Path) -> Vec<Step> {
    drive_with(server, "time=1", saved, saves, out, None)
}

/// `query`: the page's (docs/preview.md); `control`: NAME=VALUE, a slider
/// moved after the first picture (`control.API.rgba` in `out`).
pub(crate) fn drive_with(server: &PreviewServer, query: &str, saved: &Path, saves: &[&str], out: &Path, control: Option<&str>) -> Vec<Step> {
    let mut files = Vec::new();
    for (i, text) in saves.iter().enumerate() {
        let f = out.join(format!("save{i}.das"));
        std::fs::write(&f, text).unwrap();
        files.push(f);
    }
    let status = Command::new("node")
        .arg(web_dir().join("preview-drive.mjs"))
        .arg(format!("{}?{query}", server.url()))
        .arg(saved)
        .arg(out)
        .args(&files)
        .envs(control.map(|c| ("UMBRAC_PREVIEW_CONTROL", c)))
        .stdin(Stdio::null())
        .status()
        .expect("node runs");
    let result: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("result.json")).expect("the driver writes its result")).unwrap();
    assert!(status.success(), "the driver failed: {result}");
    let read = |name: String| std::fs::read(out.join(name)).ok();
    result["steps"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .map(|(i, s)| Step { state: s.clone(), webgl2: read(format!("{i}.webgl2.rgba")), webgpu: read(format!("{i}.webgpu.rgba")) })
        .collect()
}

/// How many pixels are further than TOLERANCE from `expect(x, y)` (pixel
/// centres, uv in 0..1, y up), and the first such.
fn off_pixels(px: &[u8], w: usize, h: usize, expect: impl Fn(f32, f32) -> [f32; 3]) -> (usize, Option<String>) {
    assert_eq!(px.len(), w * h * 4);
    let mut off = 0;
    let mut first = None;
    for y in 0..h {
        for x in 0..w {
            let e = expect((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
            let got = &px[4 * (y * w + x)..][..3];
            if (0..3).any(|c| (got[c] as i32 - (e[c] * 255.0).round() as i32).abs() > TOLERANCE) {
                off += 1;
                first.get_or_insert_with(|| format!("({x}, {y}): {got:?}, expected {e:?}"));
            }
        }
    }
    (off, first)
}

fn check_picture(step: &Step, what: &str, expect: impl Fn(f32, f32) -> [f32; 3] + Copy) {
    let (w, h) = (step.state["width"].as_u64().unwrap() as usize, step.state["height"].as_u64().unwrap() as usize);
    let gl = step.webgl2.as_ref().unwrap_or_else(|| panic!("{what}: no WebGL2 picture: {}", step.state));
    let (off, first) = off_pixels(gl, w, h, expect);
    assert_eq!(off, 0, "{what}: WebGL2 pixels off by more than {TOLERANCE}/255, first {first:?}");
    match &step.webgpu {
        Some(gpu) => {
            let (off, first) = off_pixels(gpu, w, h, expect);
            assert_eq!(off, 0, "{what}: WebGPU pixels off by more than {TOLERANCE}/255, first {first:?}");
            assert_eq!(step.state["diff"]["share"], 0, "{what}: the page's own comparison: {}", step.state["diff"]);
        }
        None => skip(format!("{what}: headless chromium drew no WebGPU picture: {}", step.state["errors"]["webgpu"])),
    }
}

#[test]
fn a_save_redraws_without_a_reload_and_a_broken_save_keeps_the_last_picture() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("main.das");
    let tint = dir.path().join("tint.das");
    std::fs::write(&main, MAIN).unwrap();
    std::fs::write(&tint, TINT).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&main);
    // The include is what is saved: what the program reads is watched too.
    // After the first picture, u_blue's slider is moved to 0.75.
    let steps = drive_with(&server, "time=1", &tint, &[TINT_EDITED, TINT_BROKEN], &out, Some("u_blue=0.75"));
    assert_eq!(steps.len(), 3);

    assert_eq!(steps[0].state["ok"], true, "{}", steps[0].state);
    check_picture(&steps[0], "first picture", |u, v| [u, v, 0.25]);
    let moved = Step { state: steps[0].state.clone(), webgl2: std::fs::read(out.join("control.webgl2.rgba")).ok(), webgpu: std::fs::read(out.join("control.webgpu.rgba")).ok() };
    let diff = serde_json::from_slice::<serde_json::Value>(&std::fs::read(out.join("result.json")).unwrap()).unwrap()["control"]["diff"].clone();
    check_picture(&Step { state: serde_json::json!({ "width": moved.state["width"], "height": moved.state["height"], "diff": diff }), ..moved }, "u_blue's slider at 0.75", |u, v| [u, v, 0.75]);

    let s = &steps[1].state;
    assert_eq!(s["ok"], true, "{s}");
    assert_eq!(s["notReloaded"], true);
    assert!(s["drawn"].as_u64() > steps[0].state["drawn"].as_u64(), "{s}");
    check_picture(&steps[1], "after the save", |u, v| [1.0 - u, v, 0.75]);

    let s = &steps[2].state;
    assert_eq!(s["ok"], false, "{s}");
    assert_eq!(s["notReloaded"], true);
    assert_eq!(s["overlay"], true, "the diagnostics are shown: {s}");
    let d = &s["diagnostics"][0];
    assert!(d["location"]["file"].as_str().unwrap().ends_with("tint.das"), "{d}");
    assert_eq!((d["location"]["line"].as_u64(), d["location"]["column"].as_u64()), (Some(2), Some(31)), "{d}");
    let overlay = s["overlayText"].as_str().unwrap();
    assert!(overlay.contains("unknown name `nope`") && overlay.contains("tint.das:2:31") && overlay.contains('^'), "{overlay}");
    // The last good program still draws.
    check_picture(&steps[2], "after the broken save", |u, v| [1.0 - u, v, 0.75]);
}

/// GL tutorials from ../shared, each saved over the last in one page: 03
/// (a full-screen program, time and aspect by convention, no scene mesh),
/// 04 (the scene's cube with a depth target and a checker texture), 05
/// (an instance grid) and 08 (a shadow sampler reading a depth target a
/// first pass clears). Both pictures drawn, not flat, and at most this
/// share of their pixels differ by more than 2/255.
const TUTORIAL_AGREEMENT: f64 = 0.01;

#[test]
fn tutorials_draw_alike_on_webgl2_and_webgpu() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang-tutorials");
    let names = ["03_sdf.das", "04_cube.das", "05_instancing.das", "08_shadow.das"];
    if let Some(missing) = names.iter().map(|n| root.join(n)).find(|p| !p.is_file()) {
        skip(format!("{} is missing", missing.display()));
        return;
    }
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("tutorial.das");
    std::fs::copy(root.join(names[0]), &file).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&file);
    let rest: Vec<String> = names[1..].iter().map(|n| std::fs::read_to_string(root.join(n)).unwrap()).collect();
    let steps = drive(&server, &file, &rest.iter().map(String::as_str).collect::<Vec<_>>(), &out);
    for (name, step) in names.iter().zip(&steps) {
        let s = &step.state;
        assert_eq!(s["ok"], true, "{name}: {s}");
        assert_eq!(s["errors"]["webgl2"], serde_json::Value::Null, "{name}: {s}");
        let gl = step.webgl2.as_ref().unwrap_or_else(|| panic!("{name}: no WebGL2 picture: {s}"));
        // Not the clear colour alone: the scene was drawn (08's unshadowed
        // cube has three flat faces over black).
        let distinct: std::collections::HashSet<&[u8]> = gl.chunks(4).collect();
        assert!(distinct.len() >= 3, "{name}: only {} colours in the WebGL2 picture", distinct.len());
        if step.webgpu.is_none() {
            skip(format!("{name}: headless chromium drew no WebGPU picture: {}", s["errors"]["webgpu"]));
            continue;
        }
        let share = s["diff"]["share"].as_f64().unwrap();
        assert!(share <= TUTORIAL_AGREEMENT, "{name}: {:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
    }
}

/// Tutorial 10's G-buffer program writes three colour outputs: each is
/// viewable (`?output=LOCATION`), alike on both APIs, and they differ; so
/// is its depth (`?output=depth`).
#[test]
fn every_colour_output_and_the_depth_of_a_g_buffer_are_viewable() {
    let tutorial = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang-tutorials/10_deferred.das");
    if !tutorial.is_file() {
        skip(format!("{} is missing", tutorial.display()));
        return;
    }
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("10_deferred.das");
    std::fs::copy(&tutorial, &file).unwrap();
    let server = PreviewServer::start(&file);
    let mut pictures = Vec::new();
    for location in 0..3 {
        let out = dir.path().join(format!("out{location}"));
        std::fs::create_dir(&out).unwrap();
        let steps = drive_with(&server, &format!("time=1&output={location}"), &file, &[], &out, None);
        let s = &steps[0].state;
        assert_eq!(s["errors"]["webgl2"], serde_json::Value::Null, "output {location}: {s}");
        pictures.push(steps[0].webgl2.clone().unwrap_or_else(|| panic!("output {location}: no WebGL2 picture: {s}")));
        if steps[0].webgpu.is_none() {
            skip(format!("output {location}: headless chromium drew no WebGPU picture: {}", s["errors"]["webgpu"]));
            continue;
        }
        let share = s["diff"]["share"].as_f64().unwrap();
        assert!(share <= TUTORIAL_AGREEMENT, "output {location}: {:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
    }
    assert!(pictures[0] != pictures[1] && pictures[1] != pictures[2] && pictures[0] != pictures[2], "the three outputs show the same picture");
    // The depth: grey, farther where nothing was drawn (the clear, 1: white).
    let out = dir.path().join("depth");
    std::fs::create_dir(&out).unwrap();
    let steps = drive_with(&server, "time=1&output=depth", &file, &[], &out, None);
    let s = &steps[0].state;
    let depth = steps[0].webgl2.clone().unwrap_or_else(|| panic!("depth: no WebGL2 picture: {s}"));
    assert!(depth.chunks(4).all(|p| p[0] == p[1] && p[1] == p[2]), "the depth view is grey");
    assert!(depth.chunks(4).any(|p| p[0] == 255) && depth.chunks(4).any(|p| p[0] < 250), "the depth view shows the background and something nearer");
    if steps[0].webgpu.is_some() {
        let share = s["diff"]["share"].as_f64().unwrap();
        assert!(share <= TUTORIAL_AGREEMENT, "depth: {:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
    }
}

/// The built playground (scripts/build-playground.sh, target/playground/),
/// or a skip (a failure under `CI=true`) without it.
fn built_playground() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/playground");
    if dir.join("umbrac_web_bg.wasm").is_file() {
        return Some(dir);
    }
    skip(format!("no built playground at {} (bash scripts/build-playground.sh)", dir.display()));
    None
}

/// The main file's edits: the picture mirrored in x; its channels turned
/// around (an edit typed in the page, compiled in its WebAssembly with the
/// include the server sent); an error on line 8.
const MAIN_MIRRORED: &str = "#include \"tint.das\"\nvar @uniform u_blue : float = 0.25\nvar @inout v_uv : float2\nvar @out f_color : float4\n\n[fragment_program]\ndef preview_fs {\n    f_color = float4(tint(float2(1.0 - v_uv.x, v_uv.y)), 1.0)\n}\n";
const MAIN_TYPED: &str = "#include \"tint.das\"\nvar @uniform u_blue : float = 0.25\nvar @inout v_uv : float2\nvar @out f_color : float4\n\n[fragment_program]\ndef preview_fs {\n    f_color = float4(tint(float2(1.0 - v_uv.x, v_uv.y)).zyx, 1.0)\n}\n";
const MAIN_BROKEN: &str = "#include \"tint.das\"\nvar @uniform u_blue : float = 0.25\nvar @inout v_uv : float2\nvar @out f_color : float4\n\n[fragment_program]\ndef preview_fs {\n    f_color = float4(tint(v_uv) * nope, 1.0)\n}\n";

/// `umbrac preview FILE` serves the playground with FILE loaded: the
/// editor holds the file's text and the server's bundle is drawn; a save
/// on disk reaches the editor and the picture without a reload; an edit
/// typed in the page compiles there (its include from the server's
/// bundle) and draws; a broken save is marked in the editor at its line.
#[test]
fn the_playground_under_preview_holds_the_file_and_follows_its_saves() {
    if !browser_ready() {
        return;
    }
    let Some(playground) = built_playground() else { return };
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("main.das");
    std::fs::write(&main, MAIN).unwrap();
    std::fs::write(dir.path().join("tint.das"), TINT).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start_with(&main, &[std::ffi::OsStr::new("--playground"), playground.as_os_str()]);
    let steps = serde_json::json!([
        { "save": main, "text": MAIN_MIRRORED },
        { "type": MAIN_TYPED },
        { "save": main, "text": MAIN_BROKEN },
    ]);
    let steps_file = dir.path().join("steps.json");
    std::fs::write(&steps_file, steps.to_string()).unwrap();
    let status = Command::new("node")
        .arg(web_dir().join("playground/live-drive.mjs"))
        .arg(format!("{}playground/", server.url()))
        .arg(&out)
        .arg(&steps_file)
        .stdin(Stdio::null())
        .status()
        .expect("node runs");
    let result: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("result.json")).expect("the driver writes its result")).unwrap();
    assert!(status.success(), "the driver failed: {result}");
    let read = |name: String| std::fs::read(out.join(name)).ok();
    let step = |i: usize| {
        let s = result["steps"][i].clone();
        Step { webgl2: read(format!("{i}.webgl2.rgba")), webgpu: read(format!("{i}.webgpu.rgba")), state: s }
    };

    let s0 = step(0);
    assert_eq!(s0.state["editor"], MAIN, "the editor holds the file: {}", s0.state);
    // The Example menu names the served file; the File menu lists the include.
    assert!(s0.state["menu"].as_str().is_some_and(|m| m.ends_with(".das") && !m.contains("shared")), "{}", s0.state["menu"]);
    assert!(s0.state["fileMenu"].as_array().is_some_and(|f| f.iter().any(|x| x.as_str().is_some_and(|x| x.ends_with("tint.das")))), "{}", s0.state["fileMenu"]);
    assert_eq!(s0.state["ok"], true, "{}", s0.state);
    assert_eq!(s0.state["errors"]["webgl2"], serde_json::Value::Null, "{}", s0.state);
    check_picture(&s0, "the file's picture", |u, v| [u, v, 0.25]);

    let s1 = step(1);
    assert_eq!(s1.state["editor"], MAIN_MIRRORED, "the save reached the editor: {}", s1.state);
    assert_eq!(s1.state["notReloaded"], true);
    check_picture(&s1, "after the save", |u, v| [1.0 - u, v, 0.25]);

    let s2 = step(2);
    assert_eq!(s2.state["editor"], MAIN_TYPED);
    assert_eq!(s2.state["ok"], true, "the typed edit compiles in the page with the include: {}", s2.state);
    assert_eq!(s2.state["live"]["received"], s1.state["live"]["received"], "compiled in the page, not by the server");
    check_picture(&s2, "after the typed edit", |u, v| [0.25, v, 1.0 - u]);

    let s3 = step(3);
    assert_eq!(s3.state["editor"], MAIN_BROKEN, "the broken save reached the editor: {}", s3.state);
    assert_eq!(s3.state["ok"], false);
    let marks = s3.state["marks"].as_array().unwrap();
    assert!(marks.iter().any(|m| m["line"] == 8 && m["severity"] == "error" && m["message"].as_str().unwrap().contains("nope")), "{marks:?}");
    // The last good program still draws: the typed edit's picture.
    check_picture(&s3, "after the broken save", |u, v| [0.25, v, 1.0 - u]);
}

/// Tutorial 06 in the page: its first program, the skybox, reads a
/// `samplerCube` (the built-in sky, web/preview/textures.js) with the
/// camera looking up at the horizon. On WebGL2 at least a quarter of the
/// pixels are sky (blue the largest channel, above 150) and a tenth
/// ground; WebGPU agrees within [`TUTORIAL_AGREEMENT`]. The picture is
/// saved as `skybox.page.png` among the test artifacts.
#[test]
fn the_skybox_tutorial_shows_its_sky_in_the_page() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang-tutorials/06_skybox.das");
    if !file.is_file() {
        skip(format!("{} is missing", file.display()));
        return;
    }
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = dir.path().join("06_skybox.das");
    std::fs::copy(&file, &program).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&program);
    let steps = drive(&server, &program, &[], &out);
    let s = &steps[0].state;
    assert_eq!(s["ok"], true, "{s}");
    let gl = steps[0].webgl2.as_ref().unwrap_or_else(|| panic!("no WebGL2 picture: {s}"));
    let (w, h) = (s["width"].as_u64().unwrap() as u32, s["height"].as_u64().unwrap() as u32);
    // Rows bottom first: flipped for the PNG.
    let mut img = image::RgbaImage::from_raw(w, h, gl.clone()).unwrap();
    image::imageops::flip_vertical_in_place(&mut img);
    img.save(crate::support::gpu::artifacts_dir("any-program").join("skybox.page.png")).unwrap();
    let n = gl.len() / 4;
    let sky = gl.chunks(4).filter(|p| p[2] > 150 && p[2] >= p[0] && p[2] >= p[1]).count();
    let ground = gl.chunks(4).filter(|p| p[2] < p[0].max(p[1])).count();
    assert!(sky * 4 >= n && ground * 10 >= n, "{sky} sky and {ground} ground pixels of {n}");
    if steps[0].webgpu.is_none() {
        skip(format!("headless chromium drew no WebGPU picture: {}", s["errors"]["webgpu"]));
        return;
    }
    let share = s["diff"]["share"].as_f64().unwrap();
    assert!(share <= TUTORIAL_AGREEMENT, "{:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
}

/// `shaders/programs/instanced.das` in the page: its instance table
/// (`u_instances : Instance[64]`, a loose uniform array of structs) is set
/// member by member from the scene's paths, on WebGL2 by each leaf's GLSL
/// name (it was skipped: every instance scaled to nothing, a black
/// picture). At least 5 % of the WebGL2 pixels are lit, and WebGPU agrees
/// within [`TUTORIAL_AGREEMENT`].
#[test]
fn the_instanced_program_draws_its_instance_table_in_the_page() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = dir.path().join("instanced.das");
    std::fs::copy(Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders/programs/instanced.das"), &program).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&program);
    let steps = drive(&server, &program, &[], &out);
    let s = &steps[0].state;
    assert_eq!(s["ok"], true, "{s}");
    let gl = steps[0].webgl2.as_ref().unwrap_or_else(|| panic!("no WebGL2 picture: {s}"));
    let lit = gl.chunks(4).filter(|p| p[0] > 20 || p[1] > 20 || p[2] > 20).count();
    assert!(lit * 20 >= gl.len() / 4, "{lit} lit pixels of {}", gl.len() / 4);
    if steps[0].webgpu.is_none() {
        skip(format!("headless chromium drew no WebGPU picture: {}", s["errors"]["webgpu"]));
        return;
    }
    let share = s["diff"]["share"].as_f64().unwrap();
    assert!(share <= TUTORIAL_AGREEMENT, "{:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
}
