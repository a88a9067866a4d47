//! Compute: `[compute_program(local_size_x = X, ...)]` workgroup sizes,
//! `gl_WorkGroupSize`, the barrier, atomic and image builtins, and which
//! stages may use workgroup memory, storage buffers and images.

use super::*;
use crate::sema::builtins::AtomicOp;

/// The compute builtin a name calls, if any.
pub(super) fn compute_builtin(name: &str) -> Option<Builtin> {
    use naga::Barrier as B;
    let all = B::STORAGE | B::WORK_GROUP | B::TEXTURE;
    Some(match name {
        "barrier" => Builtin::Barrier { control: true, flags: B::WORK_GROUP },
        "memoryBarrier" | "groupMemoryBarrier" => Builtin::Barrier { control: false, flags: all },
        "memoryBarrierShared" => Builtin::Barrier { control: false, flags: B::WORK_GROUP },
        "memoryBarrierBuffer" => Builtin::Barrier { control: false, flags: B::STORAGE },
        "memoryBarrierImage" => Builtin::Barrier { control: false, flags: B::TEXTURE },
        "atomicAdd" => Builtin::Atomic(AtomicOp::Add),
        "atomicMin" => Builtin::Atomic(AtomicOp::Min),
        "atomicMax" => Builtin::Atomic(AtomicOp::Max),
        "atomicAnd" => Builtin::Atomic(AtomicOp::And),
        "atomicOr" => Builtin::Atomic(AtomicOp::Or),
        "atomicXor" => Builtin::Atomic(AtomicOp::Xor),
        "atomicExchange" => Builtin::Atomic(AtomicOp::Exchange),
        "atomicCompSwap" => Builtin::Atomic(AtomicOp::CompSwap),
        "imageLoad" => Builtin::ImageLoad,
        "imageStore" => Builtin::ImageStore,
        "imageSize" => Builtin::ImageSize,
        "SetMeshOutputsEXT" => Builtin::SetMeshOutputs,
        "EmitMeshTasksEXT" => Builtin::EmitMeshTasks,
        _ => return None,
    })
}

/// The largest `local_size_*` the checker takes; each target's device
/// minimums are checked in `emit::limits`.
const MAX_LOCAL_SIZE: i64 = 65535;
/// The most vertices or primitives one mesh workgroup may write: what
/// Vulkan guarantees (maxMeshOutputVertices, maxMeshOutputPrimitives).
const MAX_MESH_OUTPUTS: u32 = 256;

impl<'a, 'd> Checker<'a, 'd> {
    /// `local_size_x/y/z` of a compute entry point (1 where not given):
    /// positive integer constants. `version = N` (daslang's GLSL version)
    /// is accepted and has no effect: each target has its own.
    pub(super) fn workgroup_size(&mut self, decl: &'a ast::FunctionDecl) -> [u32; 3] {
        let mut size = [1u32; 3];
        let workgroups = |s: Option<naga::ShaderStage>| matches!(s, Some(naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task));
        let Some((a, sa)) = decl.stage_annotation().filter(|(_, s)| workgroups(s.stage)) else { return size };
        let annot = a.name.name.as_str();
        let mesh = sa.stage == Some(naga::ShaderStage::Mesh);
        let mut given = false;
        for arg in &a.args {
            let axis = match arg.name.name.as_str() {
                "local_size_x" => 0,
                "local_size_y" => 1,
                "local_size_z" => 2,
                "version" | "name" => continue,
                // Read by `mesh_output`.
                "max_vertices" | "max_primitives" | "output_topology" if mesh => continue,
                // dasSpirv's specialization-constant workgroup sizes.
                id @ ("local_size_x_id" | "local_size_y_id" | "local_size_z_id") => {
                    let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
                    let d = Diagnostic::error(format!("`{id}` (a workgroup size set by a specialization constant) is not supported by umbrac on {}", targets.join(", ")), arg.name.span)
                        .with_note("give the size as `local_size_x = N`");
                    self.diags.push(d);
                    continue;
                }
                other => {
                    let mut d = Diagnostic::error(format!("unknown `{annot}` argument `{other}`"), arg.name.span)
                        .with_note(format!("`[{annot}(local_size_x = X, local_size_y = Y, local_size_z = Z)]` (each 1 when left out)"));
                    if let Some(s) = suggest(other, ["local_size_x", "local_size_y", "local_size_z", "version", "name"]) {
                        d = d.with_note(format!("help: did you mean `{s}`?"));
                    }
                    self.diags.push(d);
                    continue;
                }
            };
            let Some(value) = &arg.value else {
                self.diags.push(Diagnostic::error(format!("`{}` needs a value: `{} = N`", arg.name.name, arg.name.name), arg.name.span));
                continue;
            };
            given = true;
            match self.fold(value, None, value.span) {
                Some(Ok((ConstValue::Int(n), _))) if (1..=MAX_LOCAL_SIZE).contains(&n) => size[axis] = n as u32,
                Some(Ok((ConstValue::Uint(n), _))) if (1..=MAX_LOCAL_SIZE as u64).contains(&n) => size[axis] = n as u32,
                Some(Ok(_)) => {
                    let d = Diagnostic::error(format!("`{}` must be an integer from 1 to {MAX_LOCAL_SIZE}", arg.name.name), value.span)
                        .with_note("a workgroup has at least one invocation along each axis");
                    self.diags.push(d);
                }
                Some(Err(d)) => self.diags.push(d),
                None => {}
            }
        }
        // dasSpirv's `[compute_shader]` takes 1 for every axis left out.
        if !given && sa.dialect == ast::Dialect::Gl {
            let d = Diagnostic::error(format!("compute program `{}` needs a workgroup size", decl.name.name), a.span)
                .with_note("help: `[compute_program(local_size_x = 64)]` (local_size_y and local_size_z are 1 when left out)");
            self.diags.push(d);
        }
        size
    }

    /// A mesh entry point's `max_vertices` and `max_primitives` (64 each
    /// when left out, as dasSpirv's) and its `output_topology`: triangles,
    /// the one dasSpirv writes indices for.
    pub(super) fn mesh_output(&mut self, decl: &'a ast::FunctionDecl) -> [u32; 2] {
        let mut out = [64u32; 2];
        let Some((a, _)) = decl.stage_annotation() else { return out };
        for arg in &a.args {
            let name = arg.name.name.as_str();
            let at = match name {
                "max_vertices" => 0,
                "max_primitives" => 1,
                "output_topology" => {
                    let topology = match arg.value.as_ref().map(|v| &v.kind) {
                        Some(ast::ExprKind::Str(s)) => s.as_str(),
                        _ => "",
                    };
                    if topology != "triangles" {
                        let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
                        let d = Diagnostic::error(format!("mesh output topology `{topology}` is not supported by umbrac on {}", targets.join(", ")), arg.name.span)
                            .with_note("`output_topology = \"triangles\"` (the default) is the one dasSpirv writes primitive indices for");
                        self.diags.push(d);
                    }
                    continue;
                }
                _ => continue,
            };
            let Some(value) = &arg.value else {
                self.diags.push(Diagnostic::error(format!("`{name}` needs a value: `{name} = N`"), arg.name.span));
                continue;
            };
            match self.fold(value, None, value.span) {
                Some(Ok((ConstValue::Int(n), _))) if (1..=MAX_MESH_OUTPUTS as i64).contains(&n) => out[at] = n as u32,
                Some(Ok((ConstValue::Uint(n), _))) if (1..=MAX_MESH_OUTPUTS as u64).contains(&n) => out[at] = n as u32,
                Some(Ok(_)) => {
                    let d = Diagnostic::error(format!("`{name}` must be an integer from 1 to {MAX_MESH_OUTPUTS}"), value.span)
                        .with_note("Vulkan guarantees 256 vertices and primitives per mesh workgroup (maxMeshOutputVertices, maxMeshOutputPrimitives)");
                    self.diags.push(d);
                }
                Some(Err(d)) => self.diags.push(d),
                None => {}
            }
        }
        out
    }

    /// The type of `gl_MeshVerticesEXT` (`array<gl_MeshPerVertexEXT>`, a
    /// struct of `gl_Position`) and `gl_MeshPrimitivesEXT`
    /// (`array<gl_MeshPerPrimitiveEXT>`, of `gl_PrimitiveID`), as
    /// dasSpirv's `spirv_builtins` declares them; `None` for the others.
    pub(super) fn mesh_output_ty(&mut self, b: BuiltinVar, span: Span) -> Option<Ty> {
        let (name, field, ty) = match b {
            BuiltinVar::MeshVertices => ("gl_MeshPerVertexEXT", "gl_Position", Ty::Vector(Scalar::Float, 4)),
            BuiltinVar::MeshPrimitives => ("gl_MeshPerPrimitiveEXT", "gl_PrimitiveID", INT),
            _ => return None,
        };
        let sid = self.out.structs.len();
        self.out.structs.push(StructDef { name: name.to_string(), fields: vec![(field.to_string(), ty, span)], span });
        self.field_index.resize_with(sid, Default::default);
        self.field_index.push(std::iter::once((field, 0)).collect());
        Some(Ty::RuntimeArray(Box::new(Ty::Struct(sid as _))))
    }

    /// `gl_WorkGroupSize`: the entry point's size as a `uint3` constant;
    /// a helper has no one size (several entry points may call it).
    pub(super) fn workgroup_size_value(&mut self, cx: &FnCtx<'a>, span: Span) -> Expr {
        let ty = Ty::Vector(Scalar::Uint, 3);
        if !cx.entry || self.entry_workgroup_size == [0; 3] {
            let what = if cx.entry { "outside a compute program" } else { "in a helper function" };
            let d = Diagnostic::error(format!("`gl_WorkGroupSize` is not available {what}"), span)
                .with_note("it is the `local_size_*` of the `[compute_program]` it is used in; pass it to helpers as an argument");
            self.diags.push(d);
            return err_expr(span);
        }
        let parts = self.entry_workgroup_size.iter().map(|&n| Expr { kind: ExprKind::Uint(n as u64), ty: UINT, span }).collect();
        Expr { kind: ExprKind::Construct(parts), ty, span }
    }

    pub(super) fn check_compute_call(&mut self, cx: &mut FnCtx<'a>, b: Builtin, name: &str, mut xs: Vec<Expr>, span: Span) -> Expr {
        let arity = |n: usize, this: &mut Self, xs: &[Expr], sig: &str| -> bool {
            if xs.len() != n {
                this.diags.push(Diagnostic::error(format!("wrong number of arguments: `{name}` takes {n}"), span).with_note(format!("expected `{sig}`")));
                return false;
            }
            true
        };
        match b {
            Builtin::SetMeshOutputs | Builtin::EmitMeshTasks => {
                let (stage, sig) = match b {
                    Builtin::SetMeshOutputs => (naga::ShaderStage::Mesh, "SetMeshOutputsEXT(vertex_count : uint, primitive_count : uint)"),
                    _ => (naga::ShaderStage::Task, "EmitMeshTasksEXT(x : uint, y : uint, z : uint)"),
                };
                if !cx.entry || self.entry_stage != Some(stage) {
                    let d = Diagnostic::error(format!("`{name}` is only available in the body of a {} entry point", super::stmts::stage_name(stage)), span)
                        .with_note("it belongs to the entry point itself (dasSpirv's VK_EXT_mesh_shader intrinsics), not to a helper or another stage");
                    self.diags.push(d);
                    return err_expr(span);
                }
                if !arity(if stage == naga::ShaderStage::Mesh { 2 } else { 3 }, self, &xs, sig) {
                    return err_expr(span);
                }
                for x in &xs {
                    if !x.ty.is_error() && x.ty != UINT && x.ty != INT {
                        self.diags.push(Diagnostic::error(format!("`{name}` takes `uint` counts, not `{}`", self.show(&x.ty)), x.span).with_note(format!("expected `{sig}`")));
                    }
                }
                Expr { kind: ExprKind::Builtin(b, xs), ty: Ty::Void, span }
            }
            Builtin::Barrier { .. } => {
                self.saw_barrier = true;
                if !arity(0, self, &xs, &format!("{name}()")) {
                    return err_expr(span);
                }
                Expr { kind: ExprKind::Builtin(b, xs), ty: Ty::Void, span }
            }
            Builtin::Atomic(op) => {
                let (n, sig) = match op {
                    AtomicOp::CompSwap => (3, format!("{name}(place, compare, value)")),
                    _ => (2, format!("{name}(place, value)")),
                };
                if !arity(n, self, &xs, &sig) {
                    return err_expr(span);
                }
                let target = &xs[0];
                if target.ty == FLOAT {
                    // dasSpirv takes a float `atomicAdd` (SPV_EXT_shader_atomic_float_add)
                    // and refuses the other float atomics.
                    let d = match op {
                        AtomicOp::Add => Diagnostic::error("a `float` `atomicAdd` is not supported by the glsl330, gles300, glsl430, gles310, wgsl and spirv targets", target.span)
                            .with_note("WGSL and GLSL have integer atomics only, and naga's SPIR-V writer has no float atomic add (dasSpirv's OpAtomicFAddEXT, SPV_EXT_shader_atomic_float_add)"),
                        _ => Diagnostic::error(format!("`{name}` on a `float` is not supported by any target"), target.span)
                            .with_note("daslang refuses it too: only `atomicAdd` has a float form (and umbrac refuses that one)"),
                    };
                    self.diags.push(d.with_note("help: accumulate in a `uint` or `int` (e.g. fixed point: `atomicAdd(sum, uint(x * 1024.0))`)"));
                    return err_expr(span);
                }
                let Some(at) = self.atomic_place(target) else {
                    let d = Diagnostic::error(format!("`{name}` needs an `int` or `uint` in a `@ssbo` buffer or a `@groupshared` variable"), target.span)
                        .with_label(format!("this is `{}`", self.show(&target.ty)))
                        .with_note("atomics operate on shared memory: a storage buffer member (or an element of one) or workgroup memory");
                    self.diags.push(d);
                    return err_expr(span);
                };
                if let Err(d) = self.place_ok(cx, target) {
                    self.diags.push(d);
                    return err_expr(span);
                }
                let ty = target.ty.clone();
                for x in &mut xs[1..] {
                    if x.ty != ty {
                        // An integer literal of the other signedness converts (`atomicAdd(u, 1)`).
                        match (&x.kind, &ty) {
                            (ExprKind::Int(k), Ty::Scalar(Scalar::Uint)) if *k >= 0 => *x = Expr { kind: ExprKind::Uint(*k as u64), ty: UINT, span: x.span },
                            _ => {
                                let d = Diagnostic::error(format!("type mismatch: `{name}` on `{}` takes a `{}` value, not `{}`", self.show(&ty), self.show(&ty), self.show(&x.ty)), x.span);
                                self.diags.push(d);
                                return err_expr(span);
                            }
                        }
                    }
                }
                self.out.atomics.insert(at);
                Expr { kind: ExprKind::Builtin(b, xs), ty, span }
            }
            Builtin::ImageLoad | Builtin::ImageStore | Builtin::ImageSize => {
                let sig = match b {
                    Builtin::ImageLoad => "imageLoad(image, coord)",
                    Builtin::ImageStore => "imageStore(image, coord, value)",
                    _ => "imageSize(image)",
                };
                let n = match b {
                    Builtin::ImageLoad => 2,
                    Builtin::ImageStore => 3,
                    _ => 1,
                };
                if !arity(n, self, &xs, sig) {
                    return err_expr(span);
                }
                let (kind, access, g) = match (&xs[0].ty, &xs[0].kind) {
                    (Ty::Image(k), ExprKind::Global(g)) => match self.out.globals[*g].kind {
                        GlobalKind::Image { access, .. } => (*k, access, *g),
                        _ => (*k, crate::sema::types::Access::ReadWrite, *g),
                    },
                    _ => {
                        let d = Diagnostic::error(format!("`{name}` takes a storage image (`image2D`, `uimage3D`, ...) as its first argument, not `{}`", self.show(&xs[0].ty)), xs[0].span)
                            .with_note(format!("expected `{sig}`"));
                        self.diags.push(d);
                        return err_expr(span);
                    }
                };
                if b == Builtin::ImageSize && kind.dim == crate::sema::types::ImageDim::D2Array {
                    // naga 30's SPIR-V writer queries a storage image's
                    // layer count with an instruction Vulkan forbids.
                    let d = Diagnostic::error(format!("`imageSize` of an `{}` is not supported", kind.name()), span)
                        .with_note("naga 30's SPIR-V writer cannot query a storage image's layer count; pass the size in a uniform");
                    self.diags.push(d);
                    return err_expr(span);
                }
                let coord = Ty::Vector(Scalar::Int, kind.coord_width());
                let texel = Ty::Vector(kind.scalar, 4);
                use crate::sema::types::Access;
                let gname = self.out.globals[g].name.clone();
                match b {
                    Builtin::ImageLoad if access == Access::Write => {
                        let d = Diagnostic::error(format!("`imageLoad` reads `{gname}`, which is `@writeonly`"), span).with_secondary(self.out.globals[g].span, "declared here");
                        self.diags.push(d);
                        return err_expr(span);
                    }
                    Builtin::ImageStore if access == Access::Read => {
                        let d = Diagnostic::error(format!("`imageStore` writes `{gname}`, which is `@readonly`"), span).with_secondary(self.out.globals[g].span, "declared here");
                        self.diags.push(d);
                        return err_expr(span);
                    }
                    _ => {}
                }
                if n >= 2 && xs[1].ty != coord {
                    let d = Diagnostic::error(format!("type mismatch: `{name}` of `{}` takes an `{}` coordinate, not `{}`", kind.name(), self.show(&coord), self.show(&xs[1].ty)), xs[1].span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                if n == 3 && xs[2].ty != texel {
                    let d = Diagnostic::error(format!("type mismatch: `imageStore` of `{}` takes a `{}` texel, not `{}`", kind.name(), self.show(&texel), self.show(&xs[2].ty)), xs[2].span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                let ty = match b {
                    Builtin::ImageLoad => texel,
                    Builtin::ImageStore => Ty::Void,
                    _ => coord,
                };
                Expr { kind: ExprKind::Builtin(b, xs), ty, span }
            }
            _ => err_expr(span),
        }
    }

    /// `length(buf.data)` of a run-time-sized array, or `length(a)` of a
    /// fixed array (daslang's `typeinfo dim`: an `int` known when
    /// compiling), if that is the call.
    pub(super) fn array_length_call(&mut self, xs: &[Expr], span: Span) -> Option<Expr> {
        match xs {
            [x] if matches!(x.ty, Ty::RuntimeArray(_)) => Some(Expr { kind: ExprKind::Builtin(Builtin::ArrayLength, xs.to_vec()), ty: UINT, span }),
            [x] => {
                let Ty::Array(_, n) = x.ty else { return None };
                // The length is the type's: the argument is not evaluated,
                // so a call in it would lose what the call does.
                if let Some(call) = first_call(x) {
                    let d = Diagnostic::error("`length` of a fixed array does not evaluate its argument, which calls a function here", call.span)
                        .with_label("this call would not run")
                        .with_secondary(span, format!("the length is {n}, known when compiling"))
                        .with_note("help: store the array in a `let` first, then take `length` of that");
                    self.diags.push(d);
                    return Some(err_expr(span));
                }
                Some(Expr { kind: ExprKind::Int(n as i64), ty: INT, span })
            }
            _ => None,
        }
    }

    /// The atomic place `e` names: an integer scalar of a `@groupshared`
    /// variable (itself, or an element of an integer array), or of a
    /// `@ssbo` member (itself, or an element of an integer array member).
    fn atomic_place(&self, e: &Expr) -> Option<(GlobalId, Option<u32>)> {
        if !matches!(e.ty, Ty::Scalar(Scalar::Int | Scalar::Uint)) {
            return None;
        }
        let base = match &e.kind {
            ExprKind::Index(b, _) if matches!(b.ty, Ty::Array(..) | Ty::RuntimeArray(_)) => b,
            _ => e,
        };
        match &base.kind {
            ExprKind::Global(g) if matches!(self.out.globals[*g].kind, GlobalKind::Workgroup) => Some((*g, None)),
            // dasSpirv's `@ssbo x : array<uint>`: the buffer is the array.
            ExprKind::Global(g) if matches!(self.out.globals[*g].kind, GlobalKind::Storage { .. }) && matches!(base.ty, Ty::RuntimeArray(_)) => Some((*g, None)),
            ExprKind::Field(root, m) => match &root.kind {
                ExprKind::Global(g) if matches!(self.out.globals[*g].kind, GlobalKind::Storage { .. }) => Some((*g, Some(*m))),
                _ => None,
            },
            _ => None,
        }
    }

    /// What a stage may use: compute programs have no `@in`/`@out`,
    /// workgroup memory is compute-only, vertex programs write no storage
    /// (WebGPU has no writable storage in the vertex stage); the targets
    /// without compute refuse it here.
    pub(super) fn check_compute_rules(&mut self, decl: &'a ast::FunctionDecl, name: &str, stage: naga::ShaderStage, func: &Function) {
        use crate::sema::types::Access;
        if stage == naga::ShaderStage::Compute {
            let at = decl.stage_annotation().map_or(decl.name.span, |(a, _)| a.span);
            self.compute_used(at, &format!("compute program `{name}`"));
        }
        for (&gid, &span) in &func.uses {
            // Borrowed: `self.diags` is another field, and most uses are fine.
            let g = &self.out.globals[gid];
            let gname = &g.name;
            match g.kind {
                GlobalKind::Io { .. } if stage == naga::ShaderStage::Compute => {
                    let d = Diagnostic::error(format!("compute program `{name}` uses `{gname}`, an interface variable"), span)
                        .with_secondary(g.span, "declared here")
                        .with_note("compute programs have no `@in`/`@out`: read and write `@ssbo` buffers or storage images");
                    self.diags.push(d);
                }
                GlobalKind::TaskPayload if !matches!(stage, naga::ShaderStage::Task | naga::ShaderStage::Mesh) => {
                    let d = Diagnostic::error(format!("`{gname}` is a `@task_payload`, which only task and mesh entry points have; `{name}` is a {} entry point", super::stmts::stage_name(stage)), span)
                        .with_secondary(g.span, "declared here");
                    self.diags.push(d);
                }
                GlobalKind::Io { .. } if stage == naga::ShaderStage::Task => {
                    let d = Diagnostic::error(format!("task entry point `{name}` uses `{gname}`, an interface variable"), span)
                        .with_secondary(g.span, "declared here")
                        .with_note("a task entry point has no `@in`/`@out`: it hands its mesh workgroups a `@task_payload`");
                    self.diags.push(d);
                }
                GlobalKind::Io { kind, .. } if (stage == naga::ShaderStage::Mesh) != (kind == IoKind::Out && matches!(g.ty, Ty::RuntimeArray(_))) && (stage == naga::ShaderStage::Mesh || matches!(g.ty, Ty::RuntimeArray(_))) => {
                    let d = match stage {
                        naga::ShaderStage::Mesh => Diagnostic::error(format!("mesh entry point `{name}` uses `{gname}`, which is no per-vertex output"), span)
                            .with_note("a mesh entry point has no `@in`; its outputs are `@out @location = N NAME : array<T>`, one `T` per vertex"),
                        _ => Diagnostic::error(format!("`{gname}` is an array output (one element per vertex), which only mesh entry points have; `{name}` is a {} entry point", super::stmts::stage_name(stage)), span),
                    };
                    self.diags.push(d.with_secondary(g.span, "declared here"));
                }
                GlobalKind::Workgroup if !matches!(stage, naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task) => {
                    let d = Diagnostic::error(format!("`{gname}` is `@groupshared`, which only compute programs have; `{name}` is a {} entry point", super::stmts::stage_name(stage)), span)
                        .with_secondary(g.span, "declared here");
                    self.diags.push(d);
                }
                // Only WebGPU refuses the declaration (a pipeline whose vertex
                // stage binds writable storage); the other targets take it.
                GlobalKind::Storage { access: Access::ReadWrite, .. } | GlobalKind::Image { access: Access::ReadWrite | Access::Write, .. }
                    if stage == naga::ShaderStage::Vertex && (self.targets_defaulted || self.targets.contains(&crate::Target::Wgsl)) =>
                {
                    let d = Diagnostic::error(format!("vertex entry point `{name}` uses `{gname}`, which it could write"), span)
                        .with_secondary(g.span, "declared here")
                        .with_note("WebGPU has no writable storage in vertex programs: declare it `@readonly`, write it from a fragment or compute program, or compile for targets other than `wgsl`");
                    self.diags.push(d);
                }
                _ => {}
            }
            let what = match g.kind {
                GlobalKind::Storage { .. } => Some("storage buffer"),
                GlobalKind::Image { .. } => Some("storage image"),
                GlobalKind::Workgroup => Some("workgroup variable"),
                _ => None,
            };
            if let Some(what) = what {
                let what = format!("{what} `{gname}`");
                self.compute_used(span, &what);
            }
        }
    }
}

/// Storage and workgroup variables that cannot be copied as a whole: a
/// buffer whose struct ends in a run-time-sized array (or that array), and
/// anything holding atomics (WGSL has no atomic values, only places). Their
/// members and elements are read and written one by one. Checked once the
/// program's atomics are known (`Program::atomics`).
pub(super) fn check_whole_values(p: &Program, diags: &mut Diagnostics) {
    // Only storage and workgroup variables have whole-value rules.
    if !p.globals.iter().any(|g| matches!(g.kind, GlobalKind::Storage { .. } | GlobalKind::Workgroup)) {
        return;
    }
    let bodies = p.functions.iter().map(|f| &f.body).chain(p.entry_points.iter().map(|e| &e.func.body));
    let mut reported = std::collections::BTreeSet::new();
    for body in bodies {
        super::uniformity::visit_exprs(body, &mut |e| whole_uses(p, e, true, diags, &mut reported));
    }
}

/// Why the place `g` (member `member`) cannot be used as a whole value.
fn whole_problem(p: &Program, g: GlobalId, member: Option<u32>) -> Option<&'static str> {
    let global = &p.globals[g];
    match (&global.kind, member, &global.ty) {
        (GlobalKind::Storage { .. }, None, Ty::Struct(sid)) => {
            if p.structs[*sid].fields.last().is_some_and(|f| matches!(f.1, Ty::RuntimeArray(_))) {
                Some("it holds a run-time-sized array")
            } else if p.atomics.iter().any(|(a, m)| *a == g && m.is_some()) {
                Some("atomics operate on its members")
            } else {
                None
            }
        }
        (GlobalKind::Storage { .. }, Some(m), Ty::Struct(sid)) => match p.structs[*sid].fields.get(m as usize).map(|f| &f.1) {
            Some(Ty::RuntimeArray(_)) => Some("it is a run-time-sized array"),
            Some(Ty::Array(..)) if p.atomics.contains(&(g, Some(m))) => Some("atomics operate on its elements"),
            _ => None,
        },
        (GlobalKind::Workgroup, None, Ty::Array(..)) if p.atomics.contains(&(g, None)) => Some("atomics operate on its elements"),
        _ => None,
    }
}

fn whole_uses(p: &Program, e: &Expr, whole: bool, diags: &mut Diagnostics, reported: &mut std::collections::BTreeSet<(u32, u32)>) {
    let mut report = |name: &str, why: &str| {
        if reported.insert((e.span.start, e.span.end)) {
            let d = Diagnostic::error(format!("`{name}` cannot be read or written as a whole: {why}"), e.span)
                .with_note("help: read and write its elements (or members) one at a time");
            diags.push(d);
        }
    };
    match &e.kind {
        ExprKind::Global(g) => {
            if let Some(why) = whole.then(|| whole_problem(p, *g, None)).flatten() {
                report(&p.globals[*g].name, why);
            }
        }
        ExprKind::Field(b, m) => {
            if let (true, ExprKind::Global(g)) = (whole, &b.kind) {
                if let Some(why) = whole_problem(p, *g, Some(*m)) {
                    let Ty::Struct(sid) = p.globals[*g].ty else { return };
                    report(&format!("{}.{}", p.globals[*g].name, p.structs[sid].fields[*m as usize].0), why);
                    return;
                }
            }
            whole_uses(p, b, false, diags, reported);
        }
        ExprKind::Index(b, i) => {
            whole_uses(p, b, false, diags, reported);
            whole_uses(p, i, true, diags, reported);
        }
        ExprKind::Builtin(Builtin::Atomic(_) | Builtin::ArrayLength, args) => {
            if let Some((first, rest)) = args.split_first() {
                whole_uses(p, first, false, diags, reported);
                for a in rest {
                    whole_uses(p, a, true, diags, reported);
                }
            }
        }
        _ => {
            for c in super::uniformity::children(e) {
                whole_uses(p, c, true, diags, reported);
            }
        }
    }
}

/// The first call to a helper function inside `e`, if any.
fn first_call(e: &Expr) -> Option<&Expr> {
    match &e.kind {
        ExprKind::Call(..) => Some(e),
        _ => super::uniformity::children(e).into_iter().find_map(first_call),
    }
}
