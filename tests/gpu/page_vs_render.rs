//! The page of `umbrac preview` against `umbrac render` (docs/preview.md,
//! "The page against `umbrac render`"): several GL tutorials and a program
//! of the project, drawn by the page at `?time=1` on its 480x360 canvases
//! (WebGL2 and WebGPU), and rendered natively at `--time 1 --size 480x360`
//! with `--backend webgl2` (the same GLSL ES in the same chromium, by the
//! native runner's frame plan) and on Vulkan (the WGSL on lavapipe). Same
//! program, same inputs: the pictures agree within the stated tolerance.

use std::path::{Path, PathBuf};
use std::process::Command;

use image::RgbaImage;

use crate::preview::{browser_ready, drive_with};
use crate::support::preview::PreviewServer;
use crate::support::{gpu, skip};

/// The page's canvases (web/preview/index.html), and the time it is held at.
const WIDTH: u32 = 480;
const HEIGHT: u32 = 360;
const TIME: &str = "1";

/// A pixel differs when a channel is more than this far apart (of 255):
/// above the 8-bit rounding and filtering weights two rasterizers may
/// differ by on a smooth surface.
const CHANNEL: i32 = 8;
/// Share of pixels that may differ against `--backend webgl2`: the same
/// GLSL ES in the same browser; only the host's numbers differ (f32
/// matrices made in Rust and in JavaScript), which can move a triangle's
/// edge across a pixel centre here and there (seen: 0 or 1 pixel of
/// 172,800). 0.02% is 35 pixels.
const WEBGL2_SHARE: f64 = 0.0002;
/// Share of pixels that may differ against Vulkan: lavapipe and
/// SwiftShader place some edge pixels of a triangle differently (seen:
/// 0.010 to 0.023%, 17 to 40 pixels). A real difference is far more: the
/// texture clamped instead of repeated at a face's edges was 0.5% of
/// lit_cube's picture and 1.5% of tutorial 04's.
const VULKAN_SHARE: f64 = 0.001;

/// A program, and the `--program VS:FS` that makes `umbrac render` draw
/// the scene the page draws where it would otherwise pick another
/// (tutorial 08 fits the shadow scene's interface, which render draws).
struct Case {
    name: &'static str,
    path: PathBuf,
    program: Option<&'static str>,
}

fn cases() -> Option<Vec<Case>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tutorials = root.join("../shared/reference/daslang-tutorials");
    let tutorial = |name: &'static str, program| Case { name, path: tutorials.join(name), program };
    let cases = vec![
        // A full-screen program (time and aspect by convention).
        tutorial("03_sdf.das", None),
        // The textured cube with depth, its uv scrolled past 1 (repeat).
        tutorial("04_cube.das", None),
        // The instance grid.
        tutorial("05_instancing.das", None),
        // A shadow sampler over a depth target that a pass clears.
        tutorial("08_shadow.das", Some("main_vs:main_fs")),
        // A G-buffer: colour output 0 on the page and in render.
        tutorial("10_deferred.das", None),
        Case { name: "lit_cube.das", path: root.join("shaders/programs/lit_cube.das"), program: None },
    ];
    if let Some(missing) = cases.iter().find(|c| !c.path.is_file()) {
        skip(format!("{} is missing", missing.path.display()));
        return None;
    }
    Some(cases)
}

/// `umbrac render` of the case on `backend`, as RGBA rows top first.
fn render(case: &Case, backend: &str, out: &Path) -> RgbaImage {
    let png = out.join(format!("{}.{backend}.png", case.name));
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_umbrac"));
    cmd.arg("render").arg(&case.path).args(["--time", TIME, "--size", &format!("{WIDTH}x{HEIGHT}"), "--backend", backend, "-o"]).arg(&png);
    if let Some(p) = case.program {
        cmd.args(["--program", p]);
    }
    let o = cmd.output().expect("umbrac runs");
    assert!(o.status.success(), "umbrac render {} --backend {backend}: {}", case.name, String::from_utf8_lossy(&o.stderr));
    image::open(&png).unwrap().to_rgba8()
}

/// The page's picture (rows bottom first) as an image, rows top first.
fn page_image(rgba: &[u8]) -> RgbaImage {
    let row = 4 * WIDTH as usize;
    let flipped: Vec<u8> = rgba.chunks(row).rev().flatten().copied().collect();
    RgbaImage::from_raw(WIDTH, HEIGHT, flipped).expect("a 480x360 picture")
}

/// The share of pixels whose colour channels differ by more than CHANNEL,
/// the worst difference, and a picture of where (white: over CHANNEL).
fn compare(a: &RgbaImage, b: &RgbaImage) -> (f64, i32, RgbaImage) {
    assert_eq!(a.dimensions(), b.dimensions());
    let mut over = 0;
    let mut worst = 0;
    let mut map = RgbaImage::new(a.width(), a.height());
    for ((p, q), m) in a.pixels().zip(b.pixels()).zip(map.pixels_mut()) {
        let d = (0..3).map(|c| (p[c] as i32 - q[c] as i32).abs()).max().unwrap();
        worst = worst.max(d);
        let v = if d > CHANNEL {
            over += 1;
            255
        } else {
            (d * 16).min(255) as u8
        };
        *m = image::Rgba([v, v, v, 255]);
    }
    (over as f64 / (a.width() * a.height()) as f64, worst, map)
}

#[test]
fn the_page_draws_what_umbrac_render_draws() {
    let Some(cases) = cases() else { return };
    if !browser_ready() || gpu::vulkan().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let artifacts = gpu::artifacts_dir("page-vs-render");
    // One page, each program saved over the last (one browser start).
    let file = dir.path().join("page.das");
    std::fs::copy(&cases[0].path, &file).unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let server = PreviewServer::start(&file);
    let rest: Vec<String> = cases[1..].iter().map(|c| std::fs::read_to_string(&c.path).unwrap()).collect();
    let steps = drive_with(&server, &format!("time={TIME}"), &file, &rest.iter().map(String::as_str).collect::<Vec<_>>(), &out, None);

    let mut failures = Vec::new();
    for (case, step) in cases.iter().zip(&steps) {
        let s = &step.state;
        assert_eq!(s["ok"], true, "{}: {s}", case.name);
        assert_eq!((s["width"].as_u64(), s["height"].as_u64()), (Some(WIDTH as u64), Some(HEIGHT as u64)), "{}", case.name);
        let gl = page_image(step.webgl2.as_ref().unwrap_or_else(|| panic!("{}: no WebGL2 picture: {s}", case.name)));
        gl.save(artifacts.join(format!("{}.page-webgl2.png", case.name))).unwrap();
        let webgl2 = render(case, "webgl2", &out);
        let vulkan = render(case, "vulkan", &out);
        vulkan.save(artifacts.join(format!("{}.render-vulkan.png", case.name))).unwrap();
        let mut pairs = vec![("page WebGL2", "render webgl2", &gl, &webgl2, WEBGL2_SHARE), ("page WebGL2", "render vulkan", &gl, &vulkan, VULKAN_SHARE)];
        let gpu_picture = step.webgpu.as_deref().map(page_image);
        match &gpu_picture {
            Some(p) => pairs.push(("page WebGPU", "render vulkan", p, &vulkan, VULKAN_SHARE)),
            None => skip(format!("{}: headless chromium drew no WebGPU picture: {}", case.name, s["errors"]["webgpu"])),
        }
        for (page, native, a, b, limit) in pairs {
            let (share, worst, map) = compare(a, b);
            let tag = format!("{}.{}-vs-{}", case.name, page.replace(' ', "-"), native.replace(' ', "-"));
            map.save(artifacts.join(format!("{tag}.diff.png"))).unwrap();
            let pixels = (share * (WIDTH * HEIGHT) as f64).round();
            println!("{}: {page} vs {native}: {:.3}% of the pixels ({pixels}) over {CHANNEL}/255 (limit {:.2}%), worst {worst}", case.name, share * 100.0, limit * 100.0);
            if share > limit {
                failures.push(format!("{tag}: {:.3}% over {CHANNEL}/255 (limit {:.2}%), worst {worst}; pictures in {}", share * 100.0, limit * 100.0, artifacts.display()));
            }
        }
    }
    assert!(failures.is_empty(), "the page and umbrac render differ:\n{}", failures.join("\n"));
}
