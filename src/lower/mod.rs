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

#[cfg(debug_assertions)]
mod fault;
mod func;
mod inverse;
mod module;

use crate::diag::Diagnostic;
use crate::sema::{self, BuiltinVar, GlobalKind, Scalar, Ty};
use crate::source::Span;
use func::{FnBuilder, FnKind};
use module::{GlobalSlot, ModuleBuilder};

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

/// Lowers a checked program into the validated modules.
pub fn lower(program: &crate::sema::Program, conventions: Conventions) -> Result<Lowered, crate::diag::Diagnostic> {
    // Call-graph reach, once for all the modules.
    let reach = Reach::of(program);
    let (gpu, gpu_info, interface) = gpu(program, conventions, &reach)?;
    // One validator for all the GL modules: its tables are reused.
    let mut validator = module::validator(Flavor::Gl);
    let gl = (0..program.entry_points.len()).map(|i| gl_entry(program, i, &reach, &mut validator)).collect::<Result<_, _>>()?;
    Ok(Lowered { gl, gpu, gpu_info, interface })
}

/// The validated GPU module of the whole program, and its interface.
pub fn lower_gpu(program: &crate::sema::Program, conventions: Conventions) -> Result<(naga::Module, naga::valid::ModuleInfo, Interface), Diagnostic> {
    gpu(program, conventions, &Reach::of(program))
}

fn gpu(program: &crate::sema::Program, conventions: Conventions, reach: &Reach) -> Result<(naga::Module, naga::valid::ModuleInfo, Interface), Diagnostic> {
    let (gpu, mut interface) = build(program, Flavor::Gpu(conventions), None, reach)?;
    #[cfg(debug_assertions)]
    let gpu = fault::inject(gpu);
    let flavor = Flavor::Gpu(conventions);
    let gpu_info = module::validate(&mut module::validator(flavor), &gpu, flavor)?;
    interface.conventions = conventions;
    Ok((gpu, gpu_info, interface))
}

/// The validated GL module of entry point `index` alone.
pub fn lower_gl_entry(program: &crate::sema::Program, index: usize) -> Result<GlEntry, Diagnostic> {
    gl_entry(program, index, &Reach::of(program), &mut module::validator(Flavor::Gl))
}

/// [`lower_gl_entry`] with a validator from `module::validator(Flavor::Gl)`.
fn gl_entry(program: &crate::sema::Program, index: usize, reach: &Reach, validator: &mut naga::valid::Validator) -> Result<GlEntry, Diagnostic> {
    let (module, _) = build(program, Flavor::Gl, Some(index), reach)?;
    let info = module::validate(validator, &module, Flavor::Gl)?;
    Ok(GlEntry { module, info })
}

/// Validates a module the way [`lower`] validates its own output: a failure
/// is an internal compiler error at the span naga reports.
pub fn validate(module: &naga::Module, flavor: Flavor) -> Result<naga::valid::ModuleInfo, Diagnostic> {
    module::validate(&mut module::validator(flavor), module, flavor)
}

/// Builds the whole program, or (`only`) one entry point and what it
/// reaches.
fn build(p: &sema::Program, flavor: Flavor, only: Option<usize>, reach: &Reach) -> Result<(naga::Module, Interface), Diagnostic> {
    let mut m = ModuleBuilder::new(p, flavor);
    m.allow_nonuniform_derivatives();
    let io = EntryIo::of(p, only, reach);
    let only_ep = only.map(|i| &p.entry_points[i]);
    match only_ep {
        // Constants are declared where first used: only those it reads.
        Some(ep) => m.declare_globals(Some(&ep.func.uses), &io.private),
        None => {
            m.declare_consts();
            m.declare_globals(None, &io.private);
        }
    }
    // Implicit-LOD sampling means level 0 in a vertex entry point; a helper
    // that samples and is reached from both stages is lowered twice (a
    // one-entry module needs only the copy for its stage).
    let (from_vertex, from_fragment) = (&reach.vertex, &reach.fragment);
    let reached = only.map(|i| &reach.by_entry[i]);
    let vertex_entry = only_ep.map(|ep| ep.stage == naga::ShaderStage::Vertex);
    for (fid, f) in p.functions.iter().enumerate() {
        // A helper with sampler parameters is lowered per sampler at its
        // calls (`specialised_helper`).
        if reached.as_ref().is_some_and(|r| !r[fid]) || f.takes_samplers() {
            m.functions.push(None);
            m.vertex_functions.push(None);
            continue;
        }
        let two_copies = f.implicit_lod && from_vertex[fid] && from_fragment[fid];
        let vertex_only = f.implicit_lod && from_vertex[fid] && !from_fragment[fid];
        let h = (!(two_copies && vertex_entry == Some(true))).then(|| lower_helper(&mut m, f, &f.name, vertex_only, &[]));
        m.functions.push(h);
        let copy = (two_copies && vertex_entry != Some(false)).then(|| lower_helper(&mut m, f, &[&f.name, "_vertex"].concat(), true, &[]));
        m.vertex_functions.push(copy);
    }
    let mut entries = Vec::new();
    for (index, ep) in p.entry_points.iter().enumerate() {
        if only.is_none_or(|i| i == index) {
            entries.push(lower_entry(&mut m, ep, index, &io.own[index])?);
        }
    }
    let interface = Interface { conventions: Conventions::default(), resources: std::mem::take(&mut m.resources), entry_points: entries };
    Ok((m.module, interface))
}

/// Lowers one helper function; `vertex_lod`: implicit-LOD sampling at
/// level 0; `samplers`: what its sampler parameters stand for, in order.
fn lower_helper<'p>(m: &mut ModuleBuilder<'p>, f: &'p sema::Function, name: &str, vertex_lod: bool, samplers: &[func::SamplerRef]) -> naga::Handle<naga::Function> {
    let mut b = FnBuilder::new(m, name, &f.locals, FnKind::Helper);
    b.vertex_lod = vertex_lod;
    let mut samplers = samplers.iter();
    for (i, l) in f.locals[..f.params].iter().enumerate() {
        let sampler = matches!(l.ty, Ty::Sampler(_)).then(|| *samplers.next().expect("one sampler per sampler parameter"));
        b.add_param(i, sampler);
    }
    let mut body = b.block(&f.body);
    let ret = (f.ret != Ty::Void).then(|| naga::FunctionResult { ty: b.m.ty(&f.ret), binding: None });
    if ret.is_none() {
        naga::proc::ensure_block_returns(&mut body);
    }
    let func = b.finish(body, ret);
    m.module.functions.append(func, f.span.into())
}

/// Helper `fid` specialised for `samplers` (its sampler parameters, in
/// order), lowered on first request: one naga function per distinct set
/// of samplers (and per stage, for implicit LOD), named after them
/// (`blur_albedo`), since naga's backends have no sampler parameters that
/// all of GLSL, WGSL and SPIR-V share.
fn specialised_helper(m: &mut ModuleBuilder<'_>, fid: usize, vertex_lod: bool, samplers: Vec<func::SamplerRef>) -> naga::Handle<naga::Function> {
    let p = m.p;
    let f = &p.functions[fid];
    // Level 0 matters only where the helper samples with implicit LOD.
    let vertex_lod = vertex_lod && f.implicit_lod;
    if let Some(s) = m.specialised.iter().find(|s| s.function == fid && s.vertex_lod == vertex_lod && s.samplers == samplers) {
        return s.handle;
    }
    let mut name = f.name.clone();
    for r in &samplers {
        name.push('_');
        name.push_str(&p.globals[r.global].name);
        if matches!(p.globals[r.global].ty, Ty::Array(..)) {
            name.push_str(&format!("_{}", r.elem));
        }
    }
    if vertex_lod {
        name.push_str("_vertex");
    }
    let handle = lower_helper(m, f, &name, vertex_lod, &samplers);
    m.specialised.push(module::Specialised { function: fid, vertex_lod, samplers, handle });
    handle
}

/// Which helper functions each entry point reaches, and which a vertex or
/// a fragment entry point reaches.
struct Reach {
    by_entry: Vec<Vec<bool>>,
    vertex: Vec<bool>,
    fragment: Vec<bool>,
}

impl Reach {
    fn of(p: &sema::Program) -> Reach {
        let n = p.functions.len();
        let (mut vertex, mut fragment) = (vec![false; n], vec![false; n]);
        let by_entry: Vec<Vec<bool>> = p.entry_points.iter().map(|ep| reach(p, ep)).collect();
        for (ep, seen) in p.entry_points.iter().zip(&by_entry) {
            let stage = if ep.stage == naga::ShaderStage::Vertex { &mut vertex } else { &mut fragment };
            for (s, r) in stage.iter_mut().zip(seen) {
                *s |= r;
            }
        }
        Reach { by_entry, vertex, fragment }
    }
}

/// Where each entry point keeps its inputs and outputs. One that no helper
/// touches (and, for an input, that the entry point never assigns) lives in
/// the entry function itself: an input is read from its argument, an
/// output is a local variable returned at the end. Only the others get a
/// private global (GLSL's model), which every backend writes as a
/// module-level variable with copies in at the start and out at the end.
struct EntryIo {
    /// Per entry point of the program (empty for those the module leaves
    /// out), per global: held by the entry function.
    own: Vec<Vec<bool>>,
    /// Per global: declared as a private global.
    private: Vec<bool>,
}

impl EntryIo {
    fn of(p: &sema::Program, only: Option<usize>, reach: &Reach) -> EntryIo {
        let n = p.globals.len();
        let interface = |gid: usize| matches!(p.globals[gid].kind, GlobalKind::Io { .. } | GlobalKind::Builtin(_));
        let mut private = vec![false; n];
        // What the module's helpers touch: every helper for the whole
        // program, those the entry point reaches for one.
        for (fid, f) in p.functions.iter().enumerate() {
            if only.is_none_or(|i| reach.by_entry[i][fid]) {
                for &gid in f.uses.keys() {
                    private[gid] |= interface(gid);
                }
            }
        }
        let mut own = Vec::with_capacity(p.entry_points.len());
        let (mut touched, mut written) = (vec![false; n], vec![false; n]);
        for (index, ep) in p.entry_points.iter().enumerate() {
            if only.is_some_and(|i| i != index) {
                own.push(Vec::new());
                continue;
            }
            touched.fill(false);
            written.fill(false);
            for (f, _) in p.functions.iter().zip(&reach.by_entry[index]).filter(|(_, r)| **r) {
                for &gid in f.uses.keys() {
                    touched[gid] = true;
                }
            }
            assigned_globals(&ep.func.body, &mut written);
            let mut mine = vec![false; n];
            for &gid in ep.func.uses.keys() {
                let g = &p.globals[gid];
                let input = func::is_stage_input(&g.kind, ep.stage) && !written[gid];
                let output = func::is_stage_output(&g.kind, ep.stage);
                // Interface types are scalars and vectors; anything else
                // keeps the private global, where every access works.
                let plain = matches!(g.ty, Ty::Scalar(_) | Ty::Vector(..));
                mine[gid] = plain && !touched[gid] && (input || output);
                private[gid] |= interface(gid) && !mine[gid];
            }
            own.push(mine);
        }
        EntryIo { own, private }
    }
}

/// Marks the globals that `stmts` assign to (all or part of).
fn assigned_globals(stmts: &[sema::Stmt], out: &mut [bool]) {
    fn root(e: &sema::Expr) -> Option<sema::GlobalId> {
        match &e.kind {
            sema::ExprKind::Global(g) => Some(*g),
            sema::ExprKind::Field(b, _) | sema::ExprKind::Index(b, _) | sema::ExprKind::Swizzle(b, _) => root(b),
            _ => None,
        }
    }
    for s in stmts {
        match s {
            sema::Stmt::Assign { target, .. } => {
                if let Some(g) = root(target) {
                    out[g] = true;
                }
            }
            sema::Stmt::If { then, otherwise, .. } => {
                assigned_globals(then, out);
                assigned_globals(otherwise, out);
            }
            sema::Stmt::While { body, .. } | sema::Stmt::For { body, .. } => assigned_globals(body, out),
            _ => {}
        }
    }
}

/// Which helper functions entry point `ep` reaches.
fn reach(p: &sema::Program, ep: &sema::EntryPoint) -> Vec<bool> {
    let mut seen = vec![false; p.functions.len()];
    let mut stack: Vec<usize> = ep.func.callees.iter().copied().collect();
    while let Some(f) = stack.pop() {
        if f < seen.len() && !seen[f] {
            seen[f] = true;
            stack.extend(p.functions[f].callees.iter().copied());
        }
    }
    seen
}

fn interpolation(ty: &Ty) -> (Option<naga::Interpolation>, Option<naga::Sampling>) {
    match ty.scalar() {
        Some(Scalar::Float) => (Some(naga::Interpolation::Perspective), Some(naga::Sampling::Center)),
        _ => (Some(naga::Interpolation::Flat), None),
    }
}

fn location(location: u32, interp: (Option<naga::Interpolation>, Option<naga::Sampling>)) -> naga::Binding {
    naga::Binding::Location { location, interpolation: interp.0, sampling: interp.1, blend_src: None, per_primitive: false }
}

/// Lowers entry point `ep`; `own`: the inputs and outputs it holds itself
/// (see [`EntryIo`]).
fn lower_entry<'p>(m: &mut ModuleBuilder<'p>, ep: &'p sema::EntryPoint, index: usize, own: &[bool]) -> Result<EntryInterface, Diagnostic> {
    use naga::ShaderStage::{Fragment, Vertex};
    let p = m.p;
    let stage = ep.stage;
    let mut iface = EntryInterface { name: ep.name.clone(), stage, index, inputs: Vec::new(), outputs: Vec::new(), builtins: Vec::new(), resources: Vec::new() };
    // Only the GPU module's interface is kept (`lower_gl_entry` drops its
    // own): a GL module leaves the lists empty.
    let describe = m.flavor != Flavor::Gl;
    // Arguments: inputs this entry point reaches, by location then builtins.
    let mut args: Vec<(sema::GlobalId, naga::Binding, naga::Handle<naga::Type>, bool)> = Vec::new();
    let mut outs: Vec<(Option<sema::GlobalId>, Option<BuiltinVar>, naga::Handle<naga::Type>, naga::Binding, String)> = Vec::new();
    if stage == Vertex {
        let pos_global = p.globals.iter().position(|g| matches!(g.kind, GlobalKind::Builtin(BuiltinVar::Position))).filter(|g| ep.func.uses.contains_key(g));
        let ty = m.ty(&BuiltinVar::Position.ty());
        outs.push((pos_global, Some(BuiltinVar::Position), ty, naga::Binding::BuiltIn(naga::BuiltIn::Position { invariant: false }), "gl_Position".into()));
    }
    // Outputs held in local variables, declared once the function exists.
    let mut own_outputs: Vec<sema::GlobalId> = Vec::new();
    // Output locations so far (few: a list).
    let mut seen_out: Vec<(u32, Span)> = Vec::new();
    let mut point_coord_default: Vec<(sema::GlobalId, Span)> = Vec::new();
    for (&gid, &use_span) in &ep.func.uses {
        let g = &p.globals[gid];
        if matches!(g.kind, GlobalKind::Uniform | GlobalKind::Sampler { .. }) {
            iface.resources.extend(m.resource_of[gid].clone());
            continue;
        }
        if !own[gid] && !matches!(m.globals[gid], GlobalSlot::Var(_)) {
            continue;
        }
        match g.kind {
            GlobalKind::Builtin(b) if describe => iface.builtins.push(b.name().to_string()),
            _ => {}
        }
        let ty = m.ty(&g.ty);
        if func::is_stage_input(&g.kind, stage) {
            let (binding, arg_ty, to_int) = match g.kind {
                GlobalKind::Io { location: l, .. } => {
                    let interp = if stage == Fragment { interpolation(&g.ty) } else { (None, None) };
                    if describe {
                        let dsl_type = m.show_ty(&g.ty);
                        iface.inputs.push(IoVar { name: g.name.clone(), location: l, ty, dsl_type, interpolation: interp.0 });
                    }
                    (location(l, interp), ty, false)
                }
                GlobalKind::Builtin(b) => {
                    let u32_ty = m.ty(&Ty::Scalar(Scalar::Uint));
                    match b {
                        BuiltinVar::FragCoord => (naga::Binding::BuiltIn(naga::BuiltIn::Position { invariant: false }), ty, false),
                        BuiltinVar::FrontFacing => (naga::Binding::BuiltIn(naga::BuiltIn::FrontFacing), ty, false),
                        // WebGPU has no point sprites (points are one pixel):
                        // the centre of the point on WGSL/SPIR-V.
                        BuiltinVar::PointCoord if m.flavor != Flavor::Gl => {
                            point_coord_default.push((gid, g.span));
                            continue;
                        }
                        BuiltinVar::PointCoord => (naga::Binding::BuiltIn(naga::BuiltIn::PointCoord), ty, false),
                        BuiltinVar::VertexId => (naga::Binding::BuiltIn(naga::BuiltIn::VertexIndex), u32_ty, true),
                        BuiltinVar::InstanceId => (naga::Binding::BuiltIn(naga::BuiltIn::InstanceIndex), u32_ty, true),
                        _ => continue,
                    }
                }
                _ => continue,
            };
            args.push((gid, binding, arg_ty, to_int));
        } else if func::is_stage_output(&g.kind, stage) {
            if own[gid] {
                own_outputs.push(gid);
            }
            match g.kind {
                GlobalKind::Io { location: l, .. } => {
                    if let Some(&(_, prev)) = seen_out.iter().find(|o| o.0 == l) {
                        // sema reports this as a user error first.
                        return Err(Diagnostic::bug(format!("entry point `{}` writes two outputs at location {l}", ep.name), Some(use_span))
                            .with_secondary(prev, "this output also uses it")
                            .with_note("`@out` and `@inout` variables written by one vertex entry point share the output locations"));
                    }
                    seen_out.push((l, g.span));
                    let interp = if stage == Vertex { interpolation(&g.ty) } else { (None, None) };
                    if describe {
                        let dsl_type = m.show_ty(&g.ty);
                        iface.outputs.push(IoVar { name: g.name.clone(), location: l, ty, dsl_type, interpolation: interp.0 });
                    }
                    outs.push((Some(gid), None, ty, location(l, interp), g.name.clone()));
                }
                GlobalKind::Builtin(b) => {
                    let bi = match b {
                        // WGSL has no point size; SPIR-V is written with
                        // naga's FORCE_POINT_SIZE (1.0) instead, so both
                        // draw one-pixel points (docs/targets.md).
                        BuiltinVar::PointSize if m.flavor != Flavor::Gl => continue,
                        BuiltinVar::PointSize => naga::BuiltIn::PointSize,
                        BuiltinVar::FragDepth => naga::BuiltIn::FragDepth,
                        _ => continue,
                    };
                    outs.push((Some(gid), Some(b), ty, naga::Binding::BuiltIn(bi), b.name().to_string()));
                }
                _ => {}
            }
        }
    }
    iface.inputs.sort_by_key(|v| v.location);
    iface.outputs.sort_by_key(|v| v.location);
    let members = outs.iter().map(|o| (o.0, o.1, o.2)).collect();
    let result_ty = (!outs.is_empty()).then(|| m.struct_type([&ep.name, "_out"].concat(), outs.into_iter().map(|o| (o.4, o.2, Some(o.3))).collect()));
    let kind = FnKind::Entry(func::EntryOutputs { result_ty, members, stage });
    let mut b = FnBuilder::new(m, &ep.name, &ep.func.locals, kind);
    b.vertex_lod = stage == Vertex;
    // The prologue's stores, then the statements.
    let mut body = func::block_for(args.len() + ep.func.body.len() + 1);
    let private = |m: &ModuleBuilder, gid: sema::GlobalId| match m.globals[gid] {
        GlobalSlot::Var(h) if !own[gid] => Some(h),
        _ => None,
    };
    for gid in own_outputs {
        let g = &p.globals[gid];
        let ty = b.m.ty(&g.ty);
        b.output_local(gid, &g.name, ty, g.span);
    }
    for (gid, s) in point_coord_default {
        let h = private(b.m, gid);
        b.point_coord_default(&mut body, gid, h, s);
    }
    for (i, &(gid, ref binding, ty, to_int)) in args.iter().enumerate() {
        let g = &p.globals[gid];
        let h = private(b.m, gid);
        // An input held as its argument takes the variable's name; one
        // copied into a private global leaves the name to the global.
        let name = match h {
            Some(_) => ["in_", g.name.trim_start_matches("gl_")].concat(),
            None => g.name.trim_start_matches("gl_").to_owned(),
        };
        b.func.arguments.push(naga::FunctionArgument { name: Some(name), ty, binding: Some(binding.clone()) });
        b.input_argument(&mut body, gid, h, i as u32, to_int, g.span);
    }
    b.stmts_into(&ep.func.body.as_slice(), &mut body);
    if !matches!(body.last(), Some(naga::Statement::Return { .. })) {
        let end = Span::new(ep.func.span.end.saturating_sub(1), ep.func.span.end);
        b.entry_return(&mut body, end);
    }
    let result = result_ty.map(|ty| naga::FunctionResult { ty, binding: None });
    let function = b.finish(body, result);
    m.module.entry_points.push(naga::EntryPoint {
        name: ep.name.clone(),
        stage,
        early_depth_test: None,
        workgroup_size: [0; 3],
        workgroup_size_overrides: None,
        function,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
    Ok(iface)
}
