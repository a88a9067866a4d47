//! `umbrac preview FILE --scene SCENE` in headless chromium
//! (web/preview-drive.mjs): scenes of several passes, render targets and
//! draws, with samplers reading targets drawn earlier, drawn by the page
//! on WebGL2 and WebGPU (web/preview/passes.js; docs/preview.md).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::support::preview::PreviewServer;
use crate::support::skip;

/// At most this share of the pixels may differ by more than 2/255 between
/// the page's WebGL2 and WebGPU pictures (measured: none).
const API_AGREEMENT: f64 = 0.001;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Whether node, chromium and playwright-core are here (else skipped).
fn browser_ready() -> bool {
    let chromium = std::env::var_os("UMBRAC_CHROMIUM").map_or_else(|| PathBuf::from("/usr/bin/chromium"), PathBuf::from);
    let node = Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success());
    let playwright = root().join("web/node_modules/playwright-core/package.json").is_file();
    if node && chromium.is_file() && playwright {
        return true;
    }
    skip(format!("the preview page needs node ({node}), {} ({}) and playwright-core in web/node_modules ({playwright}); .ci/run installs them", chromium.display(), chromium.is_file()));
    false
}

/// The page's first picture of `program` drawn with `scene`: its state and
/// its pictures (rows bottom first; WebGPU's absent where chromium has none).
struct Picture {
    state: serde_json::Value,
    webgl2: Vec<u8>,
    webgpu: Option<Vec<u8>>,
}

fn picture(program: &Path, scene: &Path, out: &Path) -> Picture {
    picture_at(program, scene, 0.0, out)
}

/// The same with the page's clock fixed at `time` seconds.
fn picture_at(program: &Path, scene: &Path, time: f32, out: &Path) -> Picture {
    std::fs::create_dir_all(out).unwrap();
    let server = PreviewServer::start_with(program, &[std::ffi::OsStr::new("--scene"), scene.as_os_str()]);
    let status = Command::new("node")
        .arg(root().join("web/preview-drive.mjs"))
        .arg(format!("{}?time={time}", server.url()))
        .arg(program)
        .arg(out)
        .stdin(Stdio::null())
        .status()
        .expect("node runs");
    let result: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("result.json")).expect("the driver writes its result")).unwrap();
    assert!(status.success(), "the driver failed: {result}");
    let state = result["steps"][0].clone();
    assert_eq!(state["ok"], true, "{}: {state}", scene.display());
    assert_eq!(state["errors"]["webgl2"], serde_json::Value::Null, "{}: {state}", scene.display());
    let webgl2 = std::fs::read(out.join("0.webgl2.rgba")).unwrap_or_else(|_| panic!("{}: no WebGL2 picture: {state}", scene.display()));
    let webgpu = std::fs::read(out.join("0.webgpu.rgba")).ok();
    match &webgpu {
        Some(_) => {
            let share = state["diff"]["share"].as_f64().unwrap();
            assert!(share <= API_AGREEMENT, "{}: {:.3}% of the pixels differ between WebGL2 and WebGPU: {}", scene.display(), share * 100.0, state["diff"]);
        }
        None => skip(format!("{}: headless chromium drew no WebGPU picture: {}", scene.display(), state["errors"]["webgpu"])),
    }
    Picture { state, webgl2, webgpu }
}

/// The share of pixels where `a` is darker than `b` by more than `by`
/// (of 255, the sum of the colour channels).
fn darker_share(a: &[u8], b: &[u8], by: i32) -> f64 {
    assert_eq!(a.len(), b.len());
    let sum = |p: &[u8]| p[..3].iter().map(|&c| c as i32).sum::<i32>();
    let n = a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| sum(q) - sum(p) > by).count();
    n as f64 / (a.len() / 4) as f64
}

/// The scene file `scene` changed by `edit`, written as JSON into `dir`.
fn edited(scene: &Path, dir: &Path, name: &str, edit: impl FnOnce(&mut umbrac::scene::Scene)) -> PathBuf {
    let mut s = umbrac::scene::Scene::parse(&scene.display().to_string(), &std::fs::read_to_string(scene).unwrap()).unwrap();
    edit(&mut s);
    let out = dir.join(name);
    std::fs::write(&out, s.to_json().to_string()).unwrap();
    out
}

/// shaders/scenes/shadow.toml: a depth pass of two draws into a 1024 x
/// 1024 depth target, then the lit pass of two draws reading it through
/// the comparison sampler, at 4 s (the scene is animated: at 0 s its
/// shadow covers only 1.5%). Drawn alike on both APIs; shadowed
/// (against the same scene with the depth pass drawing nothing, at least
/// 2% of the pixels darker by more than 30/255 summed; measured 4.0%);
/// and as `umbrac render --backend webgl2 --time 4` draws the scene file
/// (at most 0.1% of the pixels over 8/255: measured none, worst 1).
#[test]
fn the_shadow_scene_file_draws_shadowed_on_both_apis() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = root().join("shaders/shadow.das");
    let scene = root().join("shaders/scenes/shadow.toml");
    let shadowed = picture_at(&program, &scene, 4.0, &dir.path().join("shadowed"));
    let lit_scene = edited(&scene, dir.path(), "lit.json", |s| s.passes[0].draws.clear());
    let lit = picture_at(&program, &lit_scene, 4.0, &dir.path().join("lit"));
    let share = darker_share(&shadowed.webgl2, &lit.webgl2, 30);
    assert!(share >= 0.02, "WebGL2: only {:.2}% of the pixels are in shadow", share * 100.0);
    if let (Some(s), Some(l)) = (&shadowed.webgpu, &lit.webgpu) {
        let share = darker_share(s, l, 30);
        assert!(share >= 0.02, "WebGPU: only {:.2}% of the pixels are in shadow", share * 100.0);
    }

    assert_like_native_at(&program, &scene, &shadowed, 4.0, dir.path());
}

/// shaders/scenes/shadow.toml is animated (a spinning cube, a turning
/// sun): at 1 s and at 4 s the page draws it as `umbrac render
/// --backend webgl2 --time T` does (at most 0.1% of the pixels over
/// 8/255: measured none, worst 1), alike on both APIs, and the two
/// pictures differ (at least 10% of the pixels by more than 8/255;
/// measured 42%): the page's light and draw transforms move with time.
/// Edited: a number for a float3 control fills every component, and one
/// draw of one pass (draw.js's own path) takes its transform and the
/// light, each as natively.
#[test]
fn the_animated_shadow_scene_file_moves_as_natively() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = root().join("shaders/shadow.das");
    let scene = root().join("shaders/scenes/shadow.toml");
    let early = picture_at(&program, &scene, 1.0, &dir.path().join("t1"));
    assert_like_native_at(&program, &scene, &early, 1.0, dir.path());
    let late = picture_at(&program, &scene, 4.0, &dir.path().join("t4"));
    assert_like_native_at(&program, &scene, &late, 4.0, dir.path());
    let moved = early.webgl2.chunks(4).zip(late.webgl2.chunks(4)).filter(|(a, b)| (0..3).any(|c| (a[c] as i32 - b[c] as i32).abs() > 8)).count();
    let share = moved as f64 / (early.webgl2.len() / 4) as f64;
    assert!(share >= 0.1, "only {:.1}% of the pixels change between 1 s and 4 s", share * 100.0);

    // A number for the float3 `u_light_dir` (a control) fills every
    // component, as natively: a light from (1, 1, 1), not from +x.
    let number = edited(&scene, dir.path(), "number.json", |s| {
        s.values.insert("u_light_dir".into(), umbrac::scene::ValueSpec::Number(0.577));
    });
    let page = picture_at(&program, &number, 1.0, &dir.path().join("number"));
    assert_like_native_at(&program, &number, &page, 1.0, &dir.path().join("number"));

    // One draw (the cube) of one pass, its map only cleared: draw.js's own
    // path (not passes.js), with the draw's transform and the scene's
    // light through controls.js (measured: no pixel over 8/255).
    let single = edited(&scene, dir.path(), "single.json", |s| {
        s.passes[0].draws.clear();
        s.passes[1].draws.truncate(1);
    });
    let page = picture_at(&program, &single, 3.0, &dir.path().join("single"));
    assert_like_native_at(&program, &single, &page, 3.0, &dir.path().join("single"));
}

/// The technique scene files with a light and per-draw transforms
/// (shaders/scenes/, shaders/techniques/): the cascaded sun (three depth
/// passes, each given one element of `light_view_projections`, and the
/// whole array read by the lit pass), the spot light (its position and
/// direction) and the depth packed into an RGBA8 target. Each drawn by
/// the page alike on both APIs and as `umbrac render --backend webgl2
/// --time T` draws it (at most 0.1% of the pixels over 8/255: measured
/// at most 1 pixel, on rgba8-depth's packed-depth edge).
#[test]
fn the_technique_scene_files_draw_as_natively() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (program, scene, time) in [("cascades", "cascades", 1.0), ("spot_light", "spot", 1.0), ("rgba8_depth", "rgba8-depth", 2.0)] {
        let program = root().join(format!("shaders/techniques/{program}.das"));
        let scene = root().join(format!("shaders/scenes/{scene}.toml"));
        let out = dir.path().join(scene.file_stem().unwrap());
        let page = picture_at(&program, &scene, time, &out);
        assert_like_native_at(&program, &scene, &page, time, &out);
    }
}

/// Checks that the page's WebGL2 picture is within 8/255 of `umbrac render
/// --backend webgl2` of the same program and scene file on at least 99.9%
/// of the pixels.
fn assert_like_native(program: &Path, scene: &Path, page: &Picture, dir: &Path) {
    assert_like_native_at(program, scene, page, 0.0, dir);
}

/// The same at `time` seconds.
fn assert_like_native_at(program: &Path, scene: &Path, page: &Picture, time: f32, dir: &Path) {
    let (w, h) = (page.state["width"].as_u64().unwrap() as u32, page.state["height"].as_u64().unwrap() as u32);
    let png = dir.join(format!("native-{time}.png"));
    let out = Command::new(env!("CARGO_BIN_EXE_umbrac"))
        .arg("render")
        .arg(program)
        .arg("--scene")
        .arg(scene)
        .args(["--backend", "webgl2", "--time", &time.to_string(), "--size", &format!("{w}x{h}"), "--out"])
        .arg(&png)
        .output()
        .unwrap();
    assert!(out.status.success(), "umbrac render: {}", String::from_utf8_lossy(&out.stderr));
    let native = image::open(&png).unwrap().to_rgba8();
    let mut off = 0;
    for y in 0..h {
        for x in 0..w {
            // The page's rows are bottom first; the PNG's top first.
            let px = &page.webgl2[4 * ((h - 1 - y) * w + x) as usize..][..3];
            let n = native.get_pixel(x, y).0;
            off += (0..3).any(|c| (px[c] as i32 - n[c] as i32).abs() > 8) as usize;
        }
    }
    assert!(off as f64 <= 0.001 * (w * h) as f64, "{} at {time} s: {off} of {} pixels differ from umbrac render --backend webgl2 by more than 8/255", scene.display(), w * h);
}

/// GL tutorial 08 (two programs) drawn with its scene file
/// (shaders/scenes/tutorial_08.toml): alike on both APIs and as `umbrac
/// render --backend webgl2` draws it.
#[test]
fn tutorial_08_draws_from_its_scene_file() {
    let program = root().join("../shared/reference/daslang-tutorials/08_shadow.das");
    if !program.is_file() {
        skip(format!("{} is missing", program.display()));
        return;
    }
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("shaders/scenes/tutorial_08.toml");
    let page = picture(&program, &scene, &dir.path().join("page"));
    assert_like_native(&program, &scene, &page, dir.path());
}

/// shaders/scenes/bloom.toml: four full-screen passes, three into 120 x
/// 90 colour targets each read by the next through a plain sampler, the
/// first and the last reading an image file the server serves beside the
/// scene. Alike on both APIs; the bloom the last pass reads from the
/// chain shows (against the same scene with `u_bloom_strength = 0`, at
/// least 1% of the pixels brighter by more than 12/255 summed), and
/// nothing is darker; with `output = "bright"` the page shows that target.
#[test]
fn a_post_processing_chain_reads_the_targets_drawn_before() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = root().join("shaders/programs/bloom.das");
    let scene = root().join("shaders/scenes/bloom.toml");
    let bloom = picture(&program, &scene, &dir.path().join("bloom"));
    // Beside the original, so that its image file is found.
    let plain_scene = edited(&scene, dir.path(), "plain.json", |s| {
        s.values.insert("u_bloom_strength".into(), umbrac::scene::ValueSpec::Number(0.0));
    });
    std::fs::copy(root().join("shaders/scenes/bloom_source.png"), dir.path().join("bloom_source.png")).unwrap();
    let plain = picture(&program, &plain_scene, &dir.path().join("plain"));
    let distinct: std::collections::HashSet<&[u8]> = bloom.webgl2.chunks(4).collect();
    assert!(distinct.len() > 100, "only {} colours: the image file was not drawn", distinct.len());
    let brighter = darker_share(&plain.webgl2, &bloom.webgl2, 12);
    assert!(brighter >= 0.01, "only {:.2}% of the pixels are brighter with the bloom", brighter * 100.0);
    assert_eq!(darker_share(&bloom.webgl2, &plain.webgl2, 6), 0.0, "the bloom only adds light");

    // `output` naming a target: the bright pass's, scaled to the canvas;
    // dark but for the image's bright spots.
    let bright_scene = edited(&scene, dir.path(), "bright.json", |s| s.output = "bright".into());
    let bright = picture(&program, &bright_scene, &dir.path().join("bright"));
    let dark = bright.webgl2.chunks(4).filter(|p| p[..3].iter().map(|&c| c as u32).sum::<u32>() < 30).count();
    let share = dark as f64 / (bright.webgl2.len() / 4) as f64;
    assert!((0.8..1.0).contains(&share), "{:.1}% of the bright target is dark", share * 100.0);
}

/// shaders/scenes/deferred.toml: a G-buffer pass drawing into three colour
/// targets at once (`color` as a list: WebGL2's drawBuffers, WebGPU's
/// three pipeline targets), then a lighting pass reading them. Alike on
/// both APIs and as `umbrac render --backend webgl2` draws it; with
/// `output = "normal"` the page shows location 1's target, which differs
/// from location 0's (`output = "albedo"`) at over 30 % of the pixels.
#[test]
fn a_gbuffer_pass_draws_into_several_targets() {
    if !browser_ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = root().join("shaders/programs/deferred.das");
    let scene = root().join("shaders/scenes/deferred.toml");
    let lit = picture_at(&program, &scene, 1.0, &dir.path().join("lit"));
    assert_like_native_at(&program, &scene, &lit, 1.0, &dir.path().join("lit"));
    let shown = |name: &str| {
        let file = edited(&scene, dir.path(), &format!("{name}.json"), |s| s.output = name.into());
        picture_at(&program, &file, 1.0, &dir.path().join(name)).webgl2
    };
    let (albedo, normal) = (shown("albedo"), shown("normal"));
    let differ = albedo.chunks(4).zip(normal.chunks(4)).filter(|(a, n)| (0..3).any(|k| (a[k] as i32 - n[k] as i32).abs() > 8)).count();
    assert!(differ * 10 >= 3 * albedo.len() / 4, "the normal target differs from the albedo target at only {differ} pixels");
}
