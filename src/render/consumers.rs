//! Every consumer of every emitted target, side by side: one frame of the
//! scene from one compilation on wgpu/Vulkan (WGSL and SPIR-V), wgpu's GL
//! backend (WGSL), OpenGL 3.3 core (GLSL 330), OpenGL ES 3.0 (GLSL ES
//! 3.00), WebGL2 in chromium (GLSL ES 3.00) and the CPU reference, and the
//! pairwise differences of their images (`umbrac render --compare-backends`,
//! `tests/gpu/consumers.rs`).

use std::sync::OnceLock;
use std::time::Instant;

use image::RgbaImage;

use super::glsl_set::GlslSet;
use super::gpu::{Backend, RenderError, Renderer, ShaderSet, Via};
use super::image_ops::{self, DiffStats};
use super::reference;
use super::scene::{FrameParams, View};
use super::webgl::{self, WebGl};
use crate::Target;

/// One consumer of the compiler's output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Consumer {
    /// wgpu on Vulkan, the WGSL output (translated by wgpu's naga).
    VulkanWgsl,
    /// wgpu on Vulkan, the SPIR-V output handed to the driver unchanged.
    VulkanSpirv,
    /// wgpu's OpenGL backend, the WGSL output (naga writes GLSL for it).
    WgpuGl,
    /// OpenGL 3.3 core, the `.330.*` files.
    Gl330,
    /// OpenGL ES 3.0, the `.300es.*` files.
    Gles300,
    /// WebGL2 in headless chromium, the `.300es.*` files.
    WebGl2,
    /// The CPU ray-cast reference (exact shadows).
    Reference,
}

impl Consumer {
    pub const ALL: [Consumer; 7] = [
        Consumer::VulkanWgsl,
        Consumer::VulkanSpirv,
        Consumer::WgpuGl,
        Consumer::Gl330,
        Consumer::Gles300,
        Consumer::WebGl2,
        Consumer::Reference,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Consumer::VulkanWgsl => "vulkan-wgsl",
            Consumer::VulkanSpirv => "vulkan-spirv",
            Consumer::WgpuGl => "wgpu-gl",
            Consumer::Gl330 => "gl330",
            Consumer::Gles300 => "gles300",
            Consumer::WebGl2 => "webgl2",
            Consumer::Reference => "reference",
        }
    }

    /// What runs what.
    pub fn description(self) -> &'static str {
        match self {
            Consumer::VulkanWgsl => "WGSL on wgpu/Vulkan",
            Consumer::VulkanSpirv => "SPIR-V on wgpu/Vulkan (passthrough)",
            Consumer::WgpuGl => "WGSL on wgpu's GL backend",
            Consumer::Gl330 => "GLSL 330 on an OpenGL 3.3 core context",
            Consumer::Gles300 => "GLSL ES 3.00 on an OpenGL ES 3.0 context",
            Consumer::WebGl2 => "GLSL ES 3.00 on WebGL2 in chromium",
            Consumer::Reference => "CPU ray-cast reference",
        }
    }

    /// Whether it runs the compiler's output on a GPU API (not the reference).
    pub fn is_gpu(self) -> bool {
        self != Consumer::Reference
    }
}

/// The compiled program in every form the consumers take.
pub struct Programs {
    pub label: String,
    pub wgsl: ShaderSet,
    pub spirv: ShaderSet,
    pub glsl330: GlslSet,
    pub gles300: GlslSet,
}

impl Programs {
    /// Every form from one compilation (for all targets).
    pub fn from_compiled(label: &str, compiled: &crate::Compiled) -> Result<Programs, String> {
        Ok(Programs {
            label: label.to_string(),
            wgsl: ShaderSet::from_compiled(label, compiled, Via::Wgsl).map_err(|e| e.to_string())?,
            spirv: ShaderSet::from_compiled(label, compiled, Via::Spirv).map_err(|e| e.to_string())?,
            glsl330: GlslSet::from_compiled(label, compiled, Target::Glsl330)?,
            gles300: GlslSet::from_compiled(label, compiled, Target::Gles300)?,
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

/// wgpu's GL backend lives for the whole process: dropping its last device
/// terminates the EGL display, which it shares with [`super::gl`]'s
/// contexts (both use Mesa's surfaceless platform). Open it before any
/// [`super::gl::GlRenderer`].
pub fn wgpu_gl() -> Result<&'static Renderer, String> {
    static R: OnceLock<Result<Renderer, String>> = OnceLock::new();
    R.get_or_init(|| Renderer::new(Backend::Gl).map_err(|e| e.to_string())).as_ref().map_err(|e| e.clone())
}

/// The Vulkan device, one per process.
pub fn vulkan() -> Result<&'static Renderer, RenderError> {
    static R: OnceLock<Result<Renderer, RenderError>> = OnceLock::new();
    R.get_or_init(|| Renderer::new(Backend::Vulkan)).as_ref().map_err(|e| e.clone())
}

fn timed(f: impl FnOnce() -> Result<(RgbaImage, String), Status>) -> Status {
    let started = Instant::now();
    match f() {
        Ok((image, device)) => Status::Rendered { image, device, ms: started.elapsed().as_secs_f64() * 1e3 },
        Err(s) => s,
    }
}

fn wgpu_status(e: RenderError) -> Status {
    match e {
        RenderError::NoAdapter { backend, detail } => Status::Unavailable {
            why: format!("no wgpu {} adapter ({detail})", backend.name()),
            install: match backend {
                Backend::Vulkan => "apt-get install mesa-vulkan-drivers libvulkan1 (lavapipe)".into(),
                Backend::Gl => "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri (llvmpipe)".into(),
            },
        },
        RenderError::MissingFeature { feature, why } => {
            Status::Unavailable { why: format!("the adapter lacks {feature} ({why})"), install: "a Vulkan driver with it (lavapipe has it)".into() }
        }
        other => Status::Failed(other.to_string()),
    }
}

/// Renders one frame on one consumer. GPU consumers that are not
/// installed say so; the GL ones open (and close) their context here.
pub fn render(consumer: Consumer, programs: &Programs, params: &FrameParams) -> Status {
    match consumer {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv => timed(|| {
            let r = vulkan().map_err(|e| wgpu_status(e.clone()))?;
            let set = if consumer == Consumer::VulkanWgsl { &programs.wgsl } else { &programs.spirv };
            let image = r.render(set, params).map_err(wgpu_status)?;
            Ok((image, r.adapter_name()))
        }),
        Consumer::WgpuGl => timed(|| {
            let r = wgpu_gl().map_err(|e| Status::Unavailable {
                why: e,
                install: "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri (llvmpipe)".into(),
            })?;
            let image = r.render(&programs.wgsl, params).map_err(wgpu_status)?;
            Ok((image, r.adapter_name()))
        }),
        Consumer::Gl330 | Consumer::Gles300 => render_gl(consumer, programs, params),
        Consumer::WebGl2 => {
            let tools = match WebGl::find() {
                Ok(t) => t,
                Err(why) => return Status::Unavailable { why, install: webgl::INSTALL_HINT.into() },
            };
            timed(|| {
                let f = tools.render(&programs.gles300, params).map_err(Status::Failed)?;
                Ok((f.image, format!("{} (chromium {})", f.renderer, f.browser)))
            })
        }
        Consumer::Reference => timed(|| Ok((reference::render(params), "CPU".into()))),
    }
}

#[cfg(feature = "gl")]
fn render_gl(consumer: Consumer, programs: &Programs, params: &FrameParams) -> Status {
    use super::gl::{GlApi, GlError, GlRenderer};
    let (api, set) = match consumer {
        Consumer::Gl330 => (GlApi::Gl330, &programs.glsl330),
        _ => (GlApi::Gles300, &programs.gles300),
    };
    // See `wgpu_gl`: its display must outlive these contexts.
    let _ = wgpu_gl();
    let r = match GlRenderer::new(api) {
        Ok(r) => r,
        Err(GlError::Unavailable(why)) => {
            return Status::Unavailable { why, install: GlApi::install_hint().trim_start_matches("on Debian/Ubuntu: ").into() }
        }
        Err(e) => return Status::Failed(e.to_string()),
    };
    timed(|| {
        let image = r.render(set, params).map_err(|e| Status::Failed(e.to_string()))?;
        Ok((image, r.adapter_name()))
    })
}

#[cfg(not(feature = "gl"))]
fn render_gl(_: Consumer, _: &Programs, _: &FrameParams) -> Status {
    Status::Unavailable {
        why: "umbrac was built without the `gl` feature".into(),
        install: "cargo build --features gl (no system packages needed to build)".into(),
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
