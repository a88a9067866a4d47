//! Lowering: the checked program (`sema::Program`) to naga IR.
//!
//! Two flavours of module are built from one program, because the targets
//! disagree on conventions that are baked into the IR:
//! - `gpu`: one module for WGSL and SPIR-V, holding the whole program. Every
//!   resource has a group/binding, and (in the default portable conventions)
//!   every vertex entry point ends with the clip-space adaptation
//!   `z' = (z + w) / 2`, `y' = -y`.
//! - `gl`: one module per entry point, for the GLSL backends (which write
//!   one file per entry point). GL conventions as written; resource globals
//!   carry no binding, so naga's namer gives them their source names
//!   (`uniform highp sampler2DShadow shadow_map;`). Each holds only what its
//!   entry point reaches (functions, globals, constants, structs), so the
//!   file declares nothing else; building it that way costs less than
//!   building the whole program and reducing a copy per entry point.
//!
//! The entry points of `gpu` are in program order, and `gl[i]` is the one
//! for `gpu.entry_points[i]`. Handles differ between the modules; globals
//! keep their (unique) names in both.

//!
//! The modules of this stage, in the order data flows through them:
//! - [`interface`]: what lowering hands `emit` (the contract): the modules,
//!   the resources with their bindings, each entry point's inputs/outputs;
//! - `reach`: pure analyses of the checked program (which helpers each
//!   entry point reaches, where each entry point keeps its inputs/outputs);
//! - `module` (with `types`, `globals`, `uniforms`): module-level IR:
//!   types, constants, resource and private globals, the uniform buffers
//!   of loose uniforms; `validate`: naga's validator;
//! - `helpers`: helper functions, with their per-stage and per-sampler
//!   copies; `entry`: entry points (arguments, outputs, prologue/epilogue,
//!   the clip-space adaptation);
//! - `function` (the builder), `stmts`, `exprs`, `builtins`, `textures`,
//!   `inverse`, `pack`: function bodies.

mod builtins;
mod compute;
mod entry;
mod exprs;
#[cfg(debug_assertions)]
mod fault;
mod function;
mod globals;
mod helpers;
mod mesh;
pub mod interface;
mod inverse;
mod module;
mod pack;
mod reach;
mod stmts;
mod textures;
mod types;
mod uniforms;
mod validate;

/// Validates a module the way [`lower`] validates its own output.
pub use validate::validate;
pub use interface::{Conventions, EntryInterface, Flavor, GlEntry, GlUniforms, Interface, IoVar, LooseUniform, LowerOptions, Lowered, Resource, ResourceKind};

use crate::diag::Diagnostic;
use crate::sema;
use module::ModuleBuilder;
use reach::{EntryIo, Reach};

/// Lowers a checked program into the validated modules.
pub fn lower(program: &sema::Program, options: impl Into<LowerOptions>) -> Result<Lowered, Diagnostic> {
    let options = options.into();
    // Call-graph reach, once for all the modules.
    let reach = Reach::of(program);
    let (gpu, gpu_info, mut interface) = gpu(program, options.conventions, &reach, false)?;
    // Lowered again only for a program with specialization constants.
    let spirv = match options.spirv && !gpu.overrides.is_empty() {
        true => self::gpu(program, options.conventions, &reach, true).map(|(m, i, _)| Some((m, i)))?,
        false => None,
    };
    interface.gl_uniforms = options.gl_uniforms;
    interface.gl_block_points = uniforms::gl_block_points(program, &interface.resources, options.gl_uniforms);
    let gl = (0..program.entry_points.len()).map(|i| gl_entry(program, i, options.conventions, options.gl_uniforms, &reach)).collect::<Result<_, _>>()?;
    Ok(Lowered { gl, gpu, gpu_info, spirv, interface })
}

/// The validated GPU module of the whole program, and its interface.
pub fn lower_gpu(program: &sema::Program, conventions: Conventions) -> Result<(naga::Module, naga::valid::ModuleInfo, Interface), Diagnostic> {
    gpu(program, conventions, &Reach::of(program), false)
}

/// The GPU module; `spec_private`: specialization constants as `Private`
/// variables of their defaults (for SPIR-V) instead of overrides.
fn gpu(program: &sema::Program, conventions: Conventions, reach: &Reach, spec_private: bool) -> Result<(naga::Module, naga::valid::ModuleInfo, Interface), Diagnostic> {
    let (mut gpu, mut interface, _) = build(program, Flavor::Gpu(conventions), conventions, GlUniforms::default(), None, reach, spec_private)?;
    declare_f16_if_used(&mut gpu);
    #[cfg(debug_assertions)]
    let gpu = fault::inject(gpu);
    let flavor = Flavor::Gpu(conventions);
    let gpu_info = validate::validate(&gpu, flavor)?;
    interface.conventions = conventions;
    Ok((gpu, gpu_info, interface))
}

/// Declares the `f16` type where `half` is used only inside expressions (a
/// conversion, a literal): naga's writers announce `f16` (WGSL's
/// `enable f16`, SPIR-V's 16-bit storage extension) from the module's
/// types, and without it tint, naga and spirv-val refuse the output.
fn declare_f16_if_used(module: &mut naga::Module) {
    use naga::{Expression as E, Scalar, TypeInner};
    if module.types.iter().any(|(_, t)| t.inner.scalar() == Some(Scalar::F16)) {
        return;
    }
    let half = |e: &E| matches!(e, E::As { kind: naga::ScalarKind::Float, convert: Some(2), .. } | E::Literal(naga::Literal::F16(_)));
    let functions = module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
    let used = module.global_expressions.iter().any(|(_, e)| half(e)) || functions.into_iter().any(|f| f.expressions.iter().any(|(_, e)| half(e)));
    if used {
        module.types.insert(naga::Type { name: None, inner: TypeInner::Scalar(Scalar::F16) }, naga::Span::UNDEFINED);
    }
}

/// The validated GL module of entry point `index` alone (`conventions`:
/// whether a Vulkan-dialect vertex entry point's depth is adapted).
pub fn lower_gl_entry(program: &sema::Program, index: usize, conventions: Conventions, gl_uniforms: GlUniforms) -> Result<GlEntry, Diagnostic> {
    gl_entry(program, index, conventions, gl_uniforms, &Reach::of(program))
}

/// [`lower_gl_entry`] with the program's reach already computed.
fn gl_entry(program: &sema::Program, index: usize, conventions: Conventions, gl_uniforms: GlUniforms, reach: &Reach) -> Result<GlEntry, Diagnostic> {
    // GLSL has no mesh or task stage (sema refuses the GLSL targets for
    // them): an empty module stands in, and `emit` writes no GLSL of it.
    if matches!(program.entry_points[index].stage, naga::ShaderStage::Mesh | naga::ShaderStage::Task) {
        let module = naga::Module::default();
        let info = validate::validate(&module, Flavor::Gl)?;
        return Ok(GlEntry { module, info, uniforms: Vec::new() });
    }
    let (module, _, uniforms) = build(program, Flavor::Gl, conventions, gl_uniforms, Some(index), reach, false)?;
    let info = validate::validate(&module, Flavor::Gl)?;
    Ok(GlEntry { module, info, uniforms })
}

/// Builds the whole program, or (`only`) one entry point and what it
/// reaches: globals, then helper functions (callees before callers, as
/// sema ordered them), then entry points.
#[allow(clippy::type_complexity)]
fn build(
    p: &sema::Program,
    flavor: Flavor,
    conventions: Conventions,
    gl_uniforms: GlUniforms,
    only: Option<usize>,
    reach: &Reach,
    spec_private: bool,
) -> Result<(naga::Module, Interface, Vec<(naga::Handle<naga::GlobalVariable>, String)>), Diagnostic> {
    let mut m = ModuleBuilder::new(p, flavor, conventions, gl_uniforms);
    m.spec_private = spec_private;
    m.allow_nonuniform_derivatives();
    let io = EntryIo::of(p, only, reach);
    let only_ep = only.map(|i| &p.entry_points[i]);
    match only_ep {
        // Constants are declared where first used: only those it reads.
        Some(ep) => m.declare_globals(Some(&ep.func.uses), &io.private),
        None => {
            m.declare_consts();
            // Only what some entry point reaches: a program may declare far
            // more than the modules can hold (SPIR-V validators refuse more
            // than 65 535 module-scope variables).
            let used: std::collections::BTreeMap<sema::GlobalId, crate::source::Span> =
                p.entry_points.iter().flat_map(|ep| ep.func.uses.iter().map(|(&g, &s)| (g, s))).collect();
            m.declare_globals(Some(&used), &io.private);
        }
    }
    helpers::lower_helpers(&mut m, only, reach);
    let mut entries = Vec::new();
    for (index, ep) in p.entry_points.iter().enumerate() {
        if only.is_none_or(|i| i == index) {
            entries.push(entry::lower_entry(&mut m, ep, index, &io.own[index])?);
        }
    }
    let links = match only {
        None => p.links.iter().map(|l| (l.vertex, l.fragment)).collect(),
        Some(_) => Vec::new(),
    };
    let interface = Interface {
        conventions: Conventions::default(),
        push_constants: p.push_constants.iter().map(|&g| p.globals[g].name.clone()).collect(),
        gl_uniforms,
        resources: std::mem::take(&mut m.resources),
        loose: std::mem::take(&mut m.loose),
        entry_points: entries,
        links,
        gl_block_points: Vec::new(),
    };
    Ok((m.module, interface, m.plain_uniforms))
}
