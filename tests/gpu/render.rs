//! Render tests: the wgpu image of the shadow scene against the CPU
//! ray-cast reference, at 160 x 120.
//!
//! Without a Vulkan adapter these tests print why and pass, unless the
//! environment says `CI=true`, where they fail.
//!
//! Tolerances (also in docs/runner.md):
//! - a pixel differs when one of its channels differs by more than
//!   `DELTA` = 8 / 255;
//! - at most `MAX_FRACTION` = 0.75 % of the compared pixels may differ.
//!   Pixels showing floor outside the sun's +-4 box (the tutorial's box is
//!   smaller than its +-5 floor, so the shadow map has no data there) are
//!   not compared; the reference marks them;
//! - the shadowed pixels (darker by more than 24/255 in luma than the same
//!   frame rendered with an empty shadow map) of GPU and reference must
//!   overlap with an intersection-over-union of at least `MIN_SHADOW_IOU`
//!   = 0.9.
//!
//! Measured on lavapipe with the hand port: 0.05 - 0.31 % differing
//! (shadow-edge pixels, where 3x3 PCF softens what the reference decides
//! exactly), IoU 0.98 - 0.99. A mirrored shadow measures 23 - 34 % and IoU
//! below 0.13; a missing one 1.3 - 7 % and IoU 0.

use crate::support;

use std::path::Path;

use support::gpu;
use umbrac::render::image_ops::{self, DiffStats};
use umbrac::render::exec::wgpu::{WgpuExecutor, WgpuProgram};
use umbrac::render::{hand, reference, ExecError, FrameParams, SceneExecutor, ShaderCode, ShaderSet, View};
use umbrac::{Conventions, Options, Target};

const W: u32 = 160;
const H: u32 = 120;
const DELTA: u8 = 8;
const MAX_FRACTION: f64 = 0.0075;
const MIN_SHADOW_IOU: f64 = 0.9;
const TIMES: [f32; 4] = [0.5, 2.0, 4.0, 6.0];

struct Check {
    stats: DiffStats,
    iou: f64,
    gpu_centroid: Option<(f64, f64)>,
    ref_centroid: Option<(f64, f64)>,
}

impl Check {
    fn passes(&self) -> bool {
        self.stats.fraction_over <= MAX_FRACTION && self.iou >= MIN_SHADOW_IOU
    }
}

impl std::fmt::Display for Check {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}; shadow IoU {:.3}", self.stats, self.iou)
    }
}

/// Renders frame `t` on the GPU and on the CPU and compares them.
fn check(r: &WgpuExecutor, program: &WgpuProgram, t: f32, name: &str) -> Check {
    let p = FrameParams::new(t, W, H);
    let gpu = r.draw_scene(program, &p).expect("render");
    let gpu_lit = r.draw_scene(program, &p.with_view(View::Lit)).expect("render lit");
    let reference = reference::render_frame(&p);
    let ref_lit = reference::render(&p.with_view(View::Lit));
    let skip = &reference.outside_shadow_map;
    let stats = image_ops::diff_masked(&gpu, &reference.image, DELTA, Some(skip));
    let inside = |m: Vec<bool>| m.into_iter().zip(skip).map(|(m, s)| m && !s).collect::<Vec<_>>();
    let gpu_shadow = inside(image_ops::shadow_mask(&gpu, &gpu_lit));
    let ref_shadow = inside(image_ops::shadow_mask(&reference.image, &ref_lit));
    let c = Check {
        stats,
        iou: image_ops::iou(&gpu_shadow, &ref_shadow),
        gpu_centroid: image_ops::centroid(&gpu_shadow, W),
        ref_centroid: image_ops::centroid(&ref_shadow, W),
    };
    let out = gpu::artifacts_dir("render-tests").join(format!("{name}_t{t}.png"));
    let diff = image_ops::diff_image(&gpu, &reference.image, Some(skip));
    image_ops::save_png(&image_ops::side_by_side(&[&gpu, &reference.image, &diff]), &out).unwrap();
    eprintln!("{name} t={t}: {c} ({})", out.display());
    c
}

/// The project's scene program.
const SCENE: &str = include_str!("../../shaders/shadow.das");

/// Compiles DSL text in process and picks the output the GPU gets.
fn compiled(name: &str, text: &str, via: Target, conventions: Conventions) -> ShaderSet {
    let opts = Options { targets: vec![via], conventions, ..Default::default() };
    let c = umbrac::compile_source(name, text, &opts);
    let Some(result) = c.result.as_ref().filter(|_| !c.has_errors()) else {
        panic!("{name} did not compile:\n{}", c.render_diagnostics());
    };
    ShaderSet::from_compiled(name, result, via).unwrap()
}

fn scene(via: Target) -> ShaderSet {
    compiled("shaders/shadow.das", SCENE, via, Conventions::Portable)
}

#[test]
fn compiled_program_matches_the_reference() {
    let Some(r) = gpu::vulkan() else { return };
    let program = r.prepare_scene(&scene(Target::Wgsl)).unwrap();
    for t in TIMES {
        let c = check(r, &program, t, "compiled");
        assert!(c.passes(), "t = {t}: {c}");
    }
}

#[test]
fn compiled_spirv_and_wgsl_give_the_same_image() {
    let Some(r) = gpu::vulkan() else { return };
    if !r.supports_passthrough() {
        support::skip(format!("{} lacks PASSTHROUGH_SHADERS", r.adapter_name()));
        return;
    }
    let wgsl = r.prepare_scene(&scene(Target::Wgsl)).unwrap();
    let spirv = r.prepare_scene(&scene(Target::Spirv)).unwrap();
    for t in [0.5, 3.0] {
        let p = FrameParams::new(t, W, H);
        let a = r.draw_scene(&wgsl, &p).unwrap();
        let b = r.draw_scene(&spirv, &p).unwrap();
        let stats = image_ops::diff(&a, &b, 1);
        eprintln!("compiled wgsl vs spirv t={t}: {stats}");
        assert!(stats.fraction_over <= 0.001, "t = {t}: {stats}");
    }
    let c = check(r, &spirv, 2.0, "compiled_spirv");
    assert!(c.passes(), "{c}");
}

#[test]
fn native_conventions_fail_the_check() {
    let Some(r) = gpu::vulkan() else { return };
    // GL-convention code compiled without the clip-space adaptation: the
    // shadow map's near half is clipped and its rows are mirrored.
    let set = compiled("shaders/shadow.das", SCENE, Target::Wgsl, Conventions::Native);
    assert_eq!(set.reflection.as_ref().unwrap().conventions, "native");
    let program = r.prepare_scene(&set).unwrap();
    for t in TIMES {
        let c = check(r, &program, t, "compiled_native");
        assert!(!c.passes(), "native conventions at t = {t} passed: {c}");
    }
}

#[test]
fn reordered_and_struct_uniforms_render_the_same() {
    let Some(r) = gpu::vulkan() else { return };
    let p = FrameParams::new(2.0, W, H);
    let usual = r.render_scene(&scene(Target::Wgsl), &p).unwrap();

    // The uniform declarations in reverse order: every binding moves.
    let lines: Vec<&str> = SCENE.lines().collect();
    let is_uniform = |l: &&str| l.starts_with("var @uniform");
    let uniforms: Vec<&str> = lines.iter().copied().filter(is_uniform).collect();
    let first = lines.iter().position(is_uniform).unwrap();
    let mut reordered: Vec<&str> = lines.iter().copied().filter(|l| !is_uniform(l)).collect();
    for (i, u) in uniforms.iter().rev().enumerate() {
        reordered.insert(first + i, u);
    }
    let reordered = reordered.join("\n");
    let set = compiled("reordered.das", &reordered, Target::Wgsl, Conventions::Portable);
    assert_eq!(set.reflection.as_ref().unwrap().uniform_buffers[0].members[0].name, "u_is_floor");
    assert_eq!(set.reflection.as_ref().unwrap().samplers[0].texture_binding, 0, "the shadow map now comes first");
    let image = r.render_scene(&set, &p).unwrap();
    assert_eq!(image_ops::diff(&usual, &image, 0).over, 0, "reordered uniforms changed the picture");
    // The same program as SPIR-V handed to Vulkan unchanged: wgpu numbers
    // Vulkan descriptors by their place in the layout, so the shadow pass
    // (which uses bindings 7 and 8 only) needs every binding in its layout;
    // with only its own two it drew an empty shadow map.
    if r.supports_passthrough() {
        let set = compiled("reordered.das", &reordered, Target::Spirv, Conventions::Portable);
        let image = r.render_scene(&set, &p).unwrap();
        let stats = image_ops::diff(&usual, &image, 0);
        assert_eq!(stats.over, 0, "reordered uniforms through SPIR-V changed the picture: {stats}");
    }

    // The fragment program's values as one struct block, members in
    // another order than their uses: bound by member name and offset.
    let mut text = SCENE.to_string();
    for name in ["u_light_dir", "u_cam_pos", "u_is_floor"] {
        let decl = SCENE.lines().find(|l| l.starts_with(&format!("var @uniform {name} "))).unwrap();
        text = text.replace(decl, "");
        text = text.replace(name, &format!("lighting.{name}"));
    }
    let text = format!(
        "struct Lighting {{\n    u_is_floor : float\n    u_cam_pos : float3\n    u_light_dir : float3\n}}\nvar @uniform lighting : Lighting\n{text}"
    )
    .replace("lighting.u_is_floor : float", "u_is_floor : float")
    .replace("lighting.u_cam_pos : float3", "u_cam_pos : float3")
    .replace("lighting.u_light_dir : float3", "u_light_dir : float3");
    let set = compiled("struct.das", &text, Target::Wgsl, Conventions::Portable);
    let block = set.reflection.as_ref().unwrap().uniform_buffers.iter().find(|b| b.name == "lighting").expect("a `lighting` block");
    assert_eq!(block.members.len(), 3);
    let image = r.render_scene(&set, &p).unwrap();
    let stats = image_ops::diff(&usual, &image, 0);
    assert_eq!(stats.over, 0, "a struct block changed the picture: {stats}");
}

#[test]
fn the_tutorial_itself_renders() {
    let Some(r) = gpu::vulkan() else { return };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/08_shadow.das");
    let Ok(text) = std::fs::read_to_string(&path) else {
        eprintln!("skipping: {} is not here", path.display());
        return;
    };
    let program = r.prepare_scene(&compiled("08_shadow.das", &text, Target::Wgsl, Conventions::Portable)).unwrap();
    for t in [1.0, 4.0] {
        let c = check(r, &program, t, "tutorial");
        assert!(c.passes(), "t = {t}: {c}");
    }
}

#[test]
fn hand_port_matches_the_reference() {
    let Some(r) = gpu::vulkan() else { return };
    let program = r.prepare_scene(&hand::shader_set()).unwrap();
    for t in TIMES {
        let c = check(r, &program, t, "hand");
        assert!(c.passes(), "t = {t}: {c}");
    }
}

#[test]
fn mirrored_or_missing_shadows_fail_the_same_check() {
    let Some(r) = gpu::vulkan() else { return };
    for variant in [hand::Variant::NoYFlip, hand::Variant::NoZRemap, hand::Variant::Native] {
        let program = r.prepare_scene(&variant.shader_set()).unwrap();
        for t in TIMES {
            let c = check(r, &program, t, &format!("{variant:?}"));
            assert!(!c.passes(), "{variant:?} at t = {t} passed: {c}");
        }
    }
}

#[test]
fn lighting_alone_matches_the_reference() {
    let Some(r) = gpu::vulkan() else { return };
    // No shadows: only rasterisation and float rounding can differ.
    for t in [1.0, 5.0] {
        let p = FrameParams::new(t, W, H).with_view(View::Lit);
        let gpu = r.render_scene(&hand::shader_set(), &p).unwrap();
        let cpu = reference::render(&p);
        let stats = image_ops::diff(&gpu, &cpu, 2);
        eprintln!("lit t={t}: {stats}");
        assert!(stats.fraction_over <= 0.002, "t = {t}: {stats}");
    }
}

#[test]
fn shadow_follows_the_sun() {
    let Some(r) = gpu::vulkan() else { return };
    let program = r.prepare_scene(&scene(Target::Wgsl)).unwrap();
    let times = [0.0, 1.5, 3.0, 4.5, 6.0];
    let checks: Vec<Check> = times.iter().map(|&t| check(r, &program, t, "sun")).collect();
    let mut previous: Option<((f64, f64), (f64, f64))> = None;
    for (t, c) in times.iter().zip(&checks) {
        let g = c.gpu_centroid.unwrap_or_else(|| panic!("no GPU shadow at t = {t}"));
        let e = c.ref_centroid.unwrap_or_else(|| panic!("no reference shadow at t = {t}"));
        let off = ((g.0 - e.0).powi(2) + (g.1 - e.1).powi(2)).sqrt();
        eprintln!("t={t}: shadow centroid GPU ({:.2}, {:.2}) reference ({:.2}, {:.2}), {off:.2} px apart", g.0, g.1, e.0, e.1);
        assert!(off <= 1.5, "t = {t}: GPU shadow centroid {off:.2} px from the reference's");
        if let Some((pg, pe)) = previous {
            let (mg, me) = ((g.0 - pg.0, g.1 - pg.1), (e.0 - pe.0, e.1 - pe.1));
            let moved = (me.0 * me.0 + me.1 * me.1).sqrt();
            assert!(moved >= 2.0, "the reference's shadow barely moved by t = {t}");
            let cos = (mg.0 * me.0 + mg.1 * me.1) / (moved * (mg.0 * mg.0 + mg.1 * mg.1).sqrt().max(1e-9));
            assert!(cos > 0.95, "t = {t}: the GPU shadow moved another way than the reference's (cos {cos:.3})");
        }
        previous = Some((g, e));
    }
}

#[test]
fn uniform_order_comes_from_the_reflection() {
    let Some(r) = gpu::vulkan() else { return };
    let p = FrameParams::new(2.0, W, H);
    let usual = r.render_scene(&hand::shader_set(), &p).unwrap();
    // Every binding number reversed, in the WGSL and in its reflection.
    let reversed = r.render_scene(&hand::rebound(|b| 2 - b), &p).unwrap();
    let stats = image_ops::diff(&usual, &reversed, 0);
    assert_eq!(stats.over, 0, "{stats}");
    // The same WGSL with the usual reflection does not fit: wgpu rejects
    // the pipeline and the renderer says so instead of panicking.
    let mut mismatched = hand::rebound(|b| 2 - b);
    mismatched.reflection = Some(hand::reflection());
    let err = r.render_scene(&mismatched, &p).unwrap_err();
    assert!(matches!(err, ExecError::Link { .. }), "{err}");
}

/// SPIR-V of the hand port made by naga with the options wgpu uses itself
/// (no coordinate-space adjustment), standing in for the compiler's SPIR-V
/// output until the tests below render the compiled program.
fn hand_spirv() -> Vec<u32> {
    let module = naga::front::wgsl::parse_str(hand::WGSL).unwrap();
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::all())
        .validate(&module)
        .unwrap();
    let options = naga::back::spv::Options { flags: naga::back::spv::WriterFlags::empty(), ..Default::default() };
    naga::back::spv::write_vec(&module, &info, &options, None).unwrap()
}

#[test]
fn wgsl_and_passthrough_spirv_agree() {
    let Some(r) = gpu::vulkan() else { return };
    if !r.supports_passthrough() {
        support::skip(format!("{} lacks PASSTHROUGH_SHADERS", r.adapter_name()));
        return;
    }
    let spirv = ShaderSet::single("hand.spv", ShaderCode::Spirv(hand_spirv()), hand::reflection());
    for t in [0.5, 3.0] {
        let p = FrameParams::new(t, W, H);
        let a = r.render_scene(&hand::shader_set(), &p).unwrap();
        let b = r.render_scene(&spirv, &p).unwrap();
        let stats = image_ops::diff(&a, &b, 1);
        eprintln!("wgsl vs spirv t={t}: {stats}");
        assert!(stats.fraction_over <= 0.001, "t = {t}: {stats}");
    }
}

#[test]
fn shadow_map_view_matches_the_reference() {
    let Some(r) = gpu::vulkan() else { return };
    let mut p = FrameParams::new(2.5, W, H).with_view(View::ShadowMap);
    p.shadow_size = 256;
    let gpu = r.render_scene(&scene(Target::Wgsl), &p).unwrap();
    let cpu = reference::render(&p);
    assert_eq!(gpu.dimensions(), (256, 256));
    let stats = image_ops::diff(&gpu, &cpu, DELTA);
    eprintln!("shadow map: {stats}");
    // The pipeline's depth bias moves stored depths by a few units in the
    // last place; only texels on silhouette edges may disagree.
    assert!(stats.fraction_over <= 0.005, "{stats}");
}

#[test]
fn programs_that_do_not_fit_are_clear_errors() {
    let Some(r) = gpu::vulkan() else { return };
    let mut set = hand::shader_set();
    let manifest = set.reflection.as_mut().unwrap();
    for b in &mut manifest.uniform_buffers {
        b.members.retain(|m| m.name != "u_model");
    }
    manifest.uniforms.retain(|u| u.name != "u_model");
    for e in &mut manifest.entry_points {
        e.uniforms.retain(|u| u != "u_model");
        e.inputs.retain(|i| i.name != "a_pos");
    }
    let err = r.prepare_scene(&set).err().expect("a program without u_model must be refused");
    let text = err.to_string();
    assert!(matches!(err, ExecError::Interface(_)), "{text}");
    assert!(text.contains("no `u_model` uniform"), "{text}");
    assert!(text.contains("no `a_pos` vertex input in `main_vs`"), "{text}");

    // A program that compiles but is not this scene's.
    let other = r#"
var @uniform u_light_vp : float4x4
var @uniform u_tint : float4
var @in @location = 0 a_position : float3
var @out f_FragColor : float4
[vertex_program]
def shadow_vs {
    gl_Position = u_light_vp * float4(a_position, 1.0)
}
[fragment_program]
def shadow_fs {
    f_FragColor = u_tint
}
[vertex_program]
def main_vs {
    gl_Position = u_light_vp * float4(a_position, 1.0)
}
[fragment_program]
def main_fs {
    f_FragColor = u_tint
}
"#;
    let err = r.prepare_scene(&compiled("other.das", other, Target::Wgsl, Conventions::Portable)).err().expect("refused");
    let text = err.to_string();
    eprintln!("{text}");
    for needle in [
        "no `u_model` uniform",
        "no `u_proj` uniform",
        "uniform `u_tint` is not a value the scene sets",
        "vertex input `a_position` of `main_vs` is not in the scene's meshes",
        "no `a_pos` vertex input in `shadow_vs`",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in:\n{text}");
    }

    let broken = ShaderSet::single("broken.wgsl", ShaderCode::Wgsl("fn oops( {".into()), hand::reflection());
    let err = r.prepare_scene(&broken).err().expect("WGSL that does not parse must be refused");
    assert!(matches!(err, ExecError::Compile { .. }), "{err}");
}

#[test]
fn gl_backend_agrees_with_vulkan() {
    let Some(vk) = gpu::vulkan() else { return };
    let Some(gl) = gpu::wgpu_gl() else { return };
    let p = FrameParams::new(3.0, W, H);
    let a = vk.render_scene(&hand::shader_set(), &p).unwrap();
    let b = gl.render_scene(&hand::shader_set(), &p).unwrap();
    let stats = image_ops::diff(&a, &b, DELTA);
    eprintln!("vulkan vs gl ({}): {stats}", gl.adapter_name());
    assert!(stats.fraction_over <= 0.002, "{stats}");
}

mod command {
    use super::*;
    use umbrac::render::command::{run, Quiet, RenderOptions};
    use umbrac::render::Consumer;

    fn opts(file: Option<&str>) -> RenderOptions {
        RenderOptions { file: file.map(Into::into), ..Default::default() }
    }

    #[test]
    fn frames_write_pngs_and_a_gif() {
        if gpu::vulkan().is_none() {
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().to_str().unwrap();
        let hand = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/hand/shadow.wgsl");
        let o = RenderOptions { frames: Some(3), fps: 10.0, size: (64, 48), out_dir: out.into(), ..opts(Some(hand)) };
        run(&o, &mut Quiet).unwrap();
        for f in ["frame_0000.png", "frame_0002.png", "animation.gif"] {
            assert!(dir.path().join(f).is_file(), "{f} missing");
        }
        let frame = image::open(dir.path().join("frame_0001.png")).unwrap();
        assert_eq!((frame.width(), frame.height()), (64, 48));
    }

    /// A headless `umbrac render` prints no stray "error:" lines from the
    /// graphics stack (libwayland's complaint about XDG_RUNTIME_DIR, printed
    /// on a run that succeeds, when the variable is unset).
    #[test]
    fn headless_render_without_a_runtime_dir_prints_no_errors() {
        if gpu::vulkan().is_none() {
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("f.png");
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["render", "--size", "32x24", "--out", png.to_str().unwrap()])
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env_remove("XDG_RUNTIME_DIR")
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{stderr}");
        assert!(png.is_file());
        assert!(!stderr.contains("error"), "stderr of a successful render: {stderr}");
    }

    /// `render --watch`: an edit to the program redraws; a broken edit
    /// prints its error and keeps the last good picture. The log sits in
    /// the watched directory and is read every 20 ms: those reads once held
    /// every step off for ever (they kept the quiet wait from ending).
    #[test]
    fn watch_redraws_on_change_and_keeps_the_last_good_picture() {
        if gpu::vulkan().is_none() {
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let prog = dir.path().join("scene.das");
        std::fs::write(&prog, SCENE).unwrap();
        let png = dir.path().join("f.png");
        let log = dir.path().join("log");
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["render", "--watch", prog.to_str().unwrap(), "--size", "32x24", "--out", png.to_str().unwrap()])
            .stderr(std::fs::File::create(&log).unwrap())
            .spawn()
            .unwrap();
        let read_log = || std::fs::read_to_string(&log).unwrap_or_default();
        let wait_for = |what: &str, cond: &dyn Fn() -> bool| {
            let deadline = std::time::Instant::now() + std::time::Duration::from_secs(120);
            while !cond() {
                assert!(std::time::Instant::now() < deadline, "timed out waiting for {what}:\n{}", read_log());
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
        };
        let count = |s: &str| read_log().matches(s).count();
        wait_for("the first picture", &|| count("[watch] ok") == 1);
        let first = std::fs::read(&png).unwrap();
        std::fs::write(&prog, SCENE.replacen("[fragment_program]", "[fragment_program]\ndef broken { nope }\n[fragment_program]", 1)).unwrap();
        wait_for("the error", &|| count("[watch] failed") == 1);
        assert_eq!(std::fs::read(&png).unwrap(), first, "the last good picture stays");
        // The cube black: a different picture.
        let black = SCENE.replace("var albedo = float3(0.85, 0.45, 0.30)", "var albedo = float3(0.0, 0.0, 0.0)");
        assert_ne!(black, SCENE);
        std::fs::write(&prog, black).unwrap();
        wait_for("the redraw", &|| count("[watch] ok") == 2);
        let _ = child.kill();
        let _ = child.wait();
        assert_ne!(std::fs::read(&png).unwrap(), first, "{}", read_log());
    }

    #[test]
    fn reference_and_errors() {
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("ref.png");
        run(&RenderOptions { reference: true, size: (32, 24), out: png.clone(), ..opts(None) }, &mut Quiet).unwrap();
        assert!(png.is_file());
        assert!(run(&opts(Some("/nonexistent/scene.wgsl")), &mut Quiet).is_err());
        let hand = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/hand/shadow.wgsl");
        let err = run(&RenderOptions { consumer: Consumer::VulkanSpirv, ..opts(Some(hand)) }, &mut Quiet).unwrap_err();
        assert!(err.contains("--via spirv needs a .das or .spv program"), "{err}");
    }
}

#[test]
fn hand_reflection_matches_the_compilers() {
    // The hand port claims the compiler's binding model; hold it to that.
    let c = umbrac::compile_source("shaders/shadow.das", SCENE, &Options::default());
    let compiled = &c.result.as_ref().expect("the scene compiles").reflection;
    let hand = hand::reflection();
    assert_eq!(hand.uniform_buffers, compiled.uniform_buffers);
    assert_eq!(hand.uniforms, compiled.uniforms);
    assert_eq!(hand.samplers, compiled.samplers);
    assert_eq!(hand.conventions, compiled.conventions);
    let key = |r: &umbrac::Reflection| -> Vec<_> {
        r.entry_points
            .iter()
            .map(|e| {
                let io = |v: &[umbrac::emit::reflect_types::Io]| -> Vec<_> {
                    v.iter().map(|i| (i.name.clone(), i.location, i.ty.clone(), i.vertex_format.clone())).collect()
                };
                (e.name.clone(), e.stage.clone(), io(&e.inputs), io(&e.outputs), e.uniform_buffers.clone(), e.uniforms.clone(), e.samplers.clone())
            })
            .collect()
    };
    assert_eq!(key(&hand), key(compiled));
}
