//! Lowering: the checked program (`sema::Program`) to naga IR.
//!
//! Two modules are built from one program, because the targets disagree on
//! conventions that are baked into the IR:
//! - `gl`: for the GLSL backends. GL conventions as written; resource
//!   globals carry no binding, so naga's namer gives them their source names
//!   (`uniform highp sampler2DShadow shadow_map;`).
//! - `gpu`: for WGSL and SPIR-V. Every resource has a group/binding, and (in
//!   the default portable conventions) every vertex entry point ends with
//!   the clip-space adaptation `z' = (z + w) / 2`, `y' = -y`.
//!
//! Both modules have the same globals, types and entry points in the same
//! order, so a handle or index from one is valid in the other.

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

/// The sampler types of the DSL.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerKind {
    Sampler2D,
    Sampler2DShadow,
    Sampler2DArray,
    Sampler2DArrayShadow,
    Sampler3D,
    SamplerCube,
    SamplerCubeShadow,
    ISampler2D,
    USampler2D,
}

impl SamplerKind {
    pub const ALL: [SamplerKind; 9] = [
        SamplerKind::Sampler2D,
        SamplerKind::Sampler2DShadow,
        SamplerKind::Sampler2DArray,
        SamplerKind::Sampler2DArrayShadow,
        SamplerKind::Sampler3D,
        SamplerKind::SamplerCube,
        SamplerKind::SamplerCubeShadow,
        SamplerKind::ISampler2D,
        SamplerKind::USampler2D,
    ];

    /// The DSL (and GLSL) type name.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Sampler2D => "sampler2D",
            SamplerKind::Sampler2DShadow => "sampler2DShadow",
            SamplerKind::Sampler2DArray => "sampler2DArray",
            SamplerKind::Sampler2DArrayShadow => "sampler2DArrayShadow",
            SamplerKind::Sampler3D => "sampler3D",
            SamplerKind::SamplerCube => "samplerCube",
            SamplerKind::SamplerCubeShadow => "samplerCubeShadow",
            SamplerKind::ISampler2D => "isampler2D",
            SamplerKind::USampler2D => "usampler2D",
        }
    }

    pub fn from_name(name: &str) -> Option<SamplerKind> {
        SamplerKind::ALL.into_iter().find(|k| k.name() == name)
    }

    pub fn is_shadow(self) -> bool {
        matches!(self, SamplerKind::Sampler2DShadow | SamplerKind::Sampler2DArrayShadow | SamplerKind::SamplerCubeShadow)
    }

    pub fn is_array(self) -> bool {
        matches!(self, SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow)
    }

    pub fn dim(self) -> naga::ImageDimension {
        match self {
            SamplerKind::Sampler3D => naga::ImageDimension::D3,
            SamplerKind::SamplerCube | SamplerKind::SamplerCubeShadow => naga::ImageDimension::Cube,
            _ => naga::ImageDimension::D2,
        }
    }

    /// The naga image class of the texture half.
    pub fn image_class(self) -> naga::ImageClass {
        match self {
            k if k.is_shadow() => naga::ImageClass::Depth { multi: false },
            SamplerKind::ISampler2D => naga::ImageClass::Sampled { kind: naga::ScalarKind::Sint, multi: false },
            SamplerKind::USampler2D => naga::ImageClass::Sampled { kind: naga::ScalarKind::Uint, multi: false },
            _ => naga::ImageClass::Sampled { kind: naga::ScalarKind::Float, multi: false },
        }
    }
}

/// A uniform block or sampler of the program, with its place in both modules.
#[derive(Clone, Debug)]
pub struct Resource {
    /// The DSL global's name.
    pub name: String,
    pub span: Span,
    pub kind: ResourceKind,
    /// The global holding the value (a uniform) or the texture (a sampler);
    /// the same handle in `gl` and `gpu`.
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
    /// Index into `module.entry_points` (the same in both modules).
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
}

/// The result of lowering: two validated modules and the interface that
/// names their parts.
#[derive(Debug)]
pub struct Lowered {
    pub gl: naga::Module,
    pub gl_info: naga::valid::ModuleInfo,
    pub gpu: naga::Module,
    pub gpu_info: naga::valid::ModuleInfo,
    pub interface: Interface,
}

pub fn lower(_program: &crate::sema::Program, _conventions: Conventions) -> Result<Lowered, crate::diag::Diagnostic> {
    Err(crate::diag::Diagnostic::bug("lowering not written yet", None))
}
