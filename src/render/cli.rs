//! `umbrac render`: arguments and the command itself.

use std::path::{Path, PathBuf};
use std::time::Instant;

use super::gpu::{Backend, RenderError, Renderer, ShaderCode, ShaderSet, Via};
use super::scene::{FrameParams, View, DEFAULT_SHADOW_SIZE};
use super::{hand, image_ops, reference};

/// The project's own scene program, used when FILE is not given and
/// `shaders/shadow.das` is not on disk.
const BUILTIN_PROGRAM: &str = include_str!("../../shaders/shadow.das");
const DEFAULT_PROGRAM: &str = "shaders/shadow.das";

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ViaArg {
    /// WGSL, translated by wgpu.
    #[default]
    Wgsl,
    /// SPIR-V, passed to the Vulkan driver unchanged.
    Spirv,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum BackendArg {
    #[default]
    Vulkan,
    /// wgpu's OpenGL backend through EGL.
    Gl,
    /// The GLSL 330 output on an OpenGL 3.3 core context (EGL surfaceless, no wgpu).
    Gl330,
    /// The GLSL ES 3.00 output on an OpenGL ES 3.0 context (EGL surfaceless, no wgpu).
    Gles300,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ViewArg {
    /// The shadowed, lit scene.
    #[default]
    Final,
    /// The sun's depth texture, greyscale (near dark, empty white).
    ShadowMap,
    /// The scene with an empty shadow map: lighting without shadows.
    Lit,
}

/// Arguments of `umbrac render`.
#[derive(Debug, Clone, clap::Args)]
#[command(about = "Render the shadow scene from a shader program with wgpu (headless)")]
pub struct RenderArgs {
    /// The scene program: a .das file compiled in process (default
    /// shaders/shadow.das), or a ready .wgsl / .spv file with the scene's
    /// binding model (see --reflection; a .spv file always goes to the
    /// driver unchanged, as with --via spirv).
    pub file: Option<PathBuf>,
    /// Output PNG for a single frame.
    #[arg(long, short, default_value = "frame.png")]
    pub out: PathBuf,
    /// Scene time in seconds (the first frame's time with --frames).
    #[arg(long, short, default_value_t = 0.0)]
    pub time: f32,
    /// Image size, WIDTHxHEIGHT.
    #[arg(long, default_value = "640x480", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Render an animation of N frames: DIR/frame_0000.png ... and DIR/animation.gif.
    #[arg(long, value_name = "N")]
    pub frames: Option<u32>,
    /// Frames per second of the animation (scene time advances 1/F per frame).
    #[arg(long, value_name = "F", default_value_t = 30.0)]
    pub fps: f32,
    /// Directory for --frames output.
    #[arg(long, value_name = "DIR", default_value = "frames")]
    pub out_dir: PathBuf,
    /// Which compiled form the GPU gets.
    #[arg(long, value_enum, default_value_t)]
    pub via: ViaArg,
    /// wgpu backend.
    #[arg(long, value_enum, default_value_t)]
    pub backend: BackendArg,
    /// Side of the square shadow map.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_SHADOW_SIZE)]
    pub shadow_size: u32,
    /// What to write.
    #[arg(long, value_enum, default_value_t)]
    pub view: ViewArg,
    /// Reflection JSON for a .wgsl or .spv FILE (default: the hand port's binding model).
    #[arg(long, value_name = "JSON")]
    pub reflection: Option<PathBuf>,
    /// Write the CPU ray-cast reference instead of rendering on the GPU.
    #[arg(long, conflicts_with = "compare")]
    pub reference: bool,
    /// Also render the CPU reference and print how the two differ (and, with
    /// --out a.png, write a.ref.png and a.diff.png beside it).
    #[arg(long)]
    pub compare: bool,
    /// Shadow technique: --quality, --filter, --fit, --depth-format, --casters-only.
    #[command(flatten)]
    pub setup: super::setup_cli::SetupArgs,
    /// Render one frame on every available consumer (wgpu Vulkan via WGSL
    /// and SPIR-V, wgpu GL, GL 3.3, GLES 3.0, WebGL2, the CPU reference),
    /// print their pairwise differences and write OUT.CONSUMER.png for each.
    #[arg(long, conflicts_with_all = ["reference", "compare", "frames"])]
    pub compare_backends: bool,
    /// A shadow technique scene instead of the tutorial's (docs/gallery.md):
    /// spot, pcf, cascades, proj, cull, rgba8-depth.
    #[arg(long, value_name = "NAME", conflicts_with_all = ["file", "compare_backends", "reflection"])]
    pub scene: Option<String>,
    /// Taps of the pcf scene's offset table: 1, 2, 4 or 9.
    #[arg(long, value_name = "N", default_value_t = 9)]
    pub pcf_taps: u32,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("`{s}` is not WIDTHxHEIGHT"))?;
    let w: u32 = w.trim().parse().map_err(|_| format!("bad width in `{s}`"))?;
    let h: u32 = h.trim().parse().map_err(|_| format!("bad height in `{s}`"))?;
    if w == 0 || h == 0 || w > 16384 || h > 16384 {
        return Err(format!("size `{s}` must be between 1x1 and 16384x16384"));
    }
    Ok((w, h))
}

/// Runs `umbrac render`; returns the process exit code.
pub fn run(args: &RenderArgs) -> i32 {
    match execute(args) {
        Ok(()) => 0,
        Err(message) => {
            eprintln!("error: {}", message.trim_end());
            1
        }
    }
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

/// Loads the program named on the command line.
pub fn load_program(file: Option<&Path>, reflection: Option<&Path>, via: Via) -> Result<ShaderSet, String> {
    load_program_with(file, reflection, via, Vec::new())
}

/// [`load_program`] with `-D` definitions for a .das program.
pub fn load_program_with(
    file: Option<&Path>,
    reflection: Option<&Path>,
    via: Via,
    defines: Vec<(String, Option<String>)>,
) -> Result<ShaderSet, String> {
    let ext = file.and_then(|p| p.extension()).and_then(|e| e.to_str());
    if let (Some(path), Some(ext @ ("wgsl" | "spv"))) = (file, ext) {
        let code = if ext == "wgsl" {
            if via != Via::Wgsl {
                return Err(format!("{} is WGSL; --via spirv needs a .das or .spv program", path.display()));
            }
            ShaderCode::Wgsl(std::fs::read_to_string(path).map_err(|e| format!("reading {}: {e}", path.display()))?)
        } else {
            let bytes = std::fs::read(path).map_err(|e| format!("reading {}: {e}", path.display()))?;
            ShaderCode::spirv_from_bytes(&bytes).map_err(|e| format!("{}: {e}", path.display()))?
        };
        let refl = match reflection {
            Some(r) => {
                let json = std::fs::read_to_string(r).map_err(|e| format!("reading {}: {e}", r.display()))?;
                serde_json::from_str(&json).map_err(|e| format!("{}: not a reflection manifest: {e}", r.display()))?
            }
            None => hand::reflection(),
        };
        return Ok(ShaderSet::single(path.display().to_string(), code, refl));
    }
    let opts = crate::Options { targets: vec![via.target()], defines, ..Default::default() };
    match compile_program(file, &opts) {
        (name, Some(compiled)) => ShaderSet::from_compiled(name, &compiled, via).map_err(|e| e.to_string()),
        (name, None) => Err(format!(
            "{name} did not compile (the hand-written port renders with `umbrac render {}`)",
            hand::FILE_NAME
        )),
    }
}

/// Compiles the program the runner draws: `file`, else `shaders/shadow.das`
/// when run from a checkout, else the copy built into the binary. Its
/// diagnostics go to stderr; the result comes back only when it has no
/// errors, with the name the diagnostics use.
pub(super) fn compile_program(file: Option<&Path>, opts: &crate::Options) -> (String, Option<crate::Compiled>) {
    let compilation = match file {
        Some(path) => crate::compile_file(path, opts),
        None if Path::new(DEFAULT_PROGRAM).is_file() => crate::compile_file(Path::new(DEFAULT_PROGRAM), opts),
        None => crate::compile_source(DEFAULT_PROGRAM, BUILTIN_PROGRAM, opts),
    };
    let name = file.map_or(DEFAULT_PROGRAM.to_string(), |p| p.display().to_string());
    let diagnostics = compilation.render_diagnostics();
    if !diagnostics.is_empty() {
        eprint!("{diagnostics}");
    }
    let ok = !compilation.has_errors();
    (name, compilation.result.filter(|_| ok))
}

fn execute(args: &RenderArgs) -> Result<(), String> {
    if args.scene.is_some() {
        return super::techniques::cli::run(args);
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
        return super::cli_consumers::compare_backends(args, params);
    }
    let backend = match args.backend {
        BackendArg::Vulkan => Backend::Vulkan,
        BackendArg::Gl => Backend::Gl,
        BackendArg::Gl330 | BackendArg::Gles300 => return super::cli_consumers::render_gl(args, params),
    };
    let defines = params.setup.defines(params.shadow_size);
    let set = load_program_with(args.file.as_deref(), args.reflection.as_deref(), via(args), defines)?;
    let renderer = Renderer::new(backend).map_err(|e| e.to_string())?;
    let program = renderer.prepare(&set).map_err(|e| e.to_string())?;
    eprintln!("rendering {} ({} via {}) on {}", set.label, set.via().name(), backend.name(), renderer.adapter_name());
    let frames = frame_times(args);
    write_frames(args, &frames, |p| renderer.draw(&program, p).map_err(|e: RenderError| e.to_string()), params)
}

pub(super) fn frame_times(args: &RenderArgs) -> Vec<f32> {
    match args.frames {
        None => vec![args.time],
        Some(n) => (0..n).map(|i| args.time + i as f32 / args.fps).collect(),
    }
}

pub(super) fn write_frames(
    args: &RenderArgs,
    times: &[f32],
    mut render: impl FnMut(&FrameParams) -> Result<image::RgbaImage, String>,
    base: FrameParams,
) -> Result<(), String> {
    if args.frames.is_none() {
        let started = Instant::now();
        let image = render(&base)?;
        let ms = started.elapsed().as_secs_f64() * 1e3;
        image_ops::save_png(&image, &args.out)?;
        eprintln!(
            "wrote {} ({}x{}, t = {}, view {}, {ms:.1} ms)",
            args.out.display(),
            image.width(),
            image.height(),
            base.time,
            base.view.name()
        );
        if args.compare {
            compare(&image, &base, &args.out)?;
        }
        return Ok(());
    }
    let bar = indicatif::ProgressBar::new(times.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{prefix} [{bar:40}] {pos}/{len} frames, {per_sec}, eta {eta}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar.set_prefix("rendering");
    let mut images = Vec::with_capacity(times.len());
    for (i, &t) in times.iter().enumerate() {
        let image = render(&FrameParams { time: t, ..base })?;
        let path = args.out_dir.join(format!("frame_{i:04}.png"));
        image_ops::save_png(&image, &path)?;
        images.push(image);
        bar.inc(1);
    }
    bar.set_prefix("encoding gif");
    let gif = args.out_dir.join("animation.gif");
    image_ops::save_gif(&images, args.fps, &gif)?;
    bar.finish_and_clear();
    eprintln!(
        "wrote {} frames to {}/frame_0000.png .. frame_{:04}.png and {}",
        images.len(),
        args.out_dir.display(),
        images.len() - 1,
        gif.display()
    );
    Ok(())
}

fn compare(image: &image::RgbaImage, params: &FrameParams, out: &Path) -> Result<(), String> {
    let reference = reference::render_frame(params);
    let skip = (params.view == View::Final).then_some(reference.outside_shadow_map.as_slice());
    let stats = image_ops::diff_masked(image, &reference.image, DELTA, skip);
    let masked = skip.map_or(0, image_ops::count);
    println!("vs CPU reference (delta {DELTA}/255, {masked} pixels outside the sun's box skipped): {stats}");
    let stem = out.with_extension("");
    let ref_path = stem.with_extension("ref.png");
    let diff_path = stem.with_extension("diff.png");
    image_ops::save_png(&reference.image, &ref_path)?;
    image_ops::save_png(&image_ops::diff_image(image, &reference.image, skip), &diff_path)?;
    eprintln!("wrote {} and {}", ref_path.display(), diff_path.display());
    Ok(())
}

/// The colour difference (out of 255) above which `--compare` counts a pixel.
pub const DELTA: u8 = 8;

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: RenderArgs,
    }

    #[test]
    fn parses_every_option() {
        let c = Cli::try_parse_from([
            "render", "x.das", "--out", "a.png", "--time", "2", "--size", "320x240", "--frames", "4", "--fps", "12",
            "--out-dir", "d", "--via", "spirv", "--backend", "gl", "--shadow-size", "512", "--view", "shadow-map",
        ])
        .unwrap();
        let a = c.args;
        assert_eq!(a.size, (320, 240));
        assert_eq!((a.via, a.backend, a.view), (ViaArg::Spirv, BackendArg::Gl, ViewArg::ShadowMap));
        assert_eq!((a.frames, a.fps, a.shadow_size), (Some(4), 12.0, 512));
        assert!(Cli::try_parse_from(["render", "--size", "0x3"]).is_err());
        assert!(Cli::try_parse_from(["render", "--view", "sideways"]).is_err());
    }
}
