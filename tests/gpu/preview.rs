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
fn browser_ready() -> bool {
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
struct Step {
    state: serde_json::Value,
    webgl2: Option<Vec<u8>>,
    webgpu: Option<Vec<u8>>,
}

fn drive(server: &PreviewServer, saved: &Path, saves: &[&str], out: &Path) -> Vec<Step> {
    let mut files = Vec::new();
    for (i, text) in saves.iter().enumerate() {
        let f = out.join(format!("save{i}.das"));
        std::fs::write(&f, text).unwrap();
        files.push(f);
    }
    let status = Command::new("node")
        .arg(web_dir().join("preview-drive.mjs"))
        .arg(format!("{}?time=1", server.url()))
        .arg(saved)
        .arg(out)
        .args(&files)
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
    let steps = drive(&server, &tint, &[TINT_EDITED, TINT_BROKEN], &out);
    assert_eq!(steps.len(), 3);

    assert_eq!(steps[0].state["ok"], true, "{}", steps[0].state);
    check_picture(&steps[0], "first picture", |u, v| [u, v, 0.25]);

    let s = &steps[1].state;
    assert_eq!(s["ok"], true, "{s}");
    assert_eq!(s["notReloaded"], true);
    assert!(s["drawn"].as_u64() > steps[0].state["drawn"].as_u64(), "{s}");
    check_picture(&steps[1], "after the save", |u, v| [1.0 - u, v, 0.25]);

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
    check_picture(&steps[2], "after the broken save", |u, v| [1.0 - u, v, 0.25]);
}

/// A GL tutorial from ../shared (a full-screen fragment program with time
/// and aspect by name convention): both pictures drawn, and at most this
/// share of their pixels differ by more than 2/255.
const TUTORIAL_AGREEMENT: f64 = 0.01;

#[test]
fn a_tutorial_draws_alike_on_webgl2_and_webgpu() {
    let tutorial = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang-tutorials/03_sdf.das");
    if !tutorial.is_file() {
        skip(format!("{} is missing", tutorial.display()));
        return;
    }
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("03_sdf.das");
    std::fs::copy(&tutorial, &file).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&file);
    let steps = drive(&server, &file, &[], &out);
    let s = &steps[0].state;
    assert_eq!(s["ok"], true, "{s}");
    let gl = steps[0].webgl2.as_ref().unwrap_or_else(|| panic!("no WebGL2 picture: {s}"));
    // Not one flat colour: the scene was drawn.
    let distinct: std::collections::HashSet<&[u8]> = gl.chunks(4).collect();
    assert!(distinct.len() > 100, "only {} colours in the WebGL2 picture", distinct.len());
    if steps[0].webgpu.is_none() {
        skip(format!("headless chromium drew no WebGPU picture: {}", s["errors"]["webgpu"]));
        return;
    }
    let share = s["diff"]["share"].as_f64().unwrap();
    assert!(share <= TUTORIAL_AGREEMENT, "{:.2}% of the pixels differ: {}", share * 100.0, s["diff"]);
}
