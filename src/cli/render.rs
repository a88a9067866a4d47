//! `umbrac render`: its command line (clap), turned into the library's
//! plain [`RenderOptions`]; the progress bar and `--watch`.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use umbrac::render::command::{self, Progress, RenderOptions};
use umbrac::render::scene::DEFAULT_SHADOW_SIZE;
use umbrac::render::{Consumer, DepthFormat, Filter, Fit, Quality, Setup, View};

/// A parser of one of the library's named choices (`View::ALL` by `View::name`).
fn choice<T: Copy + Send + Sync + 'static>(all: &'static [T], name: fn(T) -> &'static str) -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(all.iter().map(move |v| name(*v))).map(move |s| *all.iter().find(|v| name(**v) == s).expect("one of the possible values"))
}

/// `--backend`: where the frame is drawn.
const BACKENDS: [&str; 6] = ["vulkan", "gl", "gl330", "gles300", "gl430", "webgl2"];
/// `--via`: what wgpu is given.
const VIAS: [&str; 2] = ["wgsl", "spirv"];

/// Arguments of `umbrac render`.
#[derive(Debug, Clone, clap::Args)]
#[command(about = "Draw a shader program headless to PNG, on any consumer: the shadow scene, a scene file, or the scene inferred for it")]
pub struct RenderArgs {
    /// The program: a .das file compiled in process (default
    /// shaders/shadow.das), or a ready .wgsl / .spv file with the shadow
    /// scene's binding model (see --reflection; a .spv file always goes to
    /// the driver unchanged, as with --via spirv). A .das program that is
    /// not a shadow scene's is drawn with --scene FILE, or with the scene
    /// inferred for it (docs/runner.md, "Scene files").
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
    /// What wgpu gets: the WGSL (translated by wgpu) or the SPIR-V (passed
    /// to the Vulkan driver unchanged).
    #[arg(long, default_value = "wgsl", value_parser = PossibleValuesParser::new(VIAS))]
    pub via: String,
    /// Where it is drawn: wgpu on Vulkan or on its GL backend; the GLSL 330
    /// output on an OpenGL 3.3 core context or the ES 3.00 output on an
    /// OpenGL ES 3.0 context (EGL surfaceless, no wgpu); the GLSL 430 output
    /// on an OpenGL 4.3 core context (the one GL backend with compute, for
    /// --fit visible); the ES 3.00 output in WebGL2 (headless chromium).
    #[arg(long, default_value = "vulkan", value_parser = PossibleValuesParser::new(BACKENDS))]
    pub backend: String,
    /// Side of the square shadow map.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_SHADOW_SIZE)]
    pub shadow_size: u32,
    /// What to write: the shadowed scene, the sun's depth texture
    /// (greyscale: near dark, empty white), or the scene with an empty
    /// shadow map (lighting without shadows).
    #[arg(long, default_value = "final", value_parser = choice(&View::ALL, View::name))]
    pub view: View,
    /// daslang's checkout, where a .das program's `require`d modules are
    /// found (as `umbrac compile --daslang-root`).
    #[arg(long, value_name = "DIR", value_parser = umbrac::syntax::modules::parse_daslang_root)]
    pub daslang_root: Option<PathBuf>,
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
    /// A named shadow configuration (tutorial: fixed +-4 box, cube and
    /// floor in the map, 3x3 PCF; tuned: box fitted to casters and visible
    /// receivers, casters only, the hardware's 2x2 filter); the options
    /// below override its parts.
    #[arg(long, value_parser = choice(&Quality::ALL, Quality::name), conflicts_with = "scene")]
    pub quality: Option<Quality>,
    /// Shadow filter (a .das program is compiled with the matching -D PCF_TAPS_RADIUS).
    #[arg(long, value_parser = choice(&Filter::ALL, Filter::name), conflicts_with = "scene")]
    pub filter: Option<Filter>,
    /// How the light's box is fitted: the tutorial's fixed +-4, tight
    /// around the casters and the visible receivers (clipped on the CPU),
    /// or visible: fitted each frame to the receivers a compute pass finds
    /// in the camera's depth buffer (Vulkan, or --backend gl430).
    #[arg(long, value_parser = choice(&Fit::ALL, Fit::name), conflicts_with = "scene")]
    pub fit: Option<Fit>,
    /// Shadow map depth format.
    #[arg(long, value_parser = choice(&DepthFormat::ALL, DepthFormat::name), conflicts_with = "scene")]
    pub depth_format: Option<DepthFormat>,
    /// Draw only the shadow casters (the cube) into the shadow map.
    #[arg(long, num_args = 0..=1, default_missing_value = "true", value_name = "BOOL", conflicts_with = "scene")]
    pub casters_only: Option<bool>,
    /// Render one frame on every available consumer (wgpu Vulkan via WGSL
    /// and SPIR-V, wgpu GL, GL 3.3, GLES 3.0, WebGL2, the CPU reference),
    /// print their pairwise differences and write OUT.CONSUMER.png for each.
    #[arg(long, conflicts_with_all = ["reference", "compare", "frames"])]
    pub compare_backends: bool,
    /// A scene file (NAME.toml or NAME.json: docs/runner.md, "Scene files")
    /// to draw FILE with, or a shadow technique scene instead of the
    /// tutorial's (docs/gallery.md): spot, pcf, cascades, proj, cull,
    /// rgba8-depth. A technique scene has its own program and shadow setup,
    /// so it takes no FILE and none of --quality, --filter, --fit,
    /// --depth-format and --casters-only.
    #[arg(long, value_name = "FILE|NAME")]
    pub scene: Option<String>,
    /// Draw this program of FILE (its vertex entry point, or VS:FS) with
    /// the scene inferred for it, instead of the first.
    #[arg(long, value_name = "VS[:FS]", conflicts_with = "scene")]
    pub program: Option<String>,
    /// Render, then again whenever the program or a file it includes
    /// changes, until interrupted; a failed compile or render keeps the
    /// last good picture.
    #[arg(long, conflicts_with_all = ["compare_backends", "scene"])]
    pub watch: bool,
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

/// The consumer `--backend` and `--via` name together.
fn consumer(backend: &str, via: &str) -> Result<Consumer, String> {
    Ok(match (backend, via) {
        ("vulkan", "spirv") => Consumer::VulkanSpirv,
        ("vulkan", _) => Consumer::VulkanWgsl,
        ("gl", "spirv") => {
            return Err("--via spirv hands the SPIR-V to the driver unchanged, which only the Vulkan backend can take (this is gl)".into())
        }
        ("gl", _) => Consumer::WgpuGl,
        (other, "spirv") => return Err(format!("--via picks what wgpu gets; --backend {other} runs the compiler's GLSL")),
        ("gl330", _) => Consumer::Gl330,
        ("gles300", _) => Consumer::Gles300,
        ("gl430", _) => Consumer::Gl430,
        ("webgl2", _) => Consumer::WebGl2,
        (other, _) => return Err(format!("unknown --backend {other}")),
    })
}

impl RenderArgs {
    /// The library's options; an impossible combination is an error.
    pub fn options(&self) -> Result<RenderOptions, String> {
        let mut setup = Setup::of_quality(self.quality.unwrap_or_default());
        if let Some(f) = self.filter {
            setup.shadow.filter = f;
        }
        if let Some(f) = self.fit {
            setup.shadow.fit = f;
        }
        if let Some(d) = self.depth_format {
            setup.shadow.depth = d;
        }
        if let Some(c) = self.casters_only {
            setup.shadow.casters_only = c;
        }
        // A scene file is a path that says so; anything else names a technique.
        let (scene, scene_file) = match &self.scene {
            Some(s) if s.ends_with(".toml") || s.ends_with(".json") => (None, Some(PathBuf::from(s))),
            other => (other.clone(), None),
        };
        if scene.is_some() && (self.file.is_some() || self.compare_backends || self.reflection.is_some()) {
            return Err("--scene NAME draws a technique scene with its own program: it takes no FILE, --compare-backends or --reflection (a scene file, --scene FILE.toml, does)".into());
        }
        Ok(RenderOptions {
            file: self.file.clone(),
            out: self.out.clone(),
            time: self.time,
            size: self.size,
            frames: self.frames,
            fps: self.fps,
            out_dir: self.out_dir.clone(),
            consumer: consumer(&self.backend, &self.via)?,
            shadow_size: self.shadow_size,
            view: self.view,
            reflection: self.reflection.clone(),
            reference: self.reference,
            compare: self.compare,
            setup,
            compare_backends: self.compare_backends,
            scene,
            scene_file,
            program: self.program.clone(),
            pcf_taps: self.pcf_taps,
            daslang_root: self.daslang_root.clone(),
        })
    }
}

/// An indicatif bar over an animation's frames.
#[derive(Default)]
struct Bar(Option<indicatif::ProgressBar>);

impl Progress for Bar {
    fn start(&mut self, total: usize) {
        let bar = indicatif::ProgressBar::new(total as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{prefix} [{bar:40}] {pos}/{len} frames, {per_sec}, eta {eta}")
                .expect("valid template")
                .progress_chars("=> "),
        );
        bar.set_prefix("rendering");
        self.0 = Some(bar);
    }

    fn frame_done(&mut self) {
        if let Some(b) = &self.0 {
            b.inc(1);
        }
    }

    fn encoding(&mut self) {
        if let Some(b) = &self.0 {
            b.set_prefix("encoding gif");
        }
    }

    fn finish(&mut self) {
        if let Some(b) = self.0.take() {
            b.finish_and_clear();
        }
    }
}

fn run_once(opts: &RenderOptions) -> u8 {
    match command::run(opts, &mut Bar::default()) {
        Ok(()) => 0,
        Err(message) => {
            eprintln!("error: {}", message.trim_end());
            1
        }
    }
}

/// Runs `umbrac render`; returns the exit status.
pub fn run(args: &RenderArgs) -> u8 {
    let opts = match args.options() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return 1;
        }
    };
    if args.watch {
        return match umbrac::watch::watch(|| (run_once(&opts), command::watched(&opts))) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: {e}");
                1
            }
        };
    }
    run_once(&opts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: RenderArgs,
    }

    fn parse(list: &[&str]) -> Result<RenderOptions, String> {
        Cli::try_parse_from(std::iter::once("render").chain(list.iter().copied())).map_err(|e| e.to_string())?.args.options()
    }

    #[test]
    fn parses_every_option() {
        let a = parse(&[
            "x.das", "--out", "a.png", "--time", "2", "--size", "320x240", "--frames", "4", "--fps", "12", "--out-dir", "d", "--via", "spirv",
            "--backend", "vulkan", "--shadow-size", "512", "--view", "shadow-map",
        ])
        .unwrap();
        assert_eq!(a.size, (320, 240));
        assert_eq!((a.consumer, a.view), (Consumer::VulkanSpirv, View::ShadowMap));
        assert_eq!((a.frames, a.fps, a.shadow_size), (Some(4), 12.0, 512));
        assert!(parse(&["--size", "0x3"]).is_err());
        assert!(parse(&["--view", "sideways"]).is_err());
        assert_eq!(parse(&["--backend", "gl"]).unwrap().consumer, Consumer::WgpuGl);
        assert_eq!(parse(&["--backend", "gles300"]).unwrap().consumer, Consumer::Gles300);
        assert_eq!(parse(&["--backend", "gl430", "--fit", "visible"]).unwrap().consumer, Consumer::Gl430);
        assert_eq!(parse(&["--fit", "visible"]).unwrap().setup.shadow.fit, Fit::Visible);
        // A technique scene has its own shadow setup: its options are refused, not ignored.
        for opt in [&["--fit", "tight"][..], &["--quality", "tuned"], &["--casters-only"], &["--depth-format", "depth16"]] {
            let args: Vec<&str> = ["--scene", "spot"].iter().chain(opt).copied().collect();
            assert!(parse(&args).is_err(), "{args:?}");
        }
        let err = parse(&["--backend", "gl", "--via", "spirv"]).unwrap_err();
        assert!(err.contains("only the Vulkan backend"), "{err}");
        assert!(parse(&["--backend", "gl330", "--via", "spirv"]).is_err());
        let a = parse(&["x.das", "--scene", "two.toml", "--compare-backends"]).unwrap();
        assert_eq!((a.scene, a.scene_file), (None, Some(PathBuf::from("two.toml"))));
        assert!(parse(&["x.das", "--scene", "spot"]).is_err(), "a technique scene brings its own program");
        assert_eq!(parse(&["x.das", "--program", "post_vs:bright_fs"]).unwrap().program.as_deref(), Some("post_vs:bright_fs"));
    }

    #[test]
    fn quality_and_overrides() {
        assert_eq!(parse(&[]).unwrap().setup, Setup::default());
        assert_eq!(parse(&["--quality", "tuned"]).unwrap().setup, Setup::tuned());
        let s = parse(&["--quality", "tuned", "--filter", "5x5", "--depth-format", "depth16", "--casters-only", "false"]).unwrap().setup;
        assert_eq!(
            (s.shadow.filter, s.shadow.depth, s.shadow.casters_only, s.shadow.fit),
            (Filter::Pcf5x5, DepthFormat::Depth16, false, Fit::Tight)
        );
        assert!(parse(&["--casters-only"]).unwrap().setup.shadow.casters_only);
    }
}
