//! Mesh and task entry points (dasSpirv's VK_EXT_mesh_shader stages; sema
//! lets only SPIR-V have them).
//!
//! The DSL writes a mesh entry point's outputs as separate arrays, GLSL's
//! way: `gl_MeshVerticesEXT[i].gl_Position`, per-vertex `@out` arrays
//! (`mo_color[i]`), `gl_PrimitiveTriangleIndicesEXT[i]`,
//! `gl_MeshPrimitivesEXT[i].gl_PrimitiveID`. naga has one workgroup
//! variable of vertex and primitive structs instead (`MeshStageInfo`). So
//! each DSL array is a workgroup array of its own (`globals.rs`), and the
//! entry point's epilogue copies the counts `SetMeshOutputsEXT` set into
//! naga's variable, after a workgroup barrier, on invocation 0.
//! `EmitMeshTasksEXT(x, y, z)` is the task entry point's return of its
//! `mesh_task_size`.

use naga::{Block, Expression as E, Handle, Statement};

use super::entry::ClipAdapt;
use super::function::{span, FnBuilder, FnKind};
use super::interface::Conventions;
use super::module::{GlobalSlot, ModuleBuilder};
use crate::sema::{self, BuiltinVar, GlobalKind, IoKind, Scalar, Ty};
use crate::source::Span;

/// naga's output variable's members: the vertices, the primitives and
/// their counts.
const VERTICES: u32 = 0;
const PRIMITIVES: u32 = 1;
const VERTEX_COUNT: u32 = 2;
const PRIMITIVE_COUNT: u32 = 3;

/// Whether a global is one of a mesh entry point's output arrays.
pub(super) fn is_mesh_output(g: &sema::Global) -> bool {
    match g.kind {
        GlobalKind::Builtin(b) => b.is_mesh_output(),
        GlobalKind::Io { kind: IoKind::Out, .. } => matches!(g.ty, Ty::RuntimeArray(_)),
        _ => false,
    }
}

/// What a mesh entry point's epilogue copies: from each DSL array (a
/// workgroup variable) into a member of naga's vertex or primitive struct.
#[derive(Clone, Debug)]
pub(super) struct MeshOut {
    /// naga's output variable.
    var: Handle<naga::GlobalVariable>,
    /// Per vertex member: the array it comes from, and whether it is a
    /// field of the array's struct elements (`gl_MeshVerticesEXT`).
    vertex: Vec<(Handle<naga::GlobalVariable>, bool)>,
    /// Per primitive member: the array, whether through a field, whether
    /// converted from `int` (`gl_PrimitiveID`, naga's `u32`).
    primitive: Vec<(Handle<naga::GlobalVariable>, bool, bool)>,
    /// The struct member the first `vertex` / `primitive` source goes to
    /// (1 where the entry point writes no position / no indices: zero).
    vertex_first: u32,
    primitive_first: u32,
    /// The argument holding the local invocation index.
    local_index: u32,
}

impl ModuleBuilder<'_> {
    /// naga's output variable of mesh entry point `ep` and its stage info:
    /// a vertex struct of the position (zero when the entry point writes
    /// none) and the per-vertex outputs it writes, by location; a
    /// primitive struct of the triangle indices and the primitive id.
    /// `local_index`: the argument holding the local invocation index.
    pub(super) fn mesh_output(&mut self, ep: &sema::EntryPoint, local_index: u32) -> (naga::MeshStageInfo, MeshOut) {
        let [max_vertices, max_primitives] = ep.mesh.expect("a mesh entry point has its sizes");
        let p = self.p;
        let shadow = |m: &Self, g: sema::GlobalId| match m.globals[g] {
            GlobalSlot::Var(h) => h,
            _ => unreachable!("a mesh output is a workgroup array"),
        };
        let uses = |b: BuiltinVar| ep.func.uses.keys().copied().find(|&g| matches!(p.globals[g].kind, GlobalKind::Builtin(x) if x == b));
        let u32_ty = self.ty(&Ty::Scalar(Scalar::Uint));
        let vec4 = self.ty(&Ty::Vector(Scalar::Float, 4));
        let uvec3 = self.ty(&Ty::Vector(Scalar::Uint, 3));
        let (mut vertex, mut primitive) = (Vec::new(), Vec::new());
        // The position first: an entry point that writes none outputs zero.
        let mut vfields = vec![("position".to_string(), vec4, Some(naga::Binding::BuiltIn(naga::BuiltIn::Position { invariant: false })))];
        let positions = uses(BuiltinVar::MeshVertices).map(|g| shadow(self, g));
        let mut outputs: Vec<(u32, sema::GlobalId)> =
            ep.func.uses.keys().copied().filter(|&g| matches!(p.globals[g].kind, GlobalKind::Io { .. }) && is_mesh_output(&p.globals[g])).map(|g| (ep.location(g), g)).collect();
        outputs.sort_unstable();
        for &(l, g) in &outputs {
            let Ty::RuntimeArray(elem) = &p.globals[g].ty else { continue };
            let ty = self.ty(elem);
            let flat = p.flat.contains(&g) || elem.scalar() != Some(Scalar::Float);
            let (interpolation, sampling) = if flat { (naga::Interpolation::Flat, None) } else { (naga::Interpolation::Perspective, Some(naga::Sampling::Center)) };
            let binding = naga::Binding::Location { location: l, interpolation: Some(interpolation), sampling, blend_src: None, per_primitive: false };
            vfields.push((p.globals[g].name.clone(), ty, Some(binding)));
            vertex.push((shadow(self, g), false));
        }
        let mut pfields = vec![("indices".to_string(), uvec3, Some(naga::Binding::BuiltIn(naga::BuiltIn::TriangleIndices)))];
        let indices = uses(BuiltinVar::PrimitiveTriangleIndices).map(|g| shadow(self, g));
        let prims = uses(BuiltinVar::MeshPrimitives).map(|g| shadow(self, g));
        if let Some(h) = prims {
            pfields.push(("primitive_id".to_string(), u32_ty, Some(naga::Binding::BuiltIn(naga::BuiltIn::PrimitiveIndex))));
            primitive.push((h, true, true));
        }
        let name = &ep.name;
        let vertex_ty = self.struct_type([name, "_vertex"].concat(), vfields);
        let primitive_ty = self.struct_type([name, "_primitive"].concat(), pfields);
        let array = |m: &mut Self, base, n: u32| {
            let stride = m.types.layout(&m.module, base).to_stride();
            m.add_type(None, naga::TypeInner::Array { base, size: naga::ArraySize::Constant(std::num::NonZeroU32::new(n).expect("sizes from 1")), stride })
        };
        let vertices = array(self, vertex_ty, max_vertices);
        let primitives = array(self, primitive_ty, max_primitives);
        let b = |x| Some(naga::Binding::BuiltIn(x));
        let out_ty = self.struct_type(
            [name, "_mesh"].concat(),
            vec![
                ("vertices".into(), vertices, b(naga::BuiltIn::Vertices)),
                ("primitives".into(), primitives, b(naga::BuiltIn::Primitives)),
                ("vertex_count".into(), u32_ty, b(naga::BuiltIn::VertexCount)),
                ("primitive_count".into(), u32_ty, b(naga::BuiltIn::PrimitiveCount)),
            ],
        );
        let var = self.add_global([name, "_mesh_out"].concat(), naga::AddressSpace::WorkGroup, None, out_ty, None, naga::Span::UNDEFINED);
        // Position and indices first, as the structs have them; one the
        // entry point never writes is left zero.
        if let Some(h) = positions {
            vertex.insert(0, (h, true));
        }
        if let Some(h) = indices {
            primitive.insert(0, (h, false, false));
        }
        let out = MeshOut { var, vertex, primitive, vertex_first: u32::from(positions.is_none()), primitive_first: u32::from(indices.is_none()), local_index };
        let info = naga::MeshStageInfo {
            topology: naga::MeshOutputTopology::Triangles,
            max_vertices,
            max_vertices_override: None,
            max_primitives,
            max_primitives_override: None,
            vertex_output_type: vertex_ty,
            primitive_output_type: primitive_ty,
            output_variable: var,
        };
        (info, out)
    }
}

impl FnBuilder<'_, '_> {
    fn mesh_out(&self) -> Option<MeshOut> {
        match &self.kind {
            FnKind::Entry(outs) => outs.mesh.clone(),
            FnKind::Helper => None,
        }
    }

    /// `SetMeshOutputsEXT(vertices, primitives)`: the counts in naga's
    /// output variable (every invocation stores the same, as the call is
    /// uniform).
    pub(super) fn set_mesh_outputs(&mut self, args: &[sema::Expr], block: &mut Block, s: Span) {
        let Some(mo) = self.mesh_out() else { return };
        let base = self.append_plain(E::GlobalVariable(mo.var), s);
        for (arg, member) in args.iter().zip([VERTEX_COUNT, PRIMITIVE_COUNT]) {
            let mut v = self.expr(arg, block);
            v = self.convert(v, &arg.ty, Scalar::Uint, s);
            let ptr = self.append(E::AccessIndex { base, index: member }, s);
            self.push(block, Statement::Store { pointer: ptr, value: v }, s);
        }
    }

    /// `EmitMeshTasksEXT(x, y, z)`: the task entry point returns its mesh
    /// workgroup grid.
    pub(super) fn emit_mesh_tasks(&mut self, args: &[sema::Expr], block: &mut Block, s: Span) {
        let mut comps = Vec::with_capacity(3);
        for arg in args {
            let v = self.expr(arg, block);
            comps.push(self.convert(v, &arg.ty, Scalar::Uint, s));
        }
        let ty = self.m.ty(&Ty::Vector(Scalar::Uint, 3));
        let value = self.append(E::Compose { ty, components: comps }, s);
        self.push(block, Statement::Return { value: Some(value) }, s);
    }

    /// The end of a task entry point that launched nothing: no mesh
    /// workgroups.
    pub(super) fn task_return_none(&mut self, block: &mut Block, s: Span) {
        let ty = self.m.ty(&Ty::Vector(Scalar::Uint, 3));
        let value = self.append_plain(E::ZeroValue(ty), s);
        self.push(block, Statement::Return { value: Some(value) }, s);
    }

    /// The end of a mesh entry point: once every invocation has written its
    /// part (a workgroup barrier), invocation 0 copies the DSL arrays into
    /// naga's output variable, as many elements as the counts say.
    pub(super) fn mesh_epilogue(&mut self, block: &mut Block, s: Span) {
        let Some(mo) = self.mesh_out() else { return };
        self.push(block, Statement::ControlBarrier(naga::Barrier::WORK_GROUP), s);
        let mut copy = Block::new();
        let vertex: Vec<(Handle<naga::GlobalVariable>, bool, bool)> = mo.vertex.iter().map(|&(h, f)| (h, f, false)).collect();
        self.copy_loop(&mut copy, &mo, VERTICES, VERTEX_COUNT, mo.vertex_first, &vertex, s);
        self.copy_loop(&mut copy, &mo, PRIMITIVES, PRIMITIVE_COUNT, mo.primitive_first, &mo.primitive, s);
        let index = self.append_plain(E::FunctionArgument(mo.local_index), s);
        let zero = self.literal(naga::Literal::U32(0), s);
        let first = self.append(E::Binary { op: naga::BinaryOperator::Equal, left: index, right: zero }, s);
        self.push(block, Statement::If { condition: first, accept: copy, reject: Block::new() }, s);
    }

    /// `for i in 0..count { out.ARRAY[i].member_k = source_k[i] }`, members
    /// numbered from `first_member`.
    #[allow(clippy::too_many_arguments)]
    fn copy_loop(&mut self, block: &mut Block, mo: &MeshOut, array: u32, count: u32, first_member: u32, sources: &[(Handle<naga::GlobalVariable>, bool, bool)], s: Span) {
        if sources.is_empty() {
            return;
        }
        let u32_ty = self.m.ty(&Ty::Scalar(Scalar::Uint));
        let var = self.func.local_variables.append(naga::LocalVariable { name: Some("mesh_i".into()), ty: u32_ty, init: None }, span(s));
        let i_ptr = self.append_plain(E::LocalVariable(var), s);
        let zero = self.literal(naga::Literal::U32(0), s);
        self.push(block, Statement::Store { pointer: i_ptr, value: zero }, s);
        let out = self.append_plain(E::GlobalVariable(mo.var), s);
        let mut body = Block::new();
        let i = self.append(E::Load { pointer: i_ptr }, s);
        let count_ptr = self.append(E::AccessIndex { base: out, index: count }, s);
        let n = self.append(E::Load { pointer: count_ptr }, s);
        let done = self.append(E::Binary { op: naga::BinaryOperator::GreaterEqual, left: i, right: n }, s);
        let mut stop = Block::new();
        stop.push(Statement::Break, span(s));
        self.push(&mut body, Statement::If { condition: done, accept: stop, reject: Block::new() }, s);
        let elems = self.append(E::AccessIndex { base: out, index: array }, s);
        let elem = self.append(E::Access { base: elems, index: i }, s);
        for (k, &(src, field, to_uint)) in sources.iter().enumerate() {
            let src_base = self.append_plain(E::GlobalVariable(src), s);
            let mut from = self.append(E::Access { base: src_base, index: i }, s);
            if field {
                from = self.append(E::AccessIndex { base: from, index: 0 }, s);
            }
            let mut v = self.append(E::Load { pointer: from }, s);
            if to_uint {
                v = self.append(E::As { expr: v, kind: naga::ScalarKind::Uint, convert: Some(4) }, s);
            }
            // The position: Vulkan clip space adapted as a Vulkan-dialect
            // vertex entry point's is (y' = -y for wgpu's flipped viewport).
            if array == VERTICES && field && self.m.conventions == Conventions::Portable {
                v = self.adapt_clip_space(v, ClipAdapt::VulkanToGpu, s);
            }
            let to = self.append(E::AccessIndex { base: elem, index: first_member + k as u32 }, s);
            self.push(&mut body, Statement::Store { pointer: to, value: v }, s);
        }
        self.flush(&mut body);
        let mut cont = Block::new();
        let cur = self.append(E::Load { pointer: i_ptr }, s);
        let one = self.literal(naga::Literal::U32(1), s);
        let next = self.append(E::Binary { op: naga::BinaryOperator::Add, left: cur, right: one }, s);
        self.push(&mut cont, Statement::Store { pointer: i_ptr, value: next }, s);
        self.flush(&mut cont);
        self.push(block, Statement::Loop { body, continuing: cont, break_if: None }, s);
    }
}
