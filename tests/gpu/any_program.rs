//! Any program drawn from a scene (`umbrac::scene`, `render::plan::scene_file`):
//! every program of daslang's twelve GL tutorials with its inferred scene on
//! every consumer, the same plan on each, compared pairwise; a scene file
//! with two passes, its second reading what the first drew; the CLI.
//! The tutorials are read from `../shared/reference/daslang-tutorials`.

use std::path::{Path, PathBuf};

use umbrac::render::command::any::{self, DELTA};
use umbrac::render::consumers::{Programs, Status};
use umbrac::render::plan::scene_file::{FrameInputs, ScenePlanner};
use umbrac::scene::{infer, Scene};

use crate::support::{self as ci, gpu};

fn tutorials() -> Option<Vec<PathBuf>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/daslang-tutorials");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).ok()?.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| x == "das")).collect();
    files.sort();
    (files.len() == 12).then_some(files)
}

/// The share of pixels (any channel off by more than [`DELTA`]/255) two
/// consumers may disagree on for a tutorial program: rasterisation and
/// the drivers' transcendental functions differ in the last bits, which a
/// chaotic shader (the Mandelbrot set's edge, an SDF's march) can amplify
/// at a few pixels.
const TUTORIAL_SHARE: f64 = 0.03;

/// The frame's time: 02's zoom is shallowest at 0, where its picture is
/// least chaotic.
const TIME: f32 = 0.0;

/// The programs the runner's scenes cannot draw yet, and why (checked: the
/// inference says so): 07's transform-feedback stage.
const NOT_DRAWN: [(&str, &str); 1] = [("sim_src", "gl_Position")];

/// Whether two consumers draw points alike: the GL family honours
/// `gl_PointSize` (sprites), WebGPU's points are one pixel (wgpu's
/// Vulkan and GL backends alike), so a point program's pictures are
/// compared within each family only.
fn same_point_family(a: &str, b: &str) -> bool {
    let gl = |c: &str| matches!(c, "gl330" | "gles300" | "gl430" | "webgl2");
    gl(a) == gl(b)
}

/// Fragment programs whose pictures are not portable, so that consumers
/// need not agree: their noise is `fract(sin(dot(p, k)) * 43758.5453)` of
/// arguments in the thousands, where GLSL and WGSL leave `sin`'s precision
/// to the implementation (lavapipe, llvmpipe's GL and SwiftShader differ
/// at about half the pixels of the SSAO pass). They must still draw on
/// every consumer.
const NOT_PORTABLE: [(&str, &str); 2] = [("10_deferred.das", "ssao_fs"), ("12_gltf.das", "ssao_fs")];

#[test]
fn every_tutorial_program_draws_alike_on_every_consumer() {
    let Some(files) = tutorials() else {
        ci::skip("../shared/reference/daslang-tutorials is not here (the 12 GL tutorials)");
        return;
    };
    let (w, h) = (48, 36);
    let mut drawn = 0;
    let mut refused = Vec::new();
    let mut report = String::new();
    let mut failures = Vec::new();
    // Every program's scene first, then every frame drawn (WebGL2's in one browser).
    let mut all_programs = Vec::new();
    let mut scenes = Vec::new();
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let c = umbrac::compile_file(file, &umbrac::Options::default());
        let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{name}:\n{}", c.render_diagnostics()));
        all_programs.push(Programs::from_compiled(&name, compiled).unwrap());
        for (vs, fs) in infer::programs(&compiled.reflection) {
            let label = format!("{name} {vs}+{fs}");
            match Scene::infer_program(&compiled.reflection, &vs, &fs) {
                Ok(scene) => {
                    let planner = ScenePlanner::new(&label, scene, &compiled.reflection, None).unwrap();
                    scenes.push((name.clone(), vs, fs, all_programs.len() - 1, planner));
                }
                Err(e) => refused.push((vs.clone(), e.0.clone())),
            }
        }
    }
    let f = FrameInputs { time: TIME, frame: 0, width: w, height: h };
    let jobs: Vec<_> = scenes.iter().map(|(_, _, _, p, planner)| (&all_programs[*p], planner, f)).collect();
    let comparisons = any::compare_many(&jobs).unwrap();
    for ((name, vs, fs, _, planner), cmp) in scenes.iter().zip(&comparisons) {
        let label = &planner.label;
        let mut images = 0;
        for (c, s) in &cmp.results {
            match s {
                Status::Rendered { image, .. } => {
                    images += 1;
                    let out = gpu::artifacts_dir("any-program").join(format!("{}_{vs}_{fs}.{}.png", name.trim_end_matches(".das"), c.name()));
                    umbrac::render::image_ops::save_png(image, &out).unwrap();
                }
                Status::Unavailable { why, .. } => ci::skip(format!("{}: {why}", c.name())),
                Status::Failed(e) => failures.push(format!("{label} on {}: {e}", c.name())),
            }
        }
        for (a, b, d) in &cmp.pairs {
            report.push_str(&format!("{label}: {} vs {}: {:.4} over, max {}\n", a.name(), b.name(), d.fraction_over, d.max));
        }
        let points = planner.scene.passes.iter().flat_map(|p| &p.draws).any(|d| d.primitive == umbrac::scene::Primitive::Points);
        let worst = cmp.pairs.iter().filter(|(a, b, _)| !points || same_point_family(a.name(), b.name())).max_by(|x, y| x.2.fraction_over.total_cmp(&y.2.fraction_over));
        let portable = !NOT_PORTABLE.contains(&(name.as_str(), fs.as_str()));
        if let Some((a, b, d)) = worst.filter(|(_, _, d)| portable && d.fraction_over > TUTORIAL_SHARE) {
            failures.push(format!(
                "{label}: {} and {} differ at {} of {} pixels (over {DELTA}/255, max {}); allowed {:.1} %\n{}",
                a.name(),
                b.name(),
                d.over,
                d.pixels,
                d.max,
                100.0 * TUTORIAL_SHARE,
                any::table(&cmp.pairs)
            ));
        }
        assert!(images > 0 || cmp.results.iter().all(|(_, s)| matches!(s, Status::Unavailable { .. })));
        drawn += 1;
    }
    eprint!("{report}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!("{drawn} tutorial programs drawn on every consumer; not drawn: {refused:?}");
    assert_eq!(refused.len(), NOT_DRAWN.len(), "{refused:?}");
    for ((vs, why), (want_vs, want_why)) in refused.iter().zip(NOT_DRAWN) {
        assert!(vs == want_vs && why.contains(want_why), "{vs}: {why}");
    }
    assert_eq!(drawn, 30);
}

/// Tutorial 06's skybox with its inferred scene (the built-in sky cube
/// map, the camera looking 10 degrees up, no depth test): on every
/// consumer at least a quarter of the pixels are sky (blue the largest
/// channel, above 150) and at least a tenth ground (red or green the
/// largest); and its mirror sphere, reading the same cube map along
/// reflected rays, is no flat picture. Agreement between consumers is
/// `every_tutorial_program_draws_alike_on_every_consumer`'s.
#[test]
fn the_skybox_shows_its_sky_on_every_consumer() {
    let Some(files) = tutorials() else {
        ci::skip("../shared/reference/daslang-tutorials is not here");
        return;
    };
    let file = files.iter().find(|f| f.ends_with("06_skybox.das")).unwrap();
    let c = umbrac::compile_file(file, &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("06_skybox.das", compiled).unwrap();
    let plan = |vs: &str, fs: &str| ScenePlanner::new(vs, Scene::infer_program(&compiled.reflection, vs, fs).unwrap(), &compiled.reflection, None).unwrap();
    let (sky, sphere) = (plan("skybox_vs", "skybox_fs"), plan("scene_vs", "sphere_fs"));
    let f = FrameInputs { time: 0.0, frame: 0, width: 64, height: 48 };
    let both = any::compare_many(&[(&programs, &sky, f), (&programs, &sphere, f)]).unwrap();
    for ((c, s), (_, m)) in both[0].results.iter().zip(&both[1].results) {
        let (Some(s), Some(m)) = (s.image(), m.image()) else {
            for st in [s, m] {
                match st {
                    Status::Unavailable { why, .. } => ci::skip(format!("{}: {why}", c.name())),
                    other => assert!(other.image().is_some(), "{}: {other:?}", c.name()),
                }
            }
            continue;
        };
        let out = gpu::artifacts_dir("any-program").join(format!("skybox.{}.png", c.name()));
        umbrac::render::image_ops::save_png(s, &out).unwrap();
        let sky_px = s.pixels().filter(|p| p[2] > 150 && p[2] >= p[0] && p[2] >= p[1]).count();
        let ground = s.pixels().filter(|p| p[2] < p[0].max(p[1])).count();
        let n = (64 * 48) as usize;
        assert!(sky_px * 4 >= n && ground * 10 >= n, "{}: {sky_px} sky and {ground} ground pixels of {n} ({})", c.name(), out.display());
        let colours: std::collections::HashSet<[u8; 4]> = m.pixels().map(|p| p.0).collect();
        assert!(colours.len() > 50, "{}: the mirror sphere has {} colours", c.name(), colours.len());
    }
    for (x, y, d) in both.iter().flat_map(|c| &c.pairs) {
        assert!(d.fraction_over <= TUTORIAL_SHARE, "{} vs {}: {:.4}", x.name(), y.name(), d.fraction_over);
    }
}

const TWO_PASS_PROGRAM: &str = "var @in a_pos : float3
var @in a_normal : float3
var @in q_pos : float2
var @uniform u_mvp : float4x4
var @uniform @stage = 0 u_src : sampler2D
var @inout v_normal : float3
var @inout v_uv : float2
var @out f_color : float4
[vertex_program]
def scene_vs {
    v_normal = a_normal
    gl_Position = u_mvp * float4(a_pos, 1.0)
}
[fragment_program]
def scene_fs {
    f_color = float4(v_normal * 0.5 + float3(0.5), 1.0)
}
[vertex_program]
def post_vs {
    v_uv = q_pos * 0.5 + float2(0.5)
    gl_Position = float4(q_pos, 0.0, 1.0)
}
[fragment_program]
def post_fs {
    f_color = float4(float3(1.0) - texture(u_src, v_uv).xyz, 1.0)
}
";

const TWO_PASS_SCENE: &str = r#"
[[targets]]
name = "scene"
format = "rgba8"

[[targets]]
name = "depth"
format = "depth32float"

[[passes]]
name = "scene"
vertex = "scene_vs"
fragment = "scene_fs"
color = "scene"
depth = "depth"
clear = [0.0, 0.0, 0.0, 1.0]
values = { u_mvp = "model_view_projection" }
[[passes.draws]]
mesh = "sphere"
attributes = { a_pos = "position", a_normal = "normal" }

[[passes]]
name = "invert"
vertex = "post_vs"
fragment = "post_fs"
color = "screen"
samplers = { u_src = { texture = "scene", filter = "nearest" } }
[[passes.draws]]
mesh = "fullscreen_triangle"
attributes = { q_pos = "position" }
"#;

/// A scene file with two passes: the first draws a sphere's normals into a
/// target, the second draws that target inverted on the screen. Read back
/// with `output = "scene"`, the first pass's picture; with `screen`, its
/// inverse, texel for texel (nearest filtering at the same size), within
/// 1/255; on every consumer.
#[test]
fn a_two_pass_scene_file_feeds_the_first_pass_to_the_second() {
    let c = umbrac::compile_source("two_pass.das", TWO_PASS_PROGRAM, &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("two_pass.das", compiled).unwrap();
    let screen = Scene::parse("two_pass.toml", TWO_PASS_SCENE).unwrap();
    let mut first = screen.clone();
    first.output = "scene".into();
    let f = FrameInputs { time: 0.7, frame: 0, width: 40, height: 30 };
    let (pa, pb) = (ScenePlanner::new("screen", screen, &compiled.reflection, None).unwrap(), ScenePlanner::new("first pass", first, &compiled.reflection, None).unwrap());
    let mut both = any::compare_many(&[(&programs, &pa, f), (&programs, &pb, f)]).unwrap();
    let (b, a) = (both.pop().unwrap(), both.pop().unwrap());
    for ((c, sa), (_, sb)) in a.results.iter().zip(&b.results) {
        let (Some(inverted), Some(scene)) = (sa.image(), sb.image()) else {
            ci::skip(format!("{}: {:?}", c.name(), sa));
            continue;
        };
        let lit = scene.pixels().filter(|p| p[0] > 20 || p[1] > 20 || p[2] > 20).count();
        assert!(lit > 80 && lit < 400, "{}: the sphere covers {lit} of 1200 pixels (about 115: radius 0.5 at 3 units, 45 degrees)", c.name());
        let wrong = scene.pixels().zip(inverted.pixels()).filter(|(s, i)| (0..3).any(|k| (255 - s[k] as i32 - i[k] as i32).abs() > 1)).count();
        assert_eq!(wrong, 0, "{}: the second pass's pixels are not the first's inverted", c.name());
    }
    for (x, y, d) in a.pairs.iter().chain(&b.pairs) {
        assert!(d.fraction_over <= 0.01, "{} vs {}: {:.3}", x.name(), y.name(), d.fraction_over);
    }
}

/// `umbrac render` draws a tutorial that is no shadow scene (it used to
/// answer "does not fit the shadow scene's interface"), and
/// `--compare-backends` on it prints the table of agreement.
#[test]
fn the_cli_draws_any_program() {
    let Some(files) = tutorials() else {
        ci::skip("../shared/reference/daslang-tutorials is not here");
        return;
    };
    let sdf = files.iter().find(|f| f.ends_with("03_sdf.das")).unwrap().display().to_string();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sdf.png");
    let run = crate::support::umbrac(&["render", &sdf, "--size", "64x48", "--time", "1", "--out", out.to_str().unwrap()], dir.path());
    let stderr = String::from_utf8_lossy(&run.stderr);
    if stderr.contains("unavailable") || stderr.contains("no Vulkan") {
        ci::skip(format!("vulkan: {stderr}"));
        return;
    }
    assert!(run.status.success(), "{stderr}");
    let img = image::open(&out).unwrap().to_rgba8();
    assert_eq!(img.dimensions(), (64, 48));
    let distinct: std::collections::HashSet<[u8; 4]> = img.pixels().map(|p| p.0).collect();
    assert!(distinct.len() > 20, "a flat picture: {} colours", distinct.len());
    // A lone fragment program gets a full-screen vertex program: its uv
    // runs from 0 at the bottom left to 1 at the top right.
    let lone = dir.path().join("lone.das");
    std::fs::write(&lone, "var @inout v_uv : float2\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(v_uv, 0.0, 1.0)\n}\n").unwrap();
    let run = crate::support::umbrac(&["render", lone.to_str().unwrap(), "--size", "32x32", "--out", out.to_str().unwrap()], dir.path());
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let img = image::open(&out).unwrap().to_rgba8();
    let (bl, tr) = (img.get_pixel(0, 31), img.get_pixel(31, 0));
    assert!(bl[0] < 10 && bl[1] < 10 && tr[0] > 245 && tr[1] > 245, "bottom left {bl:?}, top right {tr:?}");
    // A scene file that does not fit the program: the place in the file.
    let scene = dir.path().join("bad.toml");
    std::fs::write(&scene, "[[passes]]\nname = \"p\"\nvertex = \"vs_mian\"\nfragment = \"fs_main\"\ncolor = \"screen\"\ndraws = []\n").unwrap();
    let bad = crate::support::umbrac(&["render", &sdf, "--scene", scene.to_str().unwrap(), "--out", out.to_str().unwrap()], dir.path());
    let err = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1), "{err}");
    assert!(err.contains("bad.toml:3:10: the program has no vertex entry point `vs_mian`") && err.contains("^"), "{err}");
    let bad = crate::support::umbrac(&["render", &sdf, "--program", "nope_vs", "--out", out.to_str().unwrap()], dir.path());
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("vs_main:fs_main"), "{}", String::from_utf8_lossy(&bad.stderr));
}

/// `shaders/scenes/shadow.toml`: the shadow program drawn from a scene file
/// (the sun's depth pass, then the lit pass comparing against it) agrees
/// on every consumer within 1 % of the pixels, and its shadow is there:
/// against the same scene with the depth pass drawing nothing (every
/// compare passes), at least 2 % of the pixels are darker by more than
/// 8/255 and none is brighter.
#[test]
fn the_shadow_scene_as_a_file_casts_its_shadow_on_every_consumer() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let c = umbrac::compile_file(&root.join("shaders/shadow.das"), &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("shadow.das", compiled).unwrap();
    let file = root.join("shaders/scenes/shadow.toml");
    let scene = Scene::parse("shadow.toml", &std::fs::read_to_string(&file).unwrap()).unwrap();
    let mut lit = scene.clone();
    lit.passes[0].draws.clear();
    let f = FrameInputs { time: 0.0, frame: 0, width: 64, height: 48 };
    let (ps, pl) = (ScenePlanner::new("shadow.toml", scene, &compiled.reflection, None).unwrap(), ScenePlanner::new("lit", lit, &compiled.reflection, None).unwrap());
    let mut both = any::compare_many(&[(&programs, &ps, f), (&programs, &pl, f)]).unwrap();
    let (unshadowed, shadowed) = (both.pop().unwrap(), both.pop().unwrap());
    for (x, y, d) in &shadowed.pairs {
        assert!(d.fraction_over <= 0.01, "{} vs {}: {:.4}\n{}", x.name(), y.name(), d.fraction_over, any::table(&shadowed.pairs));
    }
    for ((c, s), (_, l)) in shadowed.results.iter().zip(&unshadowed.results) {
        let (Some(s), Some(l)) = (s.image(), l.image()) else {
            ci::skip(format!("{}: {s:?}", c.name()));
            continue;
        };
        let luma = |p: &image::Rgba<u8>| p[0] as i32 + p[1] as i32 + p[2] as i32;
        let darker = s.pixels().zip(l.pixels()).filter(|(a, b)| luma(b) - luma(a) > 3 * DELTA as i32).count();
        let brighter = s.pixels().zip(l.pixels()).filter(|(a, b)| luma(a) - luma(b) > 3 * DELTA as i32).count();
        let out = gpu::artifacts_dir("any-program").join(format!("shadow_scene_file.{}.png", c.name()));
        umbrac::render::image_ops::save_png(s, &out).unwrap();
        assert!(darker * 50 >= (64 * 48) as usize && brighter == 0, "{}: {darker} pixels in shadow, {brighter} brighter ({})", c.name(), out.display());
    }
}

/// The page makes the runner's texels: web/preview/textures.js (run in
/// node) gives the bytes of `Texture::pattern_texels` for a sky cube map,
/// a 3D checker and a noise array, byte for byte.
#[test]
fn the_page_makes_the_runners_texels_for_every_kind() {
    use umbrac::scene::{Pattern, Texture, TextureKind};
    let web = Path::new(env!("CARGO_MANIFEST_DIR")).join("web/preview/textures.js");
    let cases = [(Pattern::Sky, TextureKind::Cube, [16, 16], 1, "sky", "cube"), (Pattern::Checker, TextureKind::D3, [16, 8], 5, "checker", "3d"), (Pattern::Noise, TextureKind::D2Array, [8, 8], 7, "noise", "2d_array")];
    for (pattern, kind, size, layers, name, js_kind) in cases {
        let script = format!(
            "const t = await import({:?}); const x = t.texels('{name}', {{ kind: '{js_kind}', size: [{}, {}], layers: {layers} }}); process.stdout.write(Buffer.from(x.data).toString('hex'));",
            format!("file://{}", web.display()),
            size[0],
            size[1]
        );
        let run = std::process::Command::new("node").args(["--input-type=module", "-e", &script]).output();
        let Some(run) = ci::or_skip(run, "node runs web/preview/textures.js") else { return };
        assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
        let t = Texture { name: "t".into(), pattern: Some(pattern), image: None, size, kind, layers };
        let (want, _) = t.pattern_texels(pattern);
        let want: String = want.iter().map(|b| format!("{b:02x}")).collect();
        assert!(String::from_utf8_lossy(&run.stdout) == want, "{name} {js_kind}: the page's texels differ from the runner's");
    }
}

/// `shaders/programs/instanced.das` places each instance from a uniform
/// table of structs (`u_instances : Instance[64]`, read by
/// `gl_InstanceID`). Its inferred scene fills the table from the instance
/// grid (`u_instances[i].offset_scale`, `.color`, by path): it drew black
/// while the table was left zero (every instance scaled to nothing). On
/// every consumer at least 5 % of the pixels are lit, and the consumers
/// agree as the tutorials do.
#[test]
fn the_instanced_program_draws_its_instance_table_on_every_consumer() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let c = umbrac::compile_file(&root.join("shaders/programs/instanced.das"), &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("instanced.das", compiled).unwrap();
    let scene = Scene::infer(&compiled.reflection).unwrap();
    assert!(scene.values.contains_key("u_instances[8].offset_scale") && scene.values.contains_key("u_instances[0].color"), "{:?}", scene.values.keys());
    let planner = ScenePlanner::new("instanced.das", scene, &compiled.reflection, None).unwrap();
    let f = FrameInputs { time: 0.5, frame: 0, width: 64, height: 48 };
    let cmp = any::compare_many(&[(&programs, &planner, f)]).unwrap().pop().unwrap();
    for (c, img, out) in pictures(&cmp, "instanced") {
        let lit = img.pixels().filter(|p| p[0] > 20 || p[1] > 20 || p[2] > 20).count();
        assert!(lit * 20 >= (64 * 48) as usize, "{}: {lit} lit pixels of {} ({})", c.name(), 64 * 48, out.display());
    }
    for (x, y, d) in &cmp.pairs {
        assert!(d.fraction_over <= TUTORIAL_SHARE, "{} vs {}: {:.4}\n{}", x.name(), y.name(), d.fraction_over, any::table(&cmp.pairs));
    }
}

/// Each consumer's picture of one comparison, saved as
/// `STEM.CONSUMER.png` under the test artifacts; a consumer this machine
/// lacks is skipped (a failure with `CI=true`), one that fails panics.
fn pictures<'a>(cmp: &'a any::Comparison, stem: &str) -> Vec<(&'a umbrac::render::Consumer, &'a image::RgbaImage, PathBuf)> {
    let mut out = Vec::new();
    for (c, s) in &cmp.results {
        match s {
            Status::Rendered { image, .. } => {
                let path = gpu::artifacts_dir("any-program").join(format!("{stem}.{}.png", c.name()));
                umbrac::render::image_ops::save_png(image, &path).unwrap();
                out.push((c, image, path));
            }
            Status::Unavailable { why, .. } => ci::skip(format!("{}: {why}", c.name())),
            Status::Failed(e) => panic!("{}: {e}", c.name()),
        }
    }
    out
}

/// Point sprites (tutorial 07's render program: `gl_PointSize` 9, a disc
/// cut from `gl_PointCoord`) drawn from the sphere's 425 vertices: on the
/// GL consumers each point is a disc 9 pixels wide (they overlap), so at
/// least 1.5x as many pixels are touched (any channel above 0; measured
/// 570 against 291 at 96 x 72) as on the WebGPU ones, whose points are one
/// pixel; each family agrees within itself.
#[test]
fn point_sprites_are_sized_on_gl_and_single_pixels_on_webgpu() {
    let Some(files) = tutorials() else {
        ci::skip("../shared/reference/daslang-tutorials is not here");
        return;
    };
    let file = files.iter().find(|f| f.ends_with("07_particles.das")).unwrap();
    let c = umbrac::compile_file(file, &umbrac::Options::default());
    let compiled = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let programs = Programs::from_compiled("07_particles.das", compiled).unwrap();
    let scene = Scene::infer_program(&compiled.reflection, "render_vs_src", "render_fs_src").unwrap();
    let planner = ScenePlanner::new("points", scene, &compiled.reflection, None).unwrap();
    let f = FrameInputs { time: 0.0, frame: 0, width: 96, height: 72 };
    let cmp = any::compare_many(&[(&programs, &planner, f)]).unwrap().pop().unwrap();
    let (mut gl_lit, mut one_px) = (Vec::new(), Vec::new());
    for (c, img, _) in pictures(&cmp, "points") {
        let lit = img.pixels().filter(|p| p[0] > 0 || p[1] > 0 || p[2] > 0).count();
        if same_point_family(c.name(), "gl330") { gl_lit.push((c.name(), lit)) } else { one_px.push((c.name(), lit)) }
    }
    eprintln!("lit pixels: GL {gl_lit:?}, WebGPU {one_px:?}");
    for &(g, lg) in &gl_lit {
        assert!(lg > 100, "{g}: {lg} lit pixels");
        for &(w, lw) in &one_px {
            assert!(lw > 100 && 2 * lg >= 3 * lw, "{g}: {lg} lit pixels, {w}: {lw}");
        }
    }
    for (x, y, d) in cmp.pairs.iter().filter(|(a, b, _)| same_point_family(a.name(), b.name())) {
        assert!(d.fraction_over <= TUTORIAL_SHARE, "{} vs {}: {:.4}", x.name(), y.name(), d.fraction_over);
    }
}
