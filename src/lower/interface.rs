//! What lowering hands `emit`: the validated modules and the interface that
//! names their parts (resources with their bindings and texture units,
//! each entry point's inputs, outputs, builtins and resources). `emit`
//! and the reflection manifest read only this.

use crate::sema::SamplerKind;
use crate::source::Span;

/// How WGSL/SPIR-V outputs treat clip space and framebuffer orientation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Conventions {
    /// The default: adapt GL-convention code so the same host math gives the
    /// same picture on WebGPU/Vulkan (z remapped to [0, w], y flipped; the
    /// host flips the final image and uses clockwise front faces).
    #[default]
    Portable,
    /// Emit as written: the shader author handles WebGPU/Vulkan conventions.
    Native,
}

impl Conventions {
    pub fn as_str(self) -> &'static str {
        match self {
            Conventions::Portable => "portable",
            Conventions::Native => "native",
        }
    }
}

/// A uniform block or sampler of the program, with its place in the GPU
/// module.
#[derive(Clone, Debug)]
pub struct Resource {
    /// The DSL global's name.
    pub name: String,
    pub span: Span,
    pub kind: ResourceKind,
    /// The global holding the value (a uniform) or the texture (a sampler)
    /// in `gpu` (a GL module has the global under the same name).
    pub global: naga::Handle<naga::GlobalVariable>,
    /// The separate sampler global of a sampler resource.
    pub sampler_global: Option<naga::Handle<naga::GlobalVariable>>,
    pub group: u32,
    /// Binding of the uniform buffer, or of the texture.
    pub binding: u32,
    /// Binding of the sampler of a sampler resource.
    pub sampler_binding: Option<u32>,
    /// GL texture unit of a sampler resource.
    pub texture_unit: Option<u32>,
    /// The host's default value of a uniform (`var @uniform x : T = value`).
    pub default: Option<crate::sema::ConstValue>,
}

#[derive(Clone, Debug)]
pub enum ResourceKind {
    /// `ty` is the global's type: a struct for a struct uniform, else the
    /// loose value's type. `dsl_type` is its DSL spelling.
    Uniform { ty: naga::Handle<naga::Type>, dsl_type: String },
    Sampler(SamplerKind),
}

/// One vertex attribute, varying or fragment output of an entry point.
#[derive(Clone, Debug)]
pub struct IoVar {
    pub name: String,
    pub location: u32,
    pub ty: naga::Handle<naga::Type>,
    pub dsl_type: String,
    pub interpolation: Option<naga::Interpolation>,
}

#[derive(Clone, Debug)]
pub struct EntryInterface {
    /// The entry point's name; also `module.entry_points[index].name`.
    pub name: String,
    pub stage: naga::ShaderStage,
    /// Index into `gpu.entry_points`, and into `Lowered::gl`.
    pub index: usize,
    pub inputs: Vec<IoVar>,
    pub outputs: Vec<IoVar>,
    /// DSL names of builtins used (`gl_Position`, `gl_FragCoord`, ...).
    pub builtins: Vec<String>,
    /// Indices into `Interface::resources` that this entry point uses.
    pub resources: Vec<usize>,
}

#[derive(Clone, Debug, Default)]
pub struct Interface {
    pub conventions: Conventions,
    pub resources: Vec<Resource>,
    pub entry_points: Vec<EntryInterface>,
    /// `(vertex, fragment)` indices into `entry_points` of the entry
    /// points that form one program (`sema::Link`).
    pub links: Vec<(usize, usize)>,
}

/// The GL module of one entry point (its only entry point), validated.
#[derive(Debug)]
pub struct GlEntry {
    pub module: naga::Module,
    pub info: naga::valid::ModuleInfo,
}

/// The result of lowering: the validated modules and the interface that
/// names their parts.
#[derive(Debug)]
pub struct Lowered {
    /// Per entry point, in the order of `interface.entry_points`.
    pub gl: Vec<GlEntry>,
    pub gpu: naga::Module,
    pub gpu_info: naga::valid::ModuleInfo,
    pub interface: Interface,
}

/// Which module is being built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flavor {
    /// For the GLSL backends: no bindings, GL conventions.
    Gl,
    /// For WGSL and SPIR-V: bindings, and the clip-space adaptation when
    /// the conventions are portable.
    Gpu(Conventions),
}

