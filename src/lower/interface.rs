//! What lowering hands `emit`: the validated modules and the interface that
//! names their parts (resources with their bindings and texture units,
//! each entry point's inputs, outputs, builtins and resources). `emit`
//! and the reflection manifest read only this.

use crate::sema::SamplerKind;
use crate::source::Span;

/// How WGSL/SPIR-V outputs treat clip space and framebuffer orientation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
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

/// How GLSL declares the loose uniforms (those that are not structs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GlUniforms {
    /// `uniform mat4 u_model;`, set by name with `glUniform*`, as daslang's
    /// own generator writes them.
    #[default]
    Plain,
    /// One std140 block per `@set` group (`uniforms_ubo`), laid out as the
    /// WGSL/SPIR-V uniform buffer, for hosts that use uniform buffers.
    Blocks,
}

impl GlUniforms {
    pub fn as_str(self) -> &'static str {
        match self {
            GlUniforms::Plain => "plain",
            GlUniforms::Blocks => "blocks",
        }
    }
}

/// How lowering builds the modules.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LowerOptions {
    pub conventions: Conventions,
    pub gl_uniforms: GlUniforms,
    /// Whether SPIR-V will be written: a program with specialization
    /// constants then gets [`Lowered::spirv`] (true by default; the
    /// driver clears it when SPIR-V is not a target).
    pub spirv: bool,
}

impl Default for LowerOptions {
    fn default() -> Self {
        LowerOptions { conventions: Conventions::default(), gl_uniforms: GlUniforms::default(), spirv: true }
    }
}

impl From<Conventions> for LowerOptions {
    fn from(conventions: Conventions) -> Self {
        LowerOptions { conventions, ..LowerOptions::default() }
    }
}

/// A uniform buffer (a struct uniform, or the loose uniforms of one
/// group) or a sampler of the program, with its place in the GPU module.
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
    /// GL texture unit of a sampler resource; the GL binding point of a
    /// storage buffer, the image unit of a storage image (numbered apart,
    /// in declaration order: `layout(binding = N)` in GLSL 430 / ES 3.10).
    pub texture_unit: Option<u32>,
    /// The host's default value of a struct uniform (`var @uniform x : T
    /// = value`); a loose uniform's is its [`LooseUniform::default`].
    pub default: Option<crate::sema::ConstValue>,
    /// The length of a descriptor array (a Vulkan-dialect `sampler2D[N]`:
    /// one binding, N elements, a naga binding array); `None` otherwise.
    pub count: Option<u32>,
}

/// A loose uniform (not a struct): a member of its group's uniform buffer
/// on WGSL/SPIR-V (and in GLSL's blocks form), a plain `uniform T name;`
/// in GLSL otherwise.
#[derive(Clone, Debug)]
pub struct LooseUniform {
    pub name: String,
    pub span: Span,
    /// The DSL type, and its spelling.
    pub ty: crate::sema::Ty,
    pub dsl_type: String,
    /// The type it is stored as in the buffer, where that differs
    /// (`uint` for `bool`, `float4[9]` for `float[9]`, `float4[3]` for
    /// `float3x2`): its spelling, and the stored type in the GPU module.
    pub storage: Option<String>,
    pub stored_ty: naga::Handle<naga::Type>,
    /// Its own type in the GPU module.
    pub value_ty: naga::Handle<naga::Type>,
    /// Index into `Interface::resources` of its buffer, and its member
    /// index there.
    pub buffer: usize,
    pub member: u32,
    /// The host's default value (`var @uniform x : T = value`).
    pub default: Option<crate::sema::ConstValue>,
}

#[derive(Clone, Debug)]
pub enum ResourceKind {
    /// `ty` is the global's type: the struct of a struct uniform, or the
    /// buffer struct holding a group's loose uniforms (`loose`, whose
    /// members are `Interface::loose` entries). `dsl_type` is its name.
    Uniform { ty: naga::Handle<naga::Type>, dsl_type: String, loose: bool },
    Sampler(SamplerKind),
    /// `@ssbo`: `ty` is the buffer's struct (std430, atomic members where
    /// atomics operate on them), `dsl_type` its name.
    Storage { ty: naga::Handle<naga::Type>, dsl_type: String, access: crate::sema::types::Access },
    /// A storage image.
    Image { kind: crate::sema::types::ImageKind, format: crate::sema::types::ImageFormat, access: crate::sema::types::Access },
}

/// One vertex attribute, varying or fragment output of an entry point.
#[derive(Clone, Debug)]
pub struct IoVar {
    pub name: String,
    pub location: u32,
    /// The source gives the location (`@location = N`): GLSL declares it
    /// (`layout(location = N)`); otherwise a GL host binds by name.
    pub explicit_location: bool,
    /// The global's declaration.
    pub span: Span,
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
    /// Indices into `Interface::loose` of the loose uniforms it reads.
    pub loose: Vec<usize>,
    /// A compute entry point's `local_size_*`; `[0; 3]` otherwise.
    pub workgroup_size: [u32; 3],
    /// The `@groupshared` variables it uses: names and declarations.
    pub workgroup: Vec<(String, Span)>,
    /// The entry point's stage annotation (`[compute_program(...)]`).
    pub span: Span,
    /// The dialect it is written in (its conventions, its varyings' GL names).
    pub dialect: crate::syntax::ast::Dialect,
}

#[derive(Clone, Debug, Default)]
pub struct Interface {
    pub conventions: Conventions,
    /// The names of the `@push_constant` globals: uniform buffers, marked
    /// in the manifest.
    pub push_constants: Vec<String>,
    pub gl_uniforms: GlUniforms,
    pub resources: Vec<Resource>,
    /// The loose uniforms any entry point reads, in declaration order.
    pub loose: Vec<LooseUniform>,
    pub entry_points: Vec<EntryInterface>,
    /// `(vertex, fragment)` indices into `entry_points` of the entry
    /// points that form one program (`sema::Link`).
    pub links: Vec<(usize, usize)>,
    /// The GL uniform-buffer binding point of each resource GLSL declares
    /// a uniform block for, by resource index (`uniforms::gl_block_points`).
    pub gl_block_points: Vec<Option<u32>>,
}

/// The GL module of one entry point (its only entry point), validated.
#[derive(Debug)]
pub struct GlEntry {
    pub module: naga::Module,
    pub info: naga::valid::ModuleInfo,
    /// The private globals standing for plain uniforms (`GlUniforms::Plain`),
    /// with their source names: the GLSL writer declares them as globals,
    /// and `emit` makes each declaration `uniform T name;`.
    pub uniforms: Vec<(naga::Handle<naga::GlobalVariable>, String)>,
}

/// The result of lowering: the validated modules and the interface that
/// names their parts.
#[derive(Debug)]
pub struct Lowered {
    /// Per entry point, in the order of `interface.entry_points`.
    pub gl: Vec<GlEntry>,
    pub gpu: naga::Module,
    pub gpu_info: naga::valid::ModuleInfo,
    /// The GPU module for the SPIR-V writer where it differs from `gpu`:
    /// a program with specialization constants holds each in a `Private`
    /// variable of its default that nothing writes, which `emit::spirv`
    /// makes an `OpSpecConstant` (naga 30's SPIR-V writer has no
    /// overrides). `None` without specialization constants, or when
    /// SPIR-V is not a target.
    pub spirv: Option<(naga::Module, naga::valid::ModuleInfo)>,
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

