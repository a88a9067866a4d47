//! `umbrac render`: what it does, with its options as a plain struct
//! ([`RenderOptions`]). The binary parses the command line into one
//! (`src/cli/render.rs`), shows progress and runs `--watch`; the library
//! needs no argument parser.
//!
//! Data flows one way: the options -> [`program`] (what to draw) -> an
//! executor -> [`frames`] (what is written). `--compare-backends` is in
//! `consumers`, the technique scenes (`--scene NAME`) in `techniques`, any
//! other program (a scene file, `--scene FILE`, or the inferred scene) in
//! [`any`].

pub mod any;
mod consumers;
pub mod frames;
pub mod program;
mod techniques;

use std::path::PathBuf;

pub use program::{load_program, load_program_with};

use super::consumers::Consumer;
use super::exec::{ExecError, Executor};
use super::plan::tutorial;
use super::reference;
use super::scene::{FrameParams, View, DEFAULT_SHADOW_SIZE};
use super::setup::{Fit, Setup};
use super::visible;
use frames::{frame_times, write_frames};

/// Everything `umbrac render` can be asked (docs/runner.md).
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    /// The scene program: a .das file compiled in process (default
    /// `shaders/shadow.das`), or a ready .wgsl / .spv file.
    pub file: Option<PathBuf>,
    /// The PNG of a single frame.
    pub out: PathBuf,
    /// Scene time in seconds (the first frame's, with `frames`).
    pub time: f32,
    pub size: (u32, u32),
    /// An animation of this many frames, `time + i / fps` each.
    pub frames: Option<u32>,
    pub fps: f32,
    /// Where `frames` writes.
    pub out_dir: PathBuf,
    /// Which consumer draws (`--backend` with `--via`).
    pub consumer: Consumer,
    pub shadow_size: u32,
    pub view: View,
    /// The manifest of a .wgsl / .spv `file`.
    pub reflection: Option<PathBuf>,
    /// Write the CPU reference instead.
    pub reference: bool,
    /// Also write the CPU reference and the difference, and print it.
    pub compare: bool,
    pub setup: Setup,
    /// One frame on every consumer, side by side.
    pub compare_backends: bool,
    /// A technique scene (docs/gallery.md) instead of the tutorial's.
    pub scene: Option<String>,
    /// Taps of the `pcf` scene's offset table.
    pub pcf_taps: u32,
    /// Where a .das program's `require`d daslang modules are (`--daslang-root`).
    pub daslang_root: Option<PathBuf>,
    /// A scene file (`--scene FILE.toml`) the program is drawn with.
    pub scene_file: Option<PathBuf>,
    /// The program (`VS` or `VS:FS`) drawn with its inferred scene.
    pub program: Option<String>,
}

impl Default for RenderOptions {
    fn default() -> RenderOptions {
        RenderOptions {
            file: None,
            out: "frame.png".into(),
            time: 0.0,
            size: (640, 480),
            frames: None,
            fps: 30.0,
            out_dir: "frames".into(),
            consumer: Consumer::VulkanWgsl,
            shadow_size: DEFAULT_SHADOW_SIZE,
            view: View::Final,
            reflection: None,
            reference: false,
            compare: false,
            setup: Setup::default(),
            compare_backends: false,
            scene: None,
            pcf_taps: 9,
            daslang_root: None,
            scene_file: None,
            program: None,
        }
    }
}

/// How far an animation is, for a progress bar.
pub trait Progress {
    /// `total` frames are about to be drawn.
    fn start(&mut self, _total: usize) {}
    fn frame_done(&mut self) {}
    /// Every frame is drawn; the GIF is being encoded.
    fn encoding(&mut self) {}
    fn finish(&mut self) {}
}

/// No progress shown.
pub struct Quiet;

impl Progress for Quiet {}

/// Runs `umbrac render` once; the error is one message for stderr.
pub fn run(opts: &RenderOptions, progress: &mut dyn Progress) -> Result<(), String> {
    if opts.scene.is_some() {
        if opts.setup.shadow.fit == Fit::Visible {
            return Err("--fit visible fits the tutorial scene's sun box; the technique scenes (--scene) make their own light boxes".into());
        }
        return techniques::run(opts);
    }
    if any::wants_scene(opts) {
        return any::run(opts, progress);
    }
    let (width, height) = opts.size;
    let mut params = FrameParams::new(opts.time, width, height);
    params.shadow_size = opts.shadow_size;
    params.view = opts.view;
    params.setup = opts.setup;
    if opts.shadow_size == 0 || opts.shadow_size > 16384 {
        return Err(format!("--shadow-size {} must be between 1 and 16384", opts.shadow_size));
    }
    if let Some(n) = opts.frames {
        if n == 0 || opts.fps.is_nan() || opts.fps <= 0.0 {
            return Err("--frames needs N >= 1 and --fps above 0".into());
        }
    }
    if opts.reference {
        return write_frames(opts, &frame_times(opts), |p| Ok(reference::render(p)), params, progress);
    }
    if opts.compare_backends {
        if params.setup.shadow.fit == Fit::Visible {
            return Err("--fit visible runs a compute pass, which most consumers have not: it does not go with --compare-backends".into());
        }
        return consumers::compare_backends(opts, params);
    }
    if params.setup.shadow.fit == Fit::Visible {
        visible::check_consumer(opts.consumer)?;
    }
    let defines = params.setup.defines(params.shadow_size);
    let base = crate::Options { defines, daslang_root: opts.daslang_root.clone(), ..Default::default() };
    let set = load_program_with(opts.file.as_deref(), opts.reflection.as_deref(), opts.consumer, base)?;
    match opts.consumer {
        #[cfg(feature = "gl")]
        Consumer::Gl430 => {
            let _ = super::consumers::wgpu_gl();
            let gl = super::exec::gl::GlExecutor::new(opts.consumer).map_err(|e| e.to_string())?;
            if params.setup.shadow.fit == Fit::Visible {
                draw_visible(&gl, &set, opts, params, progress)
            } else {
                draw(&gl, &set, opts, params, progress)
            }
        }
        Consumer::VulkanWgsl | Consumer::VulkanSpirv if params.setup.shadow.fit == Fit::Visible => {
            draw_visible(super::consumers::vulkan().map_err(|e| e.to_string())?, &set, opts, params, progress)
        }
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => draw(super::consumers::vulkan().map_err(|e| e.to_string())?, &set, opts, params, progress),
        Consumer::WgpuGl => draw(super::consumers::wgpu_gl().map_err(|e| e.to_string())?, &set, opts, params, progress),
        #[cfg(feature = "gl")]
        Consumer::Gl330 | Consumer::Gles300 => {
            let _ = super::consumers::wgpu_gl();
            let gl = super::exec::gl::GlExecutor::new(opts.consumer).map_err(|e| e.to_string())?;
            draw(&gl, &set, opts, params, progress)
        }
        Consumer::WebGl2 => draw(&super::exec::webgl::WebGl::find().map_err(|e| e.to_string())?, &set, opts, params, progress),
        other => Err(format!("{} cannot draw here ({})", other.name(), other.description())),
    }
}

fn draw<E: Executor>(e: &E, set: &super::ShaderSet, opts: &RenderOptions, params: FrameParams, progress: &mut dyn Progress) -> Result<(), String> {
    let plan = scene_plan(set);
    let prepared = e.prepare(set, &plan(&params)).map_err(|e| e.to_string())?;
    eprintln!("rendering {} ({}) on {}: {}", set.label, set.target.name(), opts.consumer.name(), e.device_name());
    let times = frame_times(opts);
    write_frames(opts, &times, |p| e.run(&prepared, &plan(p)).map(|r| r.into_image()).map_err(|e: ExecError| e.to_string()), params, progress)
}

/// The scene a program draws: dasVulkan's shadow rung for a program with
/// its Vulkan-dialect entry points, the tutorial's otherwise.
pub fn scene_plan(set: &super::ShaderSet) -> fn(&FrameParams) -> super::plan::FramePlan {
    let vulkan = set.reflection.as_ref().is_some_and(|r| {
        r.entry_points.iter().any(|e| e.name == super::plan::vk_shadow::MAIN_VS && e.dialect.as_deref() == Some("vulkan"))
    });
    if vulkan {
        super::plan::vk_shadow::plan
    } else {
        tutorial::plan
    }
}

/// [`draw`] for `--fit visible`: each frame measured first
/// ([`visible::render`]).
fn draw_visible<E: visible::ComputeExecutor>(e: &E, set: &super::ShaderSet, opts: &RenderOptions, params: FrameParams, progress: &mut dyn Progress) -> Result<(), String> {
    let prepared = e.prepare(set, &tutorial::plan(&params)).map_err(|e| e.to_string())?;
    let reduction = visible::program(set.target)?;
    eprintln!(
        "rendering {} ({}) on {}: {}, the light box fitted by {} each frame",
        set.label,
        set.target.name(),
        opts.consumer.name(),
        e.device_name(),
        visible::PROGRAM_NAME
    );
    let times = frame_times(opts);
    write_frames(opts, &times, |p| visible::render(e, &prepared, &reduction, p).map(|r| r.into_image()).map_err(|e| e.to_string()), params, progress)
}

/// What `--watch` waits on: the program and every file its preprocessing
/// reads (with the defines the render uses), and `--reflection`.
#[cfg(feature = "cli")]
pub fn watched(opts: &RenderOptions) -> crate::watch::Watched {
    let file = opts.file.clone().unwrap_or_else(|| program::DEFAULT_PROGRAM.into());
    let mut files = vec![file.clone()];
    if file.extension().is_some_and(|x| x == "das") {
        let options = crate::Options { defines: opts.setup.defines(opts.shadow_size), ..Default::default() };
        files.extend(crate::preprocess_file(&file, &options).files_read());
    }
    files.extend(opts.reflection.iter().cloned());
    files.extend(any::scene_path(opts).map(std::path::Path::to_path_buf));
    crate::watch::Watched { files, dirs: Vec::new() }
}
