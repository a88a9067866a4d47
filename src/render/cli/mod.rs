//! `umbrac render`: the command (feature `cli`).
//!
//! Data flows one way: [`args`] (what was asked) -> [`program`] (what to
//! draw) -> a renderer -> [`frames`] (what is written). The GL consumers
//! and `--compare-backends` are in [`consumers`], the technique scenes
//! (`--scene`) in [`techniques`].

pub mod args;
mod consumers;
pub mod frames;
pub mod program;
pub mod setup_args;
mod techniques;

pub use args::{BackendArg, RenderArgs, ViaArg, ViewArg};
pub use program::{load_program, load_program_with};

use super::gpu::{Backend, RenderError, Renderer, Via};
use super::reference;
use super::scene::{FrameParams, View};
use frames::{frame_times, write_frames};

/// Runs `umbrac render`; returns the process exit code.
pub fn run(args: &RenderArgs) -> i32 {
    if args.watch {
        return match crate::watch::watch(|| (run_once(args), watched(args))) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: {e}");
                1
            }
        };
    }
    run_once(args).into()
}

fn run_once(args: &RenderArgs) -> u8 {
    match execute(args) {
        Ok(()) => 0,
        Err(message) => {
            eprintln!("error: {}", message.trim_end());
            1
        }
    }
}

/// What `--watch` waits on: the program and every file its preprocessing
/// reads (with the defines the render uses), and `--reflection`.
fn watched(args: &RenderArgs) -> crate::watch::Watched {
    let file = args.file.clone().unwrap_or_else(|| program::DEFAULT_PROGRAM.into());
    let mut files = vec![file.clone()];
    if file.extension().is_some_and(|x| x == "das") {
        let params_defines = args.setup.setup().defines(args.shadow_size);
        let opts = crate::Options { defines: params_defines, ..Default::default() };
        files.extend(crate::preprocess_file(&file, &opts).files_read());
    }
    files.extend(args.reflection.iter().cloned());
    crate::watch::Watched { files, dirs: Vec::new() }
}

fn via(args: &RenderArgs) -> Via {
    match args.via {
        ViaArg::Wgsl => Via::Wgsl,
        ViaArg::Spirv => Via::Spirv,
    }
}

fn view(args: &RenderArgs) -> View {
    match args.view {
        ViewArg::Final => View::Final,
        ViewArg::ShadowMap => View::ShadowMap,
        ViewArg::Lit => View::Lit,
    }
}

fn execute(args: &RenderArgs) -> Result<(), String> {
    if args.scene.is_some() {
        return techniques::run(args);
    }
    let (width, height) = args.size;
    let mut params = FrameParams::new(args.time, width, height);
    params.shadow_size = args.shadow_size;
    params.view = view(args);
    params.setup = args.setup.setup();
    if args.shadow_size == 0 || args.shadow_size > 16384 {
        return Err(format!("--shadow-size {} must be between 1 and 16384", args.shadow_size));
    }
    if let Some(n) = args.frames {
        if n == 0 || args.fps.is_nan() || args.fps <= 0.0 {
            return Err("--frames needs N >= 1 and --fps above 0".into());
        }
    }

    if args.reference {
        let frames = frame_times(args);
        return write_frames(args, &frames, |p| Ok(reference::render(p)), params);
    }

    if args.compare_backends {
        return consumers::compare_backends(args, params);
    }
    let backend = match args.backend {
        BackendArg::Vulkan => Backend::Vulkan,
        BackendArg::Gl => Backend::Gl,
        BackendArg::Gl330 | BackendArg::Gles300 => return consumers::render_gl(args, params),
    };
    let defines = params.setup.defines(params.shadow_size);
    let set = load_program_with(args.file.as_deref(), args.reflection.as_deref(), via(args), defines)?;
    let renderer = Renderer::new(backend).map_err(|e| e.to_string())?;
    let program = renderer.prepare(&set).map_err(|e| e.to_string())?;
    eprintln!("rendering {} ({} via {}) on {}", set.label, set.via().name(), backend.name(), renderer.adapter_name());
    let frames = frame_times(args);
    write_frames(args, &frames, |p| renderer.draw(&program, p).map_err(|e: RenderError| e.to_string()), params)
}

