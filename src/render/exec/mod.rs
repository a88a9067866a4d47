//! The executors: run any frame plan with any program on a consumer.
//! [`wgpu`] (Vulkan and wgpu's GL backend; WGSL, or SPIR-V handed to
//! Vulkan unchanged), [`gl`] (GLSL 330 on an OpenGL 3.3 core context, GLSL
//! ES 3.00 on an OpenGL ES 3.0 context), [`webgl`] (GLSL ES 3.00 in WebGL2
//! in chromium, fed the same plan as JSON). Each binds what
//! [`crate::render::bind`] resolves from the manifest, and fails with one
//! error type, [`ExecError`].

#[cfg(feature = "gl")]
pub mod gl;
pub mod webgl;
pub mod wgpu;

use image::RgbaImage;

use super::bind::InterfaceError;
use super::consumer::Consumer;
use super::plan::FramePlan;
use super::program::ShaderSet;

/// Everything that can stop an executor. Displayed as a one-paragraph
/// message for the command line.
#[derive(Clone, Debug)]
pub enum ExecError {
    /// The consumer is not installed here: why, and how to install it.
    Unavailable { consumer: Consumer, why: String, install: String },
    /// The program does not fit the plan.
    Interface(InterfaceError),
    /// A module or shader did not compile: the API's log.
    Compile { file: String, log: String },
    /// A pass's program (a GL program, a wgpu pipeline) could not be made.
    Link { pass: String, log: String },
    /// The program could not be loaded, or a linked program disagrees with
    /// what it must bind.
    Program(String),
    /// The API reported an error while drawing (validation, out of memory,
    /// a GL error, an incomplete framebuffer, the page failing).
    Api(String),
    /// A request this consumer cannot do (a zero size, `--via spirv` on
    /// GL, depth read back on GLES).
    Unsupported(String),
}

impl std::fmt::Display for ExecError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExecError::Unavailable { consumer, why, install } => write!(f, "{} is unavailable: {why}; install: {install}", consumer.name()),
            ExecError::Interface(e) => write!(f, "{}", e.to_string().trim_end()),
            ExecError::Compile { file, log } => write!(f, "{file} does not compile: {}", log.trim_end()),
            ExecError::Link { pass, log } => write!(f, "the {pass} pass's program does not link: {}", log.trim_end()),
            ExecError::Program(m) | ExecError::Api(m) | ExecError::Unsupported(m) => write!(f, "{}", m.trim_end()),
        }
    }
}

impl std::error::Error for ExecError {}

impl From<InterfaceError> for ExecError {
    fn from(e: InterfaceError) -> Self {
        ExecError::Interface(e)
    }
}

/// What comes back of a compute dispatch: the bytes of each buffer and
/// image the plan reads back, by name (images: texel rows in coordinate
/// order, y = 0 first, layers after each other).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ComputeReadback {
    pub resources: std::collections::BTreeMap<String, Vec<u8>>,
}

impl ComputeReadback {
    /// The bytes of `name` as little-endian 32-bit words.
    pub fn words(&self, name: &str) -> Option<Vec<u32>> {
        let b = self.resources.get(name)?;
        Some(b.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect())
    }
}

/// What comes back of a frame: the read-back target's texels, top row of
/// the GL picture first.
#[derive(Clone, Debug, PartialEq)]
pub enum Readback {
    Rgba8(RgbaImage),
    /// Depths in [0, 1].
    Depth { width: u32, height: u32, depths: Vec<f32> },
    /// Four words per texel.
    Words { width: u32, height: u32, words: Vec<u32> },
}

impl Readback {
    /// The picture: colour as it is, depth as greyscale
    /// ([`super::image_ops::depth_to_grey`]), words as their low bytes.
    pub fn into_image(self) -> RgbaImage {
        match self {
            Readback::Rgba8(image) => image,
            Readback::Depth { width, height, depths } => {
                let bytes: Vec<u8> = depths.iter().flat_map(|d| d.to_le_bytes()).collect();
                super::image_ops::depth_to_grey(width, height, &bytes)
            }
            Readback::Words { width, height, words } => {
                RgbaImage::from_raw(width, height, words.iter().map(|w| *w as u8).collect()).expect("four words per texel")
            }
        }
    }

    /// Four words per texel (the integer target of self-checking programs).
    pub fn words(&self) -> Option<Vec<[u32; 4]>> {
        match self {
            Readback::Words { words, .. } => Some(words.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]).collect()),
            _ => None,
        }
    }
}

/// A consumer that runs frame plans.
pub trait Executor {
    /// A program made ready to run plans (modules compiled, pipelines or
    /// GL programs linked, checked against the plan it was prepared for).
    type Prepared;

    /// Fits `set` to `plan`, compiles it and makes what its passes need.
    fn prepare(&self, set: &ShaderSet, plan: &FramePlan) -> Result<Self::Prepared, ExecError>;

    /// Runs one frame. A plan of another shape than the one `prepared`
    /// was made for (another view, depth format, technique) makes what it
    /// needs on first use.
    fn run(&self, prepared: &Self::Prepared, plan: &FramePlan) -> Result<Readback, ExecError>;

    /// The device or driver it runs on, for messages.
    fn device_name(&self) -> String;
}

/// Checks what every executor refuses the same way: sizes of 0.
pub fn check_sizes(plan: &FramePlan, max: u32) -> Result<(), ExecError> {
    plan.check().map_err(ExecError::Unsupported)?;
    for t in &plan.targets {
        if t.width.max(t.height) > max {
            return Err(ExecError::Unsupported(format!(
                "{} pixels ({}) exceeds this device's texture limit of {max}",
                t.width.max(t.height),
                t.name
            )));
        }
    }
    Ok(())
}

/// The tutorial's shadow scene ([`super::plan::tutorial`]) on any executor.
pub trait SceneExecutor: Executor {
    /// Prepares `set` for the scene (every pass of the `final` view).
    fn prepare_scene(&self, set: &ShaderSet) -> Result<Self::Prepared, ExecError> {
        self.prepare(set, &super::plan::tutorial::plan(&super::scene::FrameParams::new(0.0, 16, 16)))
    }

    /// One frame of the scene, top row first.
    fn draw_scene(&self, prepared: &Self::Prepared, params: &super::scene::FrameParams) -> Result<RgbaImage, ExecError> {
        Ok(self.run(prepared, &super::plan::tutorial::plan(params))?.into_image())
    }

    /// [`prepare_scene`](Self::prepare_scene) then [`draw_scene`](Self::draw_scene).
    fn render_scene(&self, set: &ShaderSet, params: &super::scene::FrameParams) -> Result<RgbaImage, ExecError> {
        let plan = super::plan::tutorial::plan(params);
        let prepared = self.prepare(set, &plan)?;
        Ok(self.run(&prepared, &plan)?.into_image())
    }
}

impl<E: Executor> SceneExecutor for E {}
