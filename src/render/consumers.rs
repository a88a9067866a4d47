//! Every consumer of every emitted target, side by side: a compiled
//! program in the form each takes ([`Programs`]), running a plan on any of
//! them ([`run`]), and the tutorial scene on each with the pairwise differences of their images
//! (`umbrac render --compare-backends`, `tests/gpu/consumers.rs`).

use std::sync::OnceLock;
use std::time::Instant;

use image::RgbaImage;

use super::exec::{wgpu::WgpuExecutor, webgl::WebGl, ExecError, Executor, Readback};
use super::image_ops::{self, DiffStats};
use super::plan::FramePlan;
use super::program::ShaderSet;
use super::reference;
use super::scene::{FrameParams, View};
pub use super::consumer::Consumer;
use crate::Target;

/// The compiled program in every form the consumers take.
#[derive(Clone, Debug)]
pub struct Programs {
    pub label: String,
    pub wgsl: ShaderSet,
    pub spirv: ShaderSet,
    pub glsl330: ShaderSet,
    pub gles300: ShaderSet,
}

impl Programs {
    /// Every form from one compilation (for all targets).
    pub fn from_compiled(label: &str, compiled: &crate::Compiled) -> Result<Programs, String> {
        Ok(Programs {
            label: label.to_string(),
            wgsl: ShaderSet::from_compiled(label, compiled, Target::Wgsl)?,
            spirv: ShaderSet::from_compiled(label, compiled, Target::Spirv)?,
            glsl330: ShaderSet::from_compiled(label, compiled, Target::Glsl330)?,
            gles300: ShaderSet::from_compiled(label, compiled, Target::Gles300)?,
        })
    }

    /// Compiles DSL text for every target.
    pub fn compile_source(name: &str, text: &str) -> Result<Programs, String> {
        let c = crate::compile_source(name, text, &crate::Options::default());
        match c.result.as_ref() {
            Some(compiled) if !c.has_errors() => Programs::from_compiled(name, compiled),
            _ => Err(format!("{name} did not compile:\n{}", c.render_diagnostics())),
        }
    }

    /// The form `c` runs (none for the reference).
    pub fn for_consumer(&self, c: Consumer) -> Option<&ShaderSet> {
        Some(match c.target()? {
            Target::Wgsl => &self.wgsl,
            Target::Spirv => &self.spirv,
            Target::Glsl330 => &self.glsl330,
            Target::Gles300 => &self.gles300,
            // No consumer runs these yet.
            Target::Glsl430 | Target::Gles310 => return None,
        })
    }
}

/// What one consumer did with a frame.
#[derive(Clone, Debug)]
pub enum Status {
    Rendered {
        image: RgbaImage,
        /// The device or driver it ran on.
        device: String,
        ms: f64,
    },
    /// The consumer is not installed here: why, and how to install it.
    Unavailable { why: String, install: String },
    /// It is installed and the frame failed (a compile error, a driver
    /// error): a real failure.
    Failed(String),
}

impl Status {
    pub fn image(&self) -> Option<&RgbaImage> {
        match self {
            Status::Rendered { image, .. } => Some(image),
            _ => None,
        }
    }
}

impl From<ExecError> for Status {
    fn from(e: ExecError) -> Status {
        match e {
            ExecError::Unavailable { why, install, .. } => Status::Unavailable { why, install },
            other => Status::Failed(other.to_string()),
        }
    }
}

/// wgpu's GL backend lives for the whole process: dropping its last device
/// terminates the EGL display, which it shares with the GL executor's
/// contexts (both use Mesa's surfaceless platform). Open it before any
/// [`super::exec::gl::GlExecutor`].
pub fn wgpu_gl() -> Result<&'static WgpuExecutor, ExecError> {
    static R: OnceLock<Result<WgpuExecutor, ExecError>> = OnceLock::new();
    R.get_or_init(|| WgpuExecutor::new(Consumer::WgpuGl)).as_ref().map_err(|e| e.clone())
}

/// The Vulkan device, one per process (both Vulkan consumers).
pub fn vulkan() -> Result<&'static WgpuExecutor, ExecError> {
    static R: OnceLock<Result<WgpuExecutor, ExecError>> = OnceLock::new();
    R.get_or_init(|| WgpuExecutor::new(Consumer::VulkanWgsl)).as_ref().map_err(|e| e.clone())
}

fn once<E: Executor>(e: &E, set: &ShaderSet, plan: &FramePlan) -> Result<(Readback, String), ExecError> {
    let prepared = e.prepare(set, plan)?;
    Ok((e.run(&prepared, plan)?, e.device_name()))
}

/// Runs `plan` with `set` (in the form `consumer` takes) on `consumer`,
/// opening (and closing) a GL context or a browser for it. Returns what
/// came back and the device it ran on.
pub fn run(consumer: Consumer, set: &ShaderSet, plan: &FramePlan) -> Result<(Readback, String), ExecError> {
    match consumer {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => once(vulkan()?, set, plan),
        Consumer::WgpuGl => once(wgpu_gl()?, set, plan),
        Consumer::Gl330 | Consumer::Gles300 | Consumer::Gl430 => run_gl(consumer, set, plan),
        Consumer::WebGl2 => once(&WebGl::find()?, set, plan),
        Consumer::Reference => Err(ExecError::Unsupported("the CPU reference draws its scenes itself, not plans".into())),
        Consumer::Gles310 => Err(ExecError::Unsupported(format!("{} runs compute plans only (`run_compute`)", consumer.name()))),
    }
}

/// Runs a compute plan with `set` on `consumer` (one of
/// [`Consumer::COMPUTE`]): what came back and the device it ran on.
pub fn run_compute(consumer: Consumer, set: &ShaderSet, plan: &super::plan::compute::ComputePlan) -> Result<(super::exec::ComputeReadback, String), ExecError> {
    match consumer {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => {
            let e = vulkan()?;
            Ok((e.run_compute(set, plan)?, e.adapter_name()))
        }
        Consumer::Gl430 | Consumer::Gles310 => run_gl_compute(consumer, set, plan),
        other => Err(ExecError::Unsupported(format!(
            "{} runs no compute programs (WebGL2 and OpenGL 3.3 / ES 3.0 have none; the compute consumers: vulkan-wgsl, vulkan-spirv, gl430, gles310)",
            other.name()
        ))),
    }
}

#[cfg(feature = "gl")]
fn run_gl_compute(consumer: Consumer, set: &ShaderSet, plan: &super::plan::compute::ComputePlan) -> Result<(super::exec::ComputeReadback, String), ExecError> {
    let _ = wgpu_gl();
    let e = super::exec::gl::GlExecutor::new(consumer)?;
    Ok((e.run_compute(set, plan)?, e.adapter_name()))
}

#[cfg(not(feature = "gl"))]
fn run_gl_compute(consumer: Consumer, _: &ShaderSet, _: &super::plan::compute::ComputePlan) -> Result<(super::exec::ComputeReadback, String), ExecError> {
    Err(ExecError::Unavailable {
        consumer,
        why: "umbrac was built without the `gl` feature".into(),
        install: "cargo build --features gl (no system packages needed to build)".into(),
    })
}

#[cfg(feature = "gl")]
fn run_gl(consumer: Consumer, set: &ShaderSet, plan: &FramePlan) -> Result<(Readback, String), ExecError> {
    // See `wgpu_gl`: its display must outlive these contexts.
    let _ = wgpu_gl();
    once(&super::exec::gl::GlExecutor::new(consumer)?, set, plan)
}

#[cfg(not(feature = "gl"))]
fn run_gl(consumer: Consumer, _: &ShaderSet, _: &FramePlan) -> Result<(Readback, String), ExecError> {
    Err(ExecError::Unavailable {
        consumer,
        why: "umbrac was built without the `gl` feature".into(),
        install: "cargo build --features gl (no system packages needed to build)".into(),
    })
}

/// Renders one frame of the tutorial scene on one consumer.
pub fn render(consumer: Consumer, programs: &Programs, params: &FrameParams) -> Status {
    let started = Instant::now();
    let result = match programs.for_consumer(consumer) {
        None => Ok((reference::render(params), "CPU".to_string())),
        Some(set) => run(consumer, set, &super::command::scene_plan(set)(params)).map(|(r, device)| (r.into_image(), device)),
    };
    match result {
        Ok((image, device)) => Status::Rendered { image, device, ms: started.elapsed().as_secs_f64() * 1e3 },
        Err(e) => e.into(),
    }
}

/// The difference between two consumers' images.
#[derive(Clone, Debug)]
pub struct PairDiff {
    pub a: Consumer,
    pub b: Consumer,
    pub stats: DiffStats,
    /// Whether pixels outside the sun's box were skipped (pairs with the
    /// reference, where the GPU's answer there is the clamped edge texels').
    pub masked: bool,
}

/// Every pair of rendered images, compared with `delta`. Pairs with the
/// reference skip the pixels it marks as outside the shadow map.
pub fn pairwise(results: &[(Consumer, Status)], params: &FrameParams, delta: u8) -> Vec<PairDiff> {
    let skip = (params.view == View::Final).then(|| reference::render_frame(params).outside_shadow_map);
    let mut out = Vec::new();
    for (i, (a, sa)) in results.iter().enumerate() {
        for (b, sb) in &results[i + 1..] {
            let (Some(ia), Some(ib)) = (sa.image(), sb.image()) else { continue };
            let masked = (*a == Consumer::Reference || *b == Consumer::Reference) && skip.is_some();
            let mask = if masked { skip.as_deref() } else { None };
            out.push(PairDiff { a: *a, b: *b, stats: image_ops::diff_masked(ia, ib, delta, mask), masked });
        }
    }
    out
}

/// The comparison as a Markdown table: one row per pair.
pub fn table(pairs: &[PairDiff], delta: u8) -> String {
    let mut s = format!("| pair | pixels over {delta}/255 | max | mean |\n|---|---|---|---|\n");
    for p in pairs {
        s.push_str(&format!(
            "| {} vs {}{} | {} of {} ({:.3} %) | {} | {:.3} |\n",
            p.a.name(),
            p.b.name(),
            if p.masked { " *" } else { "" },
            p.stats.over,
            p.stats.pixels,
            100.0 * p.stats.fraction_over,
            p.stats.max,
            p.stats.mean
        ));
    }
    s
}
