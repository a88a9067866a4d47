//! Entry points: inputs arrive as arguments (or are copied into private
//! globals where a helper touches them), outputs are local variables (or
//! private globals) returned as one struct; the prologue and epilogue
//! that move them, and the clip-space adaptation of vertex outputs on the
//! WGSL/SPIR-V targets.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::{block_for, span, EntryOutputs, FnBuilder, FnKind, LocalSlot};
use super::interface::{Conventions, EntryInterface, Flavor, IoVar};
use super::module::{GlobalSlot, ModuleBuilder};
use super::reach::{is_stage_input, is_stage_output};
use crate::diag::Diagnostic;
use crate::sema::{self, BuiltinVar, GlobalKind, Scalar, Ty};
use crate::source::Span;
use crate::syntax::ast::Dialect;

impl FnBuilder<'_, '_> {
    /// Entry prologue: input `gid` arrives as argument `index` (builtin
    /// `u32` indices converted to the DSL's `int`); see [`Self::hold_input`].
    pub(super) fn input_argument(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, index: u32, to_int: bool, s: Span) {
        let mut v = self.append_plain(E::FunctionArgument(index), s);
        if to_int {
            v = self.convert(v, &Ty::Scalar(Scalar::Uint), Scalar::Int, s);
        }
        self.hold_input(block, gid, global, v, s);
    }

    /// Entry prologue: `gl_PointCoord` on targets without point sprites,
    /// float2(0.5), the centre of a one-pixel point; into its private copy
    /// (`Some`) or held as the entry point's own value.
    pub(super) fn point_coord_default(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, s: Span) {
        let half = self.literal(naga::Literal::F32(0.5), s);
        let v = self.append(E::Splat { size: naga::VectorSize::Bi, value: half }, s);
        self.hold_input(block, gid, global, v, s);
    }

    /// Entry prologue: input `gid` has value `v`, stored into its private
    /// copy (`Some`) or held as the entry point's own value. The emit range
    /// is closed here, in the function's top block, so the value dominates
    /// every use.
    pub(super) fn hold_input(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, v: Handle<E>, s: Span) {
        match global {
            Some(g) => {
                let ptr = self.append_plain(E::GlobalVariable(g), s);
                self.push(block, Statement::Store { pointer: ptr, value: v }, s);
            }
            None => {
                self.flush(block);
                self.entry_global(gid, LocalSlot::Value(v));
            }
        }
    }

    /// Entry prologue: output `gid` lives in a new local variable.
    pub(super) fn output_local(&mut self, gid: sema::GlobalId, name: &str, ty: Handle<naga::Type>, s: Span) {
        let var = self.func.local_variables.append(naga::LocalVariable { name: Some(name.to_owned()), ty, init: None }, span(s));
        self.entry_global(gid, LocalSlot::Var(var));
    }

    pub(super) fn entry_global(&mut self, gid: sema::GlobalId, slot: LocalSlot) {
        if self.entry_globals.is_empty() {
            self.entry_globals = vec![LocalSlot::Unset; self.m.p.globals.len()];
        }
        self.entry_globals[gid] = slot;
    }

    /// The epilogue of an entry point: build and return its outputs.
    pub(super) fn entry_return(&mut self, block: &mut Block, s: Span) {
        let FnKind::Entry(outs) = &self.kind else {
            self.push(block, Statement::Return { value: None }, s);
            return;
        };
        match outs.stage {
            naga::ShaderStage::Task => return self.task_return_none(block, s),
            naga::ShaderStage::Mesh => self.mesh_epilogue(block, s),
            _ => {}
        }
        let FnKind::Entry(outs) = &self.kind else { unreachable!("an entry point") };
        let Some(result_ty) = outs.result_ty else {
            self.push(block, Statement::Return { value: None }, s);
            return;
        };
        let members: Vec<_> = outs.members.clone();
        let adapt = match (outs.stage, outs.dialect, self.m.flavor) {
            (naga::ShaderStage::Vertex, _, _) if self.m.conventions == Conventions::Native => None,
            (naga::ShaderStage::Vertex, Dialect::Gl, Flavor::Gpu(_)) => Some(ClipAdapt::GlToGpu),
            (naga::ShaderStage::Vertex, Dialect::Vulkan, Flavor::Gpu(_)) => Some(ClipAdapt::VulkanToGpu),
            (naga::ShaderStage::Vertex, Dialect::Vulkan, Flavor::Gl) => Some(ClipAdapt::VulkanToGl),
            _ => None,
        };
        let mut comps = Vec::with_capacity(members.len());
        for (g, builtin, ty) in members {
            let mut v = match g {
                Some(g) => {
                    let ptr = self.global_pointer(g, s).expect("an entry point's outputs are variables");
                    self.append(E::Load { pointer: ptr }, s)
                }
                None => self.append_plain(E::ZeroValue(ty), s),
            };
            if let (Some(how), Some(BuiltinVar::Position)) = (adapt, builtin) {
                v = self.adapt_clip_space(v, how, s);
            }
            comps.push(v);
        }
        let value = self.append(E::Compose { ty: result_ty, components: comps }, s);
        self.push(block, Statement::Return { value: Some(value) }, s);
    }

    /// The clip-space adaptation `how` (docs/targets.md): GL clip space to
    /// WebGPU: z' = (z + w) / 2, y' = -y; Vulkan clip space to WebGPU
    /// (wgpu drives Vulkan with a flipped viewport): y' = -y; Vulkan clip
    /// space to GL: z' = 2z - w (row 0 is NDC y = -1 in both).
    pub(super) fn adapt_clip_space(&mut self, p: Handle<E>, how: ClipAdapt, s: Span) -> Handle<E> {
        let x = self.append(E::AccessIndex { base: p, index: 0 }, s);
        let mut y = self.append(E::AccessIndex { base: p, index: 1 }, s);
        let mut z = self.append(E::AccessIndex { base: p, index: 2 }, s);
        let w = self.append(E::AccessIndex { base: p, index: 3 }, s);
        if how != ClipAdapt::VulkanToGl {
            y = self.append(E::Unary { op: naga::UnaryOperator::Negate, expr: y }, s);
        }
        match how {
            ClipAdapt::GlToGpu => {
                let zw = self.append(E::Binary { op: naga::BinaryOperator::Add, left: z, right: w }, s);
                let half = self.append_plain(E::Literal(naga::Literal::F32(0.5)), s);
                z = self.append(E::Binary { op: naga::BinaryOperator::Multiply, left: zw, right: half }, s);
            }
            ClipAdapt::VulkanToGl => {
                let two = self.append_plain(E::Literal(naga::Literal::F32(2.0)), s);
                let z2 = self.append(E::Binary { op: naga::BinaryOperator::Multiply, left: z, right: two }, s);
                z = self.append(E::Binary { op: naga::BinaryOperator::Subtract, left: z2, right: w }, s);
            }
            ClipAdapt::VulkanToGpu => {}
        }
        let ty = self.m.ty(&Ty::Vector(Scalar::Float, 4));
        self.append(E::Compose { ty, components: vec![x, y, z, w] }, s)
    }
}

/// Which clip-space adaptation a vertex entry point's position gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ClipAdapt {
    GlToGpu,
    VulkanToGpu,
    VulkanToGl,
}

fn interpolation(ty: &Ty, flat: bool) -> (Option<naga::Interpolation>, Option<naga::Sampling>) {
    match ty.scalar() {
        Some(Scalar::Float) if !flat => (Some(naga::Interpolation::Perspective), Some(naga::Sampling::Center)),
        _ => (Some(naga::Interpolation::Flat), None),
    }
}

fn location(location: u32, interp: (Option<naga::Interpolation>, Option<naga::Sampling>)) -> naga::Binding {
    naga::Binding::Location { location, interpolation: interp.0, sampling: interp.1, blend_src: None, per_primitive: false }
}

/// Lowers entry point `ep`; `own`: the inputs and outputs it holds itself
/// (see `reach::EntryIo`).
pub(super) fn lower_entry<'p>(m: &mut ModuleBuilder<'p>, ep: &'p sema::EntryPoint, index: usize, own: &[bool]) -> Result<EntryInterface, Diagnostic> {
    use naga::ShaderStage::{Fragment, Vertex};
    let p = m.p;
    let stage = ep.stage;
    let mut iface = EntryInterface { name: ep.name.clone(), stage, index, inputs: Vec::new(), outputs: Vec::new(), builtins: Vec::new(), resources: Vec::new(), loose: Vec::new(), workgroup_size: ep.workgroup_size, workgroup: Vec::new(), span: ep.annotation, dialect: ep.dialect };
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
        if g.is_resource() {
            // The loose uniforms of a group share their buffer.
            for r in m.resource_of[gid].clone() {
                if !iface.resources.contains(&r) {
                    iface.resources.push(r);
                }
            }
            iface.loose.extend(m.loose_of[gid]);
            continue;
        }
        // A mesh entry point's outputs and the task payload are module
        // variables (`lower::mesh`).
        if super::mesh::is_mesh_output(g) || matches!(g.kind, GlobalKind::TaskPayload) {
            if describe {
                match (&g.kind, &g.ty) {
                    (GlobalKind::Builtin(b), _) => iface.builtins.push(b.name().to_string()),
                    // A per-vertex output: its element type.
                    (GlobalKind::Io { .. }, Ty::RuntimeArray(elem)) => {
                        let ty = m.ty(elem);
                        let dsl_type = m.show_ty(elem);
                        let interp = interpolation(elem, p.flat.contains(&gid));
                        iface.outputs.push(IoVar { name: g.name.clone(), location: ep.location(gid), explicit_location: true, span: g.span, ty, dsl_type, interpolation: interp.0 });
                    }
                    _ => {}
                }
            }
            continue;
        }
        if matches!(g.kind, GlobalKind::Workgroup) {
            if describe {
                iface.workgroup.push((g.name.clone(), g.span));
            }
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
        if is_stage_input(&g.kind, stage) {
            let (binding, arg_ty, to_int) = match g.kind {
                GlobalKind::Io { .. } => {
                    let l = ep.location(gid);
                    let interp = if stage == Fragment { interpolation(&g.ty, p.flat.contains(&gid)) } else { (None, None) };
                    if describe {
                        let dsl_type = m.show_ty(&g.ty);
                        iface.inputs.push(IoVar { name: g.name.clone(), location: l, explicit_location: matches!(g.kind, GlobalKind::Io { location: Some(_), .. }), span: g.span, ty, dsl_type, interpolation: interp.0 });
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
                        BuiltinVar::GlobalInvocationId => (naga::Binding::BuiltIn(naga::BuiltIn::GlobalInvocationId), ty, false),
                        BuiltinVar::LocalInvocationId => (naga::Binding::BuiltIn(naga::BuiltIn::LocalInvocationId), ty, false),
                        BuiltinVar::LocalInvocationIndex => (naga::Binding::BuiltIn(naga::BuiltIn::LocalInvocationIndex), ty, false),
                        BuiltinVar::WorkGroupId => (naga::Binding::BuiltIn(naga::BuiltIn::WorkGroupId), ty, false),
                        BuiltinVar::NumWorkGroups => (naga::Binding::BuiltIn(naga::BuiltIn::NumWorkGroups), ty, false),
                        BuiltinVar::DrawId => (naga::Binding::BuiltIn(naga::BuiltIn::DrawIndex), u32_ty, true),
                        BuiltinVar::PrimitiveId => (naga::Binding::BuiltIn(naga::BuiltIn::PrimitiveIndex), u32_ty, true),
                        BuiltinVar::SubgroupSize => (naga::Binding::BuiltIn(naga::BuiltIn::SubgroupSize), ty, false),
                        BuiltinVar::SubgroupInvocationId => (naga::Binding::BuiltIn(naga::BuiltIn::SubgroupInvocationId), ty, false),
                        BuiltinVar::NumSubgroups => (naga::Binding::BuiltIn(naga::BuiltIn::NumSubgroups), ty, false),
                        BuiltinVar::SubgroupId => (naga::Binding::BuiltIn(naga::BuiltIn::SubgroupId), ty, false),
                        _ => continue,
                    }
                }
                _ => continue,
            };
            args.push((gid, binding, arg_ty, to_int));
        } else if is_stage_output(&g.kind, stage) {
            if own[gid] {
                own_outputs.push(gid);
            }
            match g.kind {
                GlobalKind::Io { .. } => {
                    let l = ep.location(gid);
                    if let Some(&(_, prev)) = seen_out.iter().find(|o| o.0 == l) {
                        // sema reports this as a user error first.
                        return Err(Diagnostic::bug(format!("entry point `{}` writes two outputs at location {l}", ep.name), Some(use_span))
                            .with_secondary(prev, "this output also uses it")
                            .with_note("`@out` and `@inout` variables written by one vertex entry point share the output locations"));
                    }
                    seen_out.push((l, g.span));
                    let interp = if stage == Vertex { interpolation(&g.ty, p.flat.contains(&gid)) } else { (None, None) };
                    if describe {
                        let dsl_type = m.show_ty(&g.ty);
                        iface.outputs.push(IoVar { name: g.name.clone(), location: l, explicit_location: matches!(g.kind, GlobalKind::Io { location: Some(_), .. }), span: g.span, ty, dsl_type, interpolation: interp.0 });
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
    // A mesh entry point's epilogue runs on invocation 0: the argument
    // holding the local invocation index (one added where none is read).
    let local_index = args.iter().position(|a| a.1 == naga::Binding::BuiltIn(naga::BuiltIn::LocalInvocationIndex)).unwrap_or(args.len()) as u32;
    let (mesh_info, mesh) = match stage {
        naga::ShaderStage::Mesh => {
            let (info, out) = m.mesh_output(ep, local_index);
            (Some(info), Some(out))
        }
        _ => (None, None),
    };
    let kind = FnKind::Entry(EntryOutputs { result_ty, members, stage, dialect: ep.dialect, mesh });
    let mut b = FnBuilder::new(m, &ep.name, &ep.func.locals, kind);
    b.vertex_lod = stage == Vertex;
    // The prologue's stores, then the statements.
    let mut body = block_for(args.len() + ep.func.body.len() + 1);
    let private = |m: &ModuleBuilder, gid: sema::GlobalId| match m.globals[gid] {
        GlobalSlot::Var(h) if !own[gid] => Some(h),
        _ => None,
    };
    // In a GL module the interface variables take the source names (the
    // GLSL writer names them by location; emit renames them), so what
    // holds them inside the entry function is named apart: `in_a_pos`,
    // `out_v_uv`, and `io_a_pos` for a private copy (`globals.rs`).
    let gl = b.m.flavor == Flavor::Gl;
    for gid in own_outputs {
        let g = &p.globals[gid];
        let ty = b.m.ty(&g.ty);
        let name = if gl && matches!(g.kind, GlobalKind::Io { .. }) { ["out_", &g.name].concat() } else { g.name.clone() };
        b.output_local(gid, &name, ty, g.span);
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
            None if gl && matches!(g.kind, GlobalKind::Io { .. }) => ["in_", &g.name].concat(),
            None => g.name.trim_start_matches("gl_").to_owned(),
        };
        b.func.arguments.push(naga::FunctionArgument { name: Some(name), ty, binding: Some(binding.clone()) });
        b.input_argument(&mut body, gid, h, i as u32, to_int, g.span);
    }
    if mesh_info.is_some() && local_index as usize == args.len() {
        let ty = b.m.ty(&Ty::Scalar(Scalar::Uint));
        b.func.arguments.push(naga::FunctionArgument { name: Some("local_invocation_index".into()), ty, binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::LocalInvocationIndex)) });
    }
    b.stmts_into(ep.func.body.as_slice(), &mut body);
    if !matches!(body.last(), Some(naga::Statement::Return { .. })) {
        let end = Span::new(ep.func.span.end.saturating_sub(1), ep.func.span.end);
        b.entry_return(&mut body, end);
    }
    let result = match stage {
        // The task entry point's mesh workgroup grid (`EmitMeshTasksEXT`).
        naga::ShaderStage::Task => Some(naga::FunctionResult { ty: b.m.ty(&Ty::Vector(Scalar::Uint, 3)), binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::MeshTaskSize)) }),
        _ => result_ty.map(|ty| naga::FunctionResult { ty, binding: None }),
    };
    let function = b.finish(body, result);
    let task_payload = ep.func.uses.keys().find(|&&g| matches!(p.globals[g].kind, GlobalKind::TaskPayload)).and_then(|&g| match m.globals[g] {
        GlobalSlot::Var(h) => Some(h),
        _ => None,
    });
    m.module.entry_points.push(naga::EntryPoint {
        name: ep.name.clone(),
        stage,
        early_depth_test: None,
        workgroup_size: ep.workgroup_size,
        workgroup_size_overrides: None,
        function,
        mesh_info,
        task_payload,
        incoming_ray_payload: None,
    });
    Ok(iface)
}
