//! Which consumer runs the compiler's output: the one enum every executor,
//! binder and command names ([`Consumer`]). It sits below everything
//! else in `render/`, so that the executors need not import the module that
//! runs them ([`super::consumers`]).

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
    /// The CPU ray-cast reference (exact shadows; the tutorial and
    /// technique scenes only).
    Reference,
    /// OpenGL 4.3 core, the `.430.*` files: compute plans, and the shadow
    /// scene's frames through `umbrac render --backend gl430` (for
    /// `--fit visible`; not one of [`Consumer::ALL`]'s side-by-side set).
    Gl430,
    /// OpenGL ES 3.1, the `.310es.*` files: compute plans only.
    Gles310,
}

impl Consumer {
    pub const ALL: [Consumer; 7] =
        [Consumer::VulkanWgsl, Consumer::VulkanSpirv, Consumer::WgpuGl, Consumer::Gl330, Consumer::Gles300, Consumer::WebGl2, Consumer::Reference];

    pub fn name(self) -> &'static str {
        match self {
            Consumer::VulkanWgsl => "vulkan-wgsl",
            Consumer::VulkanSpirv => "vulkan-spirv",
            Consumer::WgpuGl => "wgpu-gl",
            Consumer::Gl330 => "gl330",
            Consumer::Gles300 => "gles300",
            Consumer::WebGl2 => "webgl2",
            Consumer::Reference => "reference",
            Consumer::Gl430 => "gl430",
            Consumer::Gles310 => "gles310",
        }
    }

    /// The consumers that run compute plans (`WgpuExecutor::run_compute`,
    /// `GlExecutor::run_compute`); the GL 4.3 / ES 3.1 ones run nothing else.
    pub const COMPUTE: [Consumer; 4] = [Consumer::VulkanWgsl, Consumer::VulkanSpirv, Consumer::Gl430, Consumer::Gles310];

    pub fn from_name(name: &str) -> Option<Consumer> {
        Consumer::ALL.into_iter().chain(Consumer::COMPUTE).find(|c| c.name() == name)
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
            Consumer::Gl430 => "GLSL 430 on an OpenGL 4.3 core context (compute)",
            Consumer::Gles310 => "GLSL ES 3.10 on an OpenGL ES 3.1 context (compute)",
        }
    }

    /// Whether it runs the compiler's output on a GPU API (not the reference).
    pub fn is_gpu(self) -> bool {
        self != Consumer::Reference
    }

    /// The compiler output it runs.
    pub fn target(self) -> Option<Target> {
        Some(match self {
            Consumer::VulkanWgsl | Consumer::WgpuGl => Target::Wgsl,
            Consumer::VulkanSpirv => Target::Spirv,
            Consumer::Gl330 => Target::Glsl330,
            Consumer::Gles300 | Consumer::WebGl2 => Target::Gles300,
            Consumer::Gl430 => Target::Glsl430,
            Consumer::Gles310 => Target::Gles310,
            Consumer::Reference => return None,
        })
    }
}
