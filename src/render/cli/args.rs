//! The arguments of `umbrac render` (clap), and their checks.

use std::path::PathBuf;

use crate::render::scene::DEFAULT_SHADOW_SIZE;
use super::setup_args::SetupArgs;

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
    pub setup: SetupArgs,
    /// Render one frame on every available consumer (wgpu Vulkan via WGSL
    /// and SPIR-V, wgpu GL, GL 3.3, GLES 3.0, WebGL2, the CPU reference),
    /// print their pairwise differences and write OUT.CONSUMER.png for each.
    #[arg(long, conflicts_with_all = ["reference", "compare", "frames"])]
    pub compare_backends: bool,
    /// A shadow technique scene instead of the tutorial's (docs/gallery.md):
    /// spot, pcf, cascades, proj, cull, rgba8-depth.
    #[arg(long, value_name = "NAME", conflicts_with_all = ["file", "compare_backends", "reflection"])]
    pub scene: Option<String>,
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
