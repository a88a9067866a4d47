//! Function bodies: checked statements and expressions to naga IR.
//!
//! Expressions that naga wants covered by `Statement::Emit` are appended
//! while the emitter runs; the others (literals, constants, variables,
//! arguments, call results) are appended with the emitter paused. Every
//! statement push flushes the pending range first.

use naga::{Block, Expression as E, Handle, Statement};

use super::module::{naga_scalar, vector_size, GlobalSlot, ModuleBuilder};
use super::Flavor;
use crate::sema::builtins::Builtin;
use crate::sema::{self, BuiltinVar, Expr, ExprKind, GlobalKind, IoKind, Scalar, Stmt, Ty};
use crate::syntax::ast::{BinaryOp, UnaryOp};

/// A texture call with its image left open (so one call on an array of
/// samplers can be applied to each element).
enum TexOp {
    Sample { coordinate: Handle<E>, array_index: Option<Handle<E>>, depth_ref: Option<Handle<E>>, level: naga::SampleLevel, offset: Option<Handle<E>> },
    Load { coordinate: Handle<E>, array_index: Option<Handle<E>>, level: Handle<E> },
    Size { level: Handle<E> },
}

/// How a sema local lives in naga.
#[derive(Clone, Copy)]
enum LocalSlot {
    /// A `var`, loop counter or parameter copy: a function-local variable.
    Var(Handle<naga::LocalVariable>),
    /// A `let` or an unmodified parameter: an expression.
    Value(Handle<E>),
    /// A sampler parameter: the sampler this specialisation was made for.
    Sampler(SamplerRef),
    Unset,
}

/// One sampler: element `elem` of sampler global `global` (0 for a single
/// sampler). What a sampler argument names, known when compiling.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub struct SamplerRef {
    pub global: sema::GlobalId,
    pub elem: u32,
}

/// What a `return` does in this function.
pub enum FnKind {
    Helper,
    /// An entry point: `return` builds the output struct from its outputs.
    Entry(EntryOutputs),
}

/// The entry point's outputs, in result-struct member order.
pub struct EntryOutputs {
    pub result_ty: Option<Handle<naga::Type>>,
    /// The output global of each member, read where it lives (a local
    /// variable of the entry function or a private global). `None` for an
    /// output the shader never writes (gl_Position of a vertex shader that
    /// ignores it): zero.
    pub members: Vec<(Option<sema::GlobalId>, Option<BuiltinVar>, Handle<naga::Type>)>,
    pub stage: naga::ShaderStage,
}

pub struct FnBuilder<'m, 'p> {
    pub m: &'m mut ModuleBuilder<'p>,
    pub func: naga::Function,
    emitter: naga::proc::Emitter,
    locals: Vec<LocalSlot>,
    sema_locals: &'p [sema::Local],
    kind: FnKind,
    /// Emit ranges closed by `append_plain`, waiting for the next statement.
    pending: Vec<(Statement, naga::Span)>,
    /// Implicit-LOD sampling samples level 0 (vertex entry points and the
    /// helpers lowered for them): naga, WGSL and SPIR-V allow implicit LOD
    /// only in fragment shaders.
    pub vertex_lod: bool,
    /// Per sema global, in an entry point: an input held as its argument
    /// (`Value`) or an output held in a local variable (`Var`) instead of
    /// the module's private global. Empty in helpers.
    entry_globals: Vec<LocalSlot>,
}

fn span(s: crate::source::Span) -> naga::Span {
    s.into()
}

/// An empty block with room for what `n` checked statements usually
/// become (a statement each, after one or two emit ranges: every plain
/// expression splits a range), so pushing rarely grows its two vectors.
pub fn block_for(n: usize) -> Block {
    match n {
        0 => Block::new(),
        _ => Block::with_capacity(3 * n + 2),
    }
}

/// A block of one `break`.
fn break_block(s: crate::source::Span) -> Block {
    let mut b = Block::with_capacity(1);
    b.push(Statement::Break, span(s));
    b
}

impl<'m, 'p> FnBuilder<'m, 'p> {
    pub fn new(m: &'m mut ModuleBuilder<'p>, name: &str, sema_locals: &'p [sema::Local], kind: FnKind) -> Self {
        let mut func = naga::Function { name: Some(name.to_string()), ..Default::default() };
        // A `let` names its expression: room for all of them up front.
        func.named_expressions.reserve(sema_locals.iter().filter(|l| !l.mutable).count());
        let mut b = FnBuilder { m, func, emitter: Default::default(), locals: vec![LocalSlot::Unset; sema_locals.len()], sema_locals, kind, pending: Vec::new(), vertex_lod: false, entry_globals: Vec::new() };
        b.emitter.start(&b.func.expressions);
        b
    }

    /// Declares parameter `i` as a function argument. Parameters are
    /// immutable, so the argument expression serves directly. A sampler
    /// parameter is no argument: it stands for `sampler`, the one this
    /// copy of the function is specialised for.
    pub fn add_param(&mut self, i: usize, sampler: Option<SamplerRef>) {
        let l = &self.sema_locals[i];
        if let Some(r) = sampler {
            self.locals[i] = LocalSlot::Sampler(r);
            return;
        }
        let ty = self.m.ty(&l.ty);
        let idx = self.func.arguments.len() as u32;
        self.func.arguments.push(naga::FunctionArgument { name: Some(l.name.as_str().to_owned()), ty, binding: None });
        let h = self.append_plain(E::FunctionArgument(idx), l.span);
        self.locals[i] = LocalSlot::Value(h);
    }

    /// Appends an expression that must not be emitted.
    fn append_plain(&mut self, e: E, s: crate::source::Span) -> Handle<E> {
        // Close the running range, append outside it, and start again.
        let pending = self.emitter.finish(&self.func.expressions);
        let h = self.func.expressions.append(e, span(s));
        self.emitter.start(&self.func.expressions);
        if let Some((stmt, sp)) = pending {
            // The range ends before `h`; it is pushed with the next statement.
            self.pending.push((stmt, sp));
        }
        h
    }

    /// Appends an expression that must be emitted.
    fn append(&mut self, e: E, s: crate::source::Span) -> Handle<E> {
        self.func.expressions.append(e, span(s))
    }

    /// Pushes a statement after flushing pending emit ranges.
    fn push(&mut self, block: &mut Block, stmt: Statement, s: crate::source::Span) {
        self.flush(block);
        block.push(stmt, span(s));
    }

    fn flush(&mut self, block: &mut Block) {
        for (stmt, sp) in self.pending.drain(..) {
            block.push(stmt, sp);
        }
        if let Some((stmt, sp)) = self.emitter.finish(&self.func.expressions) {
            block.push(stmt, sp);
        }
        self.emitter.start(&self.func.expressions);
    }

    pub fn finish(mut self, mut body: Block, ret: Option<naga::FunctionResult>) -> naga::Function {
        self.flush(&mut body);
        let _ = self.emitter.finish(&self.func.expressions);
        self.func.body = body;
        self.func.result = ret;
        self.func
    }

    // ------------------------------------------------------------ statements

    /// Lowers statements onto the end of `block`.
    pub fn stmts_into(&mut self, stmts: &[Stmt], block: &mut Block) {
        for s in stmts {
            self.stmt(s, block);
        }
        self.flush(block);
    }

    /// Entry prologue: input `gid` arrives as argument `index` (builtin
    /// `u32` indices converted to the DSL's `int`); see [`Self::hold_input`].
    pub fn input_argument(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, index: u32, to_int: bool, s: crate::source::Span) {
        let mut v = self.append_plain(E::FunctionArgument(index), s);
        if to_int {
            v = self.convert(v, &Ty::Scalar(Scalar::Uint), Scalar::Int, s);
        }
        self.hold_input(block, gid, global, v, s);
    }

    /// Entry prologue: `gl_PointCoord` on targets without point sprites,
    /// float2(0.5), the centre of a one-pixel point; into its private copy
    /// (`Some`) or held as the entry point's own value.
    pub fn point_coord_default(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, s: crate::source::Span) {
        let half = self.literal(naga::Literal::F32(0.5), s);
        let v = self.append(E::Splat { size: naga::VectorSize::Bi, value: half }, s);
        self.hold_input(block, gid, global, v, s);
    }

    /// Entry prologue: input `gid` has value `v`, stored into its private
    /// copy (`Some`) or held as the entry point's own value. The emit range
    /// is closed here, in the function's top block, so the value dominates
    /// every use.
    fn hold_input(&mut self, block: &mut Block, gid: sema::GlobalId, global: Option<Handle<naga::GlobalVariable>>, v: Handle<E>, s: crate::source::Span) {
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
    pub fn output_local(&mut self, gid: sema::GlobalId, name: &str, ty: Handle<naga::Type>, s: crate::source::Span) {
        let var = self.func.local_variables.append(naga::LocalVariable { name: Some(name.to_owned()), ty, init: None }, span(s));
        self.entry_global(gid, LocalSlot::Var(var));
    }

    fn entry_global(&mut self, gid: sema::GlobalId, slot: LocalSlot) {
        if self.entry_globals.is_empty() {
            self.entry_globals = vec![LocalSlot::Unset; self.m.p.globals.len()];
        }
        self.entry_globals[gid] = slot;
    }

    /// A call of helper `fid`: the function it reaches from here and its
    /// argument values. A helper with sampler parameters is specialised
    /// for the samplers given (lowered on its first such call); those
    /// arguments are not passed.
    fn call(&mut self, fid: usize, args: &[Expr], block: &mut Block) -> (Handle<naga::Function>, Vec<Handle<E>>) {
        let mut samplers = Vec::new();
        let mut values = Vec::with_capacity(args.len());
        for a in args {
            if !matches!(a.ty, Ty::Sampler(_)) {
                values.push(self.expr(a, block));
                continue;
            }
            match self.sampler_of(a) {
                Some(Ok(r)) => samplers.push(r),
                _ => unreachable!("sema checks that a sampler argument is known"),
            }
        }
        let function = match samplers.is_empty() {
            true => self.callee(fid),
            false => super::specialised_helper(self.m, fid, self.vertex_lod, samplers),
        };
        (function, values)
    }

    /// The sampler expression `e` names: one known here, or an element of
    /// sampler global `g` picked at run time (`Err((g, index))`). `None`
    /// for an expression that is no sampler.
    fn sampler_of<'e>(&self, e: &'e Expr) -> Option<Result<SamplerRef, (sema::GlobalId, &'e Expr)>> {
        match &e.kind {
            ExprKind::Global(g) if matches!(self.m.globals[*g], GlobalSlot::Sampler { .. }) => Some(Ok(SamplerRef { global: *g, elem: 0 })),
            ExprKind::Index(base, i) => match base.kind {
                ExprKind::Global(g) if matches!(self.m.globals[g], GlobalSlot::Sampler { .. }) => Some(match i.const_int(&self.m.p.consts) {
                    Some(k) => Ok(SamplerRef { global: g, elem: k.clamp(0, u32::MAX as i64) as u32 }),
                    None => Err((g, &**i)),
                }),
                _ => None,
            },
            ExprKind::Local(l) => match self.locals[*l] {
                LocalSlot::Sampler(r) => Some(Ok(r)),
                _ => None,
            },
            _ => None,
        }
    }

    /// The function a call of helper `fid` (without sampler parameters)
    /// reaches from here.
    fn callee(&self, fid: usize) -> Handle<naga::Function> {
        match self.m.vertex_functions.get(fid) {
            Some(Some(h)) if self.vertex_lod => *h,
            // A one-entry module holds every function its entry point
            // reaches (`lower::build`), so a call never misses.
            _ => self.m.functions[fid].expect("the callee is lowered"),
        }
    }

    pub fn block(&mut self, stmts: &[Stmt]) -> Block {
        let mut b = block_for(stmts.len());
        for s in stmts {
            self.stmt(s, &mut b);
        }
        self.flush(&mut b);
        b
    }

    /// The epilogue of an entry point: build and return its outputs.
    pub fn entry_return(&mut self, block: &mut Block, s: crate::source::Span) {
        let FnKind::Entry(outs) = &self.kind else {
            self.push(block, Statement::Return { value: None }, s);
            return;
        };
        let Some(result_ty) = outs.result_ty else {
            self.push(block, Statement::Return { value: None }, s);
            return;
        };
        let members: Vec<_> = outs.members.clone();
        let stage = outs.stage;
        let adapt = self.m.flavor == Flavor::Gpu(super::Conventions::Portable) && stage == naga::ShaderStage::Vertex;
        let mut comps = Vec::with_capacity(members.len());
        for (g, builtin, ty) in members {
            let mut v = match g {
                Some(g) => {
                    let ptr = self.global_pointer(g, s).expect("an entry point's outputs are variables");
                    self.append(E::Load { pointer: ptr }, s)
                }
                None => self.append_plain(E::ZeroValue(ty), s),
            };
            if adapt && builtin == Some(BuiltinVar::Position) {
                v = self.adapt_clip_space(v, s);
            }
            comps.push(v);
        }
        let value = self.append(E::Compose { ty: result_ty, components: comps }, s);
        self.push(block, Statement::Return { value: Some(value) }, s);
    }

    /// GL clip space to WebGPU/Vulkan: z' = (z + w) / 2, y' = -y.
    fn adapt_clip_space(&mut self, p: Handle<E>, s: crate::source::Span) -> Handle<E> {
        let x = self.append(E::AccessIndex { base: p, index: 0 }, s);
        let y = self.append(E::AccessIndex { base: p, index: 1 }, s);
        let z = self.append(E::AccessIndex { base: p, index: 2 }, s);
        let w = self.append(E::AccessIndex { base: p, index: 3 }, s);
        let ny = self.append(E::Unary { op: naga::UnaryOperator::Negate, expr: y }, s);
        let zw = self.append(E::Binary { op: naga::BinaryOperator::Add, left: z, right: w }, s);
        let half = self.append_plain(E::Literal(naga::Literal::F32(0.5)), s);
        let nz = self.append(E::Binary { op: naga::BinaryOperator::Multiply, left: zw, right: half }, s);
        let ty = self.m.ty(&Ty::Vector(Scalar::Float, 4));
        self.append(E::Compose { ty, components: vec![x, ny, nz, w] }, s)
    }

    fn stmt(&mut self, s: &Stmt, block: &mut Block) {
        match s {
            Stmt::Local { local, init, span: sp } => {
                let l = &self.sema_locals[*local];
                if l.mutable {
                    let ty = self.m.ty(&l.ty);
                    let var = self.func.local_variables.append(naga::LocalVariable { name: Some(l.name.as_str().to_owned()), ty, init: None }, span(l.span));
                    self.locals[*local] = LocalSlot::Var(var);
                    let ptr = self.append_plain(E::LocalVariable(var), *sp);
                    let value = match init {
                        Some(e) => self.expr(e, block),
                        None => self.append_plain(E::ZeroValue(ty), *sp),
                    };
                    self.push(block, Statement::Store { pointer: ptr, value }, *sp);
                } else if let Some(e) = init {
                    let h = self.expr(e, block);
                    if self.is_emitted(h) {
                        self.func.named_expressions.entry(h).or_insert_with(|| l.name.as_str().to_owned());
                    }
                    self.locals[*local] = LocalSlot::Value(h);
                }
            }
            Stmt::Assign { target, op, value, span: sp } => self.assign(target, *op, value, *sp, block),
            Stmt::Expr(e) => {
                if let ExprKind::Call(fid, args) = &e.kind {
                    let (function, args) = self.call(*fid, args, block);
                    let result = (e.ty != Ty::Void).then(|| self.append_plain(E::CallResult(function), e.span));
                    self.push(block, Statement::Call { function, arguments: args, result }, e.span);
                } else {
                    self.expr(e, block);
                }
            }
            Stmt::If { cond, then, otherwise, span: sp } => {
                if let ExprKind::Bool(true) = cond.kind {
                    // A plain nested block.
                    let inner = self.block_in(then, block);
                    self.push(block, Statement::Block(inner), *sp);
                    return;
                }
                let c = self.expr(cond, block);
                self.flush(block);
                let accept = self.block(then);
                let reject = self.block(otherwise);
                self.push(block, Statement::If { condition: c, accept, reject }, *sp);
            }
            Stmt::While { cond, body, span: sp } => {
                self.flush(block);
                // The exit test, then the body.
                let mut lb = block_for(body.len() + 1);
                let c = self.expr(cond, &mut lb);
                let not_c = self.append(E::Unary { op: naga::UnaryOperator::LogicalNot, expr: c }, cond.span);
                self.flush(&mut lb);
                lb.push(Statement::If { condition: not_c, accept: break_block(*sp), reject: Block::new() }, span(cond.span));
                for st in body {
                    self.stmt(st, &mut lb);
                }
                self.flush(&mut lb);
                self.push(block, Statement::Loop { body: lb, continuing: Block::new(), break_if: None }, *sp);
            }
            Stmt::For { var, start, end, body, span: sp } => {
                let l = &self.sema_locals[*var];
                let ty = self.m.ty(&l.ty);
                let v = self.func.local_variables.append(naga::LocalVariable { name: Some(l.name.as_str().to_owned()), ty, init: None }, span(l.span));
                self.locals[*var] = LocalSlot::Var(v);
                let ptr = self.append_plain(E::LocalVariable(v), *sp);
                let s0 = self.expr(start, block);
                self.push(block, Statement::Store { pointer: ptr, value: s0 }, start.span);
                // The bound is evaluated once, before the loop.
                let e0 = self.expr(end, block);
                self.flush(block);
                let mut lb = block_for(body.len() + 1);
                let cur = self.append(E::Load { pointer: ptr }, *sp);
                let more = self.append(E::Binary { op: naga::BinaryOperator::Less, left: cur, right: e0 }, end.span);
                let done = self.append(E::Unary { op: naga::UnaryOperator::LogicalNot, expr: more }, end.span);
                self.flush(&mut lb);
                lb.push(Statement::If { condition: done, accept: break_block(*sp), reject: Block::new() }, span(end.span));
                for st in body {
                    self.stmt(st, &mut lb);
                }
                self.flush(&mut lb);
                // The increment: an emit range and the store.
                let mut cont = Block::with_capacity(2);
                let cur2 = self.append(E::Load { pointer: ptr }, *sp);
                let one = match l.ty {
                    Ty::Scalar(Scalar::Uint) => naga::Literal::U32(1),
                    _ => naga::Literal::I32(1),
                };
                let one = self.append_plain(E::Literal(one), *sp);
                let next = self.append(E::Binary { op: naga::BinaryOperator::Add, left: cur2, right: one }, *sp);
                self.push(&mut cont, Statement::Store { pointer: ptr, value: next }, *sp);
                self.flush(&mut cont);
                self.push(block, Statement::Loop { body: lb, continuing: cont, break_if: None }, *sp);
            }
            Stmt::Return(value, sp) => match (&self.kind, value) {
                (FnKind::Entry(_), _) => self.entry_return(block, *sp),
                (FnKind::Helper, v) => {
                    let value = v.as_ref().map(|e| self.expr(e, block));
                    self.push(block, Statement::Return { value }, *sp);
                }
            },
            Stmt::Break(sp) => self.push(block, Statement::Break, *sp),
            Stmt::Continue(sp) => self.push(block, Statement::Continue, *sp),
            Stmt::Discard(sp) => self.push(block, Statement::Kill, *sp),
        }
    }

    fn block_in(&mut self, stmts: &[Stmt], outer: &mut Block) -> Block {
        self.flush(outer);
        self.block(stmts)
    }

    fn is_emitted(&self, h: Handle<E>) -> bool {
        !matches!(
            self.func.expressions[h],
            E::Literal(_) | E::Constant(_) | E::ZeroValue(_) | E::FunctionArgument(_) | E::GlobalVariable(_) | E::LocalVariable(_) | E::CallResult(_)
        )
    }

    fn assign(&mut self, target: &Expr, op: Option<BinaryOp>, value: &Expr, sp: crate::source::Span, block: &mut Block) {
        // A multi-component swizzle is written as a whole-vector store.
        if let ExprKind::Swizzle(base, comps) = &target.kind {
            if comps.len() > 1 {
                let Some(base_ptr) = self.pointer(base, block) else { return };
                let old = self.append(E::Load { pointer: base_ptr }, sp);
                let mut new = self.expr(value, block);
                if let Some(op) = op {
                    let cur = self.swizzle(old, comps, target.span);
                    new = self.binary(op, cur, &target.ty, new, &value.ty, sp);
                }
                let width = base.ty.width().unwrap_or(4);
                let mut parts = Vec::with_capacity(width as usize);
                for i in 0..width {
                    let part = match comps.iter().position(|&c| c == i) {
                        Some(k) => self.append(E::AccessIndex { base: new, index: k as u32 }, sp),
                        None => self.append(E::AccessIndex { base: old, index: i as u32 }, sp),
                    };
                    parts.push(part);
                }
                let ty = self.m.ty(&base.ty);
                let whole = self.append(E::Compose { ty, components: parts }, sp);
                self.push(block, Statement::Store { pointer: base_ptr, value: whole }, sp);
                return;
            }
        }
        let Some(ptr) = self.pointer(target, block) else { return };
        let mut v = self.expr(value, block);
        if let Some(op) = op {
            let cur = self.append(E::Load { pointer: ptr }, sp);
            v = self.binary(op, cur, &target.ty, v, &value.ty, sp);
        }
        self.push(block, Statement::Store { pointer: ptr, value: v }, sp);
    }

    // ------------------------------------------------------------ expressions

    /// A pointer to a place (variable, field, element, one component), if
    /// `e` is one.
    fn pointer(&mut self, e: &Expr, block: &mut Block) -> Option<Handle<E>> {
        match &e.kind {
            ExprKind::Local(id) => match self.locals[*id] {
                LocalSlot::Var(v) => Some(self.append_plain(E::LocalVariable(v), e.span)),
                _ => None,
            },
            ExprKind::Global(g) => self.global_pointer(*g, e.span),
            ExprKind::Field(base, idx) => {
                let b = self.pointer(base, block)?;
                Some(self.append(E::AccessIndex { base: b, index: *idx }, e.span))
            }
            ExprKind::Swizzle(base, comps) if comps.len() == 1 => {
                let b = self.pointer(base, block)?;
                Some(self.append(E::AccessIndex { base: b, index: comps[0] as u32 }, e.span))
            }
            ExprKind::Index(base, index) => {
                let b = self.pointer(base, block)?;
                Some(match index.kind {
                    ExprKind::Int(k) if k >= 0 => self.append(E::AccessIndex { base: b, index: k as u32 }, e.span),
                    ExprKind::Uint(k) => self.append(E::AccessIndex { base: b, index: k as u32 }, e.span),
                    _ => {
                        let i = self.expr(index, block);
                        self.append(E::Access { base: b, index: i }, e.span)
                    }
                })
            }
            _ => None,
        }
    }

    /// Where global `g` is held in this function: the entry point's own
    /// slot, else the module's global.
    fn global_slot(&self, g: sema::GlobalId) -> Option<LocalSlot> {
        match self.entry_globals.get(g) {
            Some(LocalSlot::Unset) | None => None,
            slot => slot.copied(),
        }
    }

    /// A pointer to global `g`, unless it is a held value or a sampler.
    fn global_pointer(&mut self, g: sema::GlobalId, s: crate::source::Span) -> Option<Handle<E>> {
        match self.global_slot(g) {
            Some(LocalSlot::Var(v)) => Some(self.append_plain(E::LocalVariable(v), s)),
            Some(_) => None,
            None => match self.m.globals[g] {
                GlobalSlot::Var(h) => Some(self.append_plain(E::GlobalVariable(h), s)),
                GlobalSlot::Sampler { .. } | GlobalSlot::Absent => None,
            },
        }
    }

    fn literal(&mut self, l: naga::Literal, s: crate::source::Span) -> Handle<E> {
        self.append_plain(E::Literal(l), s)
    }

    /// Broadcasts a scalar to the vector shape of `to` (no-op otherwise).
    fn splat_to(&mut self, h: Handle<E>, from: &Ty, to: &Ty, s: crate::source::Span) -> Handle<E> {
        match (from, to) {
            (Ty::Scalar(_), Ty::Vector(_, n)) => self.append(E::Splat { size: vector_size(*n), value: h }, s),
            _ => h,
        }
    }

    fn swizzle(&mut self, v: Handle<E>, comps: &[u8], s: crate::source::Span) -> Handle<E> {
        if comps.len() == 1 {
            return self.append(E::AccessIndex { base: v, index: comps[0] as u32 }, s);
        }
        let mut pattern = [naga::SwizzleComponent::X; 4];
        for (i, &c) in comps.iter().enumerate() {
            pattern[i] = naga::SwizzleComponent::XYZW[c as usize];
        }
        self.append(E::Swizzle { size: vector_size(comps.len() as u8), vector: v, pattern }, s)
    }

    pub fn expr(&mut self, e: &Expr, block: &mut Block) -> Handle<E> {
        let s = e.span;
        // An input the entry point holds as its argument.
        if let ExprKind::Global(g) = e.kind {
            if let Some(LocalSlot::Value(h)) = self.global_slot(g) {
                return h;
            }
        }
        match &e.kind {
            ExprKind::Float(v) => self.literal(naga::Literal::F32(*v as f32), s),
            ExprKind::Int(v) => self.literal(naga::Literal::I32(*v as i32), s),
            ExprKind::Uint(v) => self.literal(naga::Literal::U32(*v as u32), s),
            ExprKind::Bool(v) => self.literal(naga::Literal::Bool(*v), s),
            ExprKind::Const(c) => {
                let h = self.m.constant(*c);
                self.append_plain(E::Constant(h), s)
            }
            ExprKind::Local(id) => match self.locals[*id] {
                LocalSlot::Value(h) => h,
                LocalSlot::Var(v) => {
                    let p = self.append_plain(E::LocalVariable(v), s);
                    self.append(E::Load { pointer: p }, s)
                }
                LocalSlot::Unset => {
                    let ty = self.m.ty(&e.ty);
                    self.append_plain(E::ZeroValue(ty), s)
                }
                LocalSlot::Sampler(_) => unreachable!("sema allows a sampler only where a sampler is taken"),
            },
            ExprKind::Global(_) | ExprKind::Field(..) | ExprKind::Index(..) if self.is_place(e) => {
                let p = self.pointer(e, block).expect("is_place checked");
                self.append(E::Load { pointer: p }, s)
            }
            ExprKind::Swizzle(base, comps) => {
                if comps.len() == 1 && self.is_place(base) {
                    let p = self.pointer(e, block).expect("is_place checked");
                    return self.append(E::Load { pointer: p }, s);
                }
                let v = self.expr(base, block);
                self.swizzle(v, comps, s)
            }
            ExprKind::Global(_) => {
                // Samplers are only used through texture builtins.
                let ty = self.m.ty(&e.ty);
                self.append_plain(E::ZeroValue(ty), s)
            }
            ExprKind::Field(base, idx) => {
                let b = self.expr(base, block);
                self.append(E::AccessIndex { base: b, index: *idx }, s)
            }
            ExprKind::Index(base, index) => {
                let b = self.expr(base, block);
                let constant = match index.kind {
                    ExprKind::Int(k) if k >= 0 => Some(k as u32),
                    ExprKind::Uint(k) => Some(k as u32),
                    _ => None,
                };
                if let Some(k) = constant {
                    return self.append(E::AccessIndex { base: b, index: k }, s);
                }
                let i = self.expr(index, block);
                if matches!(base.ty, Ty::Matrix(..)) {
                    // naga indexes a matrix value only by a constant: spill
                    // it to a local and index through the pointer.
                    let ty = self.m.ty(&base.ty);
                    let var = self.func.local_variables.append(naga::LocalVariable { name: None, ty, init: None }, span(s));
                    let ptr = self.append_plain(E::LocalVariable(var), s);
                    self.push(block, Statement::Store { pointer: ptr, value: b }, s);
                    let col = self.append(E::Access { base: ptr, index: i }, s);
                    return self.append(E::Load { pointer: col }, s);
                }
                self.append(E::Access { base: b, index: i }, s)
            }
            ExprKind::Unary(op, x) => {
                let v = self.expr(x, block);
                let op = match op {
                    UnaryOp::Neg => naga::UnaryOperator::Negate,
                    UnaryOp::Not => naga::UnaryOperator::LogicalNot,
                    UnaryOp::BitNot => naga::UnaryOperator::BitwiseNot,
                    _ => return v,
                };
                self.append(E::Unary { op, expr: v }, s)
            }
            ExprKind::Binary(op, lr) => {
                let (l, r) = &**lr;
                let lh = self.expr(l, block);
                let rh = self.expr(r, block);
                self.binary(*op, lh, &l.ty, rh, &r.ty, s)
            }
            ExprKind::Select { cond, accept, reject } => {
                let c = self.expr(cond, block);
                let a = self.expr(accept, block);
                let r = self.expr(reject, block);
                // naga's GLSL writer turns a vector-condition select into
                // `mix`, which GLSL 330 / ES 300 have only for floats: select
                // the components of int, uint and bool vectors one by one.
                if let (Flavor::Gl, Ty::Vector(_, n), Some(sc)) = (self.m.flavor, &cond.ty, e.ty.scalar()) {
                    if sc != Scalar::Float {
                        let parts: Vec<Handle<E>> = (0..*n as u32)
                            .map(|i| {
                                let ci = self.append(E::AccessIndex { base: c, index: i }, s);
                                let ai = self.append(E::AccessIndex { base: a, index: i }, s);
                                let ri = self.append(E::AccessIndex { base: r, index: i }, s);
                                self.append(E::Select { condition: ci, accept: ai, reject: ri }, s)
                            })
                            .collect();
                        let ty = self.m.ty(&e.ty);
                        return self.append(E::Compose { ty, components: parts }, s);
                    }
                }
                self.append(E::Select { condition: c, accept: a, reject: r }, s)
            }
            ExprKind::Call(fid, args) => {
                let (function, args) = self.call(*fid, args, block);
                let result = self.append_plain(E::CallResult(function), s);
                self.push(block, Statement::Call { function, arguments: args, result: Some(result) }, s);
                result
            }
            ExprKind::Builtin(b, args) => self.builtin(*b, args, &e.ty, s, block),
            ExprKind::Construct(args) => self.construct(&e.ty, args, s, block),
        }
    }

    fn is_place(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Local(id) => matches!(self.locals[*id], LocalSlot::Var(_)),
            ExprKind::Global(g) => match self.global_slot(*g) {
                Some(slot) => matches!(slot, LocalSlot::Var(_)),
                None => matches!(self.m.globals[*g], GlobalSlot::Var(_)),
            },
            ExprKind::Field(b, _) | ExprKind::Index(b, _) => self.is_place(b),
            ExprKind::Swizzle(b, c) => c.len() == 1 && self.is_place(b),
            _ => false,
        }
    }

    /// `l op r` with GLSL semantics on naga: scalars splatted where naga
    /// wants equal shapes, float `%` as GLSL `mod`, vector `==` reduced.
    pub fn binary(&mut self, op: BinaryOp, l: Handle<E>, lt: &Ty, r: Handle<E>, rt: &Ty, s: crate::source::Span) -> Handle<E> {
        use naga::BinaryOperator as Bo;
        let vec_ty = if matches!(lt, Ty::Vector(..)) { lt } else { rt };
        let (mut l, mut r) = (l, r);
        let needs_same_shape = !matches!(op, BinaryOp::Mul | BinaryOp::Shl | BinaryOp::Shr);
        if needs_same_shape || (op == BinaryOp::Mul && matches!((lt, rt), (Ty::Scalar(_), Ty::Scalar(_)))) {
            l = self.splat_to(l, lt, vec_ty, s);
            r = self.splat_to(r, rt, vec_ty, s);
        }
        let bo = match op {
            BinaryOp::Add => Bo::Add,
            BinaryOp::Sub => Bo::Subtract,
            BinaryOp::Mul => Bo::Multiply,
            BinaryOp::Div => Bo::Divide,
            BinaryOp::Mod => {
                if lt.scalar() == Some(Scalar::Float) {
                    // GLSL mod: x - y * floor(x / y).
                    let q = self.append(E::Binary { op: Bo::Divide, left: l, right: r }, s);
                    let f = self.append(E::Math { fun: naga::MathFunction::Floor, arg: q, arg1: None, arg2: None, arg3: None }, s);
                    let m = self.append(E::Binary { op: Bo::Multiply, left: r, right: f }, s);
                    return self.append(E::Binary { op: Bo::Subtract, left: l, right: m }, s);
                }
                if lt.scalar() == Some(Scalar::Int) && self.m.flavor == Flavor::Gl {
                    // GLSL leaves `%` with a negative operand undefined; the
                    // DSL's (and WGSL's) truncated remainder is
                    // x - y * (x / y) with division rounding toward zero.
                    let q = self.append(E::Binary { op: Bo::Divide, left: l, right: r }, s);
                    let m = self.append(E::Binary { op: Bo::Multiply, left: r, right: q }, s);
                    return self.append(E::Binary { op: Bo::Subtract, left: l, right: m }, s);
                }
                Bo::Modulo
            }
            BinaryOp::Eq | BinaryOp::Ne => {
                let bo = if op == BinaryOp::Eq { Bo::Equal } else { Bo::NotEqual };
                let c = self.append(E::Binary { op: bo, left: l, right: r }, s);
                if matches!(lt, Ty::Vector(..)) {
                    let fun = if op == BinaryOp::Eq { naga::RelationalFunction::All } else { naga::RelationalFunction::Any };
                    return self.append(E::Relational { fun, argument: c }, s);
                }
                return c;
            }
            BinaryOp::Lt => Bo::Less,
            BinaryOp::Le => Bo::LessEqual,
            BinaryOp::Gt => Bo::Greater,
            BinaryOp::Ge => Bo::GreaterEqual,
            BinaryOp::And => Bo::LogicalAnd,
            BinaryOp::Or => Bo::LogicalOr,
            BinaryOp::Xor => Bo::NotEqual,
            BinaryOp::BitAnd => Bo::And,
            BinaryOp::BitOr => Bo::InclusiveOr,
            BinaryOp::BitXor => Bo::ExclusiveOr,
            BinaryOp::Shl | BinaryOp::Shr => {
                // naga (like WGSL) wants an unsigned shift amount.
                if rt.scalar() == Some(Scalar::Int) {
                    r = self.append(E::As { expr: r, kind: naga::ScalarKind::Uint, convert: Some(4) }, s);
                }
                if op == BinaryOp::Shl {
                    Bo::ShiftLeft
                } else {
                    Bo::ShiftRight
                }
            }
        };
        self.append(E::Binary { op: bo, left: l, right: r }, s)
    }

    fn math(&mut self, fun: naga::MathFunction, args: &[Handle<E>], s: crate::source::Span) -> Handle<E> {
        self.append(E::Math { fun, arg: args[0], arg1: args.get(1).copied(), arg2: args.get(2).copied(), arg3: args.get(3).copied() }, s)
    }

    fn convert(&mut self, h: Handle<E>, from: &Ty, to: Scalar, s: crate::source::Span) -> Handle<E> {
        if from.scalar() == Some(to) {
            return h;
        }
        let width = if to == Scalar::Bool { 1 } else { 4 };
        self.append(E::As { expr: h, kind: naga_scalar(to).kind, convert: Some(width) }, s)
    }

    fn builtin(&mut self, b: Builtin, args: &[Expr], ret: &Ty, s: crate::source::Span, block: &mut Block) -> Handle<E> {
        use naga::MathFunction as Mf;
        if b.is_texture() {
            return self.texture(b, args, ret, s, block);
        }
        let mut hs: Vec<Handle<E>> = args.iter().map(|a| self.expr(a, block)).collect();
        match b {
            Builtin::Math(fun) => {
                // Scalars of a vector call are broadcast (min(v, 0.0), mix(a, b, t), step(0.5, v)).
                if matches!(ret, Ty::Vector(..)) && !matches!(fun, Mf::Cross | Mf::Refract) {
                    for (h, a) in hs.iter_mut().zip(args) {
                        *h = self.splat_to(*h, &a.ty, ret, s);
                    }
                }
                self.math(fun, &hs, s)
            }
            Builtin::Saturate => self.math(Mf::Saturate, &hs, s),
            Builtin::Rcp => {
                let one = self.literal(naga::Literal::F32(1.0), s);
                let one = self.splat_to(one, &Ty::Scalar(Scalar::Float), ret, s);
                self.append(E::Binary { op: naga::BinaryOperator::Divide, left: one, right: hs[0] }, s)
            }
            Builtin::Mod => self.binary(BinaryOp::Mod, hs[0], &args[0].ty, hs[1], &args[1].ty, s),
            Builtin::Any => self.append(E::Relational { fun: naga::RelationalFunction::Any, argument: hs[0] }, s),
            Builtin::All => self.append(E::Relational { fun: naga::RelationalFunction::All, argument: hs[0] }, s),
            Builtin::Not => self.append(E::Unary { op: naga::UnaryOperator::LogicalNot, expr: hs[0] }, s),
            Builtin::Compare(op) => {
                use naga::BinaryOperator as Bo;
                let bo = match op {
                    BinaryOp::Lt => Bo::Less,
                    BinaryOp::Le => Bo::LessEqual,
                    BinaryOp::Gt => Bo::Greater,
                    BinaryOp::Ge => Bo::GreaterEqual,
                    BinaryOp::Eq => Bo::Equal,
                    _ => Bo::NotEqual,
                };
                self.append(E::Binary { op: bo, left: hs[0], right: hs[1] }, s)
            }
            Builtin::Derivative(axis, ctrl) => self.append(E::Derivative { axis, ctrl, expr: hs[0] }, s),
            Builtin::Bitcast(to) => self.append(E::As { expr: hs[0], kind: naga_scalar(to).kind, convert: None }, s),
            Builtin::Inverse => {
                let Ty::Matrix(n, _) = *ret else { unreachable!("sema checks that `inverse` takes a square matrix") };
                let function = super::inverse::function(self.m, n);
                let result = self.append_plain(E::CallResult(function), s);
                self.push(block, Statement::Call { function, arguments: vec![hs[0]], result: Some(result) }, s);
                result
            }
            _ => unreachable!("texture builtins handled above"),
        }
    }

    fn texture(&mut self, b: Builtin, args: &[Expr], ret: &Ty, s: crate::source::Span, block: &mut Block) -> Handle<E> {
        // The sampler global, and the element when known here.
        let (g, constant, index) = match self.sampler_of(&args[0]) {
            Some(Ok(r)) => (r.global, Some(r.elem), None),
            Some(Err((g, i))) => (g, None, Some(i)),
            None => unreachable!("sema checks the sampler argument"),
        };
        let GlobalSlot::Sampler { first, count } = self.m.globals[g] else { unreachable!("sema checks the sampler argument") };
        let GlobalKind::Sampler { kind, .. } = self.m.p.globals[g].kind else { unreachable!("sema checks the sampler argument") };
        // An `...Offset` call: the call it offsets, with the offset (a
        // constant, checked by sema) as a const-expression as naga wants.
        let (b, offset_at) = b.split_offset();
        let rest: Vec<Handle<E>> = args.iter().enumerate().skip(1).filter(|(i, _)| Some(*i) != offset_at).map(|(_, a)| self.expr(a, block)).collect();
        let offset = offset_at.map(|at| self.texel_offset(&args[at], s));
        let op = self.texture_op(b, kind, &rest, offset, args, s);
        if let Some(k) = constant {
            let (image, sampler) = self.m.sampler_elems[first + k.min(count - 1) as usize];
            return self.texture_apply(&op, kind, image, sampler, ret, s);
        }
        // A dynamic index into an array of samplers: a switch over the
        // elements (each a separate global), the index clamped like every
        // other array index.
        let index = index.expect("a dynamic index");
        let mut i = self.expr(index, block);
        i = self.convert(i, &index.ty, Scalar::Int, s);
        let lo = self.literal(naga::Literal::I32(0), s);
        let hi = self.literal(naga::Literal::I32(count as i32 - 1), s);
        let i = self.math(naga::MathFunction::Clamp, &[i, lo, hi], s);
        let ty = self.m.ty(ret);
        let var = self.func.local_variables.append(naga::LocalVariable { name: Some("texel".into()), ty, init: None }, span(s));
        self.flush(block);
        let mut cases = Vec::new();
        for k in 0..count {
            let mut body = Block::with_capacity(2);
            let (image, sampler) = self.m.sampler_elems[first + k as usize];
            let v = self.texture_apply(&op, kind, image, sampler, ret, s);
            let ptr = self.append_plain(E::LocalVariable(var), s);
            self.push(&mut body, Statement::Store { pointer: ptr, value: v }, s);
            let value = if k + 1 == count { naga::SwitchValue::Default } else { naga::SwitchValue::I32(k as i32) };
            cases.push(naga::SwitchCase { value, body, fall_through: false });
        }
        self.push(block, Statement::Switch { selector: i, cases }, s);
        let ptr = self.append_plain(E::LocalVariable(var), s);
        self.append(E::Load { pointer: ptr }, s)
    }

    /// A texel offset as the const-expression naga wants: a vector of
    /// literals (sema checked that `e` is a constant in range).
    fn texel_offset(&mut self, e: &Expr, s: crate::source::Span) -> Handle<E> {
        let ks = e.const_ints(&self.m.p.consts).expect("sema checks that a texel offset is constant");
        let components: Vec<Handle<E>> = ks.iter().map(|&k| self.literal(naga::Literal::I32(k as i32), s)).collect();
        let ty = self.m.ty(&e.ty);
        self.append(E::Compose { ty, components }, s)
    }

    /// The image-independent part of a texture call: coordinates, level,
    /// reference depth, texel offset.
    fn texture_op(&mut self, b: Builtin, kind: crate::lower::SamplerKind, rest: &[Handle<E>], offset: Option<Handle<E>>, args: &[Expr], s: crate::source::Span) -> TexOp {
        let f32s = Ty::Scalar(Scalar::Float);
        match b {
            Builtin::Texture | Builtin::TextureLod | Builtin::TextureCompare | Builtin::TextureProj | Builtin::TextureGrad => {
                let (coordinate, array_index, depth_ref) = if b == Builtin::TextureProj {
                    let v = rest[0];
                    let n = args[1].ty.width().unwrap_or(4);
                    let q = self.append(E::AccessIndex { base: v, index: n as u32 - 1 }, s);
                    let xy = self.swizzle(v, &[0, 1], s);
                    let q2 = self.append(E::Splat { size: naga::VectorSize::Bi, value: q }, s);
                    let uv = self.append(E::Binary { op: naga::BinaryOperator::Divide, left: xy, right: q2 }, s);
                    let dref = if kind.is_shadow() {
                        let z = self.append(E::AccessIndex { base: v, index: 2 }, s);
                        Some(self.append(E::Binary { op: naga::BinaryOperator::Divide, left: z, right: q }, s))
                    } else {
                        None
                    };
                    (uv, None, dref)
                } else if kind.is_array() {
                    // Split an array coordinate into uv and a rounded integer layer.
                    let coord = rest[0];
                    let uv = self.swizzle(coord, &[0, 1], s);
                    let layer = self.append(E::AccessIndex { base: coord, index: 2 }, s);
                    let layer = self.math(naga::MathFunction::Round, &[layer], s);
                    let layer = self.convert(layer, &f32s, Scalar::Int, s);
                    (uv, Some(layer), (b == Builtin::TextureCompare).then(|| rest[1]))
                } else {
                    (rest[0], None, (b == Builtin::TextureCompare).then(|| rest[1]))
                };
                let level = match b {
                    Builtin::TextureLod => naga::SampleLevel::Exact(rest[1]),
                    Builtin::TextureGrad => naga::SampleLevel::Gradient { x: rest[1], y: rest[2] },
                    // No implicit derivatives outside fragment shaders: the
                    // base level, plus the bias if one is given.
                    Builtin::Texture if rest.len() == 2 && self.vertex_lod => naga::SampleLevel::Exact(rest[1]),
                    Builtin::Texture if rest.len() == 2 => naga::SampleLevel::Bias(rest[1]),
                    _ if self.vertex_lod => naga::SampleLevel::Zero,
                    _ => naga::SampleLevel::Auto,
                };
                TexOp::Sample { coordinate, array_index, depth_ref, level, offset }
            }
            Builtin::TexelFetch => {
                let (coordinate, array_index) = if kind.is_array() {
                    let c = rest[0];
                    let xy = self.swizzle(c, &[0, 1], s);
                    (xy, Some(self.append(E::AccessIndex { base: c, index: 2 }, s)))
                } else {
                    (rest[0], None)
                };
                // Loads take no offset in WGSL: the texel `offset` away is
                // the one at coordinate + offset, which is what GLSL's
                // texelFetchOffset reads.
                let coordinate = match offset {
                    Some(o) => self.append(E::Binary { op: naga::BinaryOperator::Add, left: coordinate, right: o }, s),
                    None => coordinate,
                };
                TexOp::Load { coordinate, array_index, level: rest[1] }
            }
            _ => TexOp::Size { level: rest[0] },
        }
    }

    /// A texture operation on one image/sampler pair.
    fn texture_apply(
        &mut self,
        op: &TexOp,
        kind: crate::lower::SamplerKind,
        image: Handle<naga::GlobalVariable>,
        sampler: Handle<naga::GlobalVariable>,
        ret: &Ty,
        s: crate::source::Span,
    ) -> Handle<E> {
        let img = self.append_plain(E::GlobalVariable(image), s);
        match op {
            TexOp::Sample { coordinate, array_index, depth_ref, level, offset } => {
                let smp = self.append_plain(E::GlobalVariable(sampler), s);
                let e = E::ImageSample {
                    image: img,
                    sampler: smp,
                    gather: None,
                    coordinate: *coordinate,
                    array_index: *array_index,
                    offset: *offset,
                    level: *level,
                    depth_ref: *depth_ref,
                    clamp_to_edge: false,
                };
                self.append(e, s)
            }
            TexOp::Load { coordinate, array_index, level } => {
                self.append(E::ImageLoad { image: img, coordinate: *coordinate, array_index: *array_index, sample: None, level: Some(*level) }, s)
            }
            TexOp::Size { level } => {
                let size = self.append(E::ImageQuery { image: img, query: naga::ImageQuery::Size { level: Some(*level) } }, s);
                let dims = if kind.dim() == naga::ImageDimension::D3 { 3 } else { 2 };
                let size = self.convert(size, &Ty::Vector(Scalar::Uint, dims), Scalar::Int, s);
                if kind.is_array() {
                    let layers = self.append(E::ImageQuery { image: img, query: naga::ImageQuery::NumLayers }, s);
                    let layers = self.convert(layers, &Ty::Scalar(Scalar::Uint), Scalar::Int, s);
                    let ty = self.m.ty(ret);
                    return self.append(E::Compose { ty, components: vec![size, layers] }, s);
                }
                size
            }
        }
    }

    fn construct(&mut self, ty: &Ty, args: &[Expr], s: crate::source::Span, block: &mut Block) -> Handle<E> {
        let hs: Vec<Handle<E>> = args.iter().map(|a| self.expr(a, block)).collect();
        match ty {
            Ty::Scalar(to) => self.convert(hs[0], &args[0].ty, *to, s),
            Ty::Vector(to, n) => {
                if hs.len() == 1 {
                    let v = self.convert(hs[0], &args[0].ty, *to, s);
                    return match args[0].ty {
                        Ty::Scalar(_) => self.append(E::Splat { size: vector_size(*n), value: v }, s),
                        Ty::Vector(_, m) if m > *n => {
                            let comps: Vec<u8> = (0..*n).collect();
                            self.swizzle(v, &comps, s)
                        }
                        _ => v,
                    };
                }
                let comps: Vec<Handle<E>> = hs.iter().zip(args).map(|(h, a)| self.convert(*h, &a.ty, *to, s)).collect();
                let t = self.m.ty(ty);
                self.append(E::Compose { ty: t, components: comps }, s)
            }
            Ty::Matrix(c, r) => {
                let t = self.m.ty(ty);
                if hs.len() == 1 && args[0].ty == *ty {
                    return hs[0];
                }
                let col_ty = self.m.ty(&Ty::Vector(Scalar::Float, *r));
                let cols: Vec<Handle<E>> = if hs.len() == *c as usize && matches!(args[0].ty, Ty::Vector(..)) {
                    hs
                } else if hs.len() == 1 {
                    // A diagonal matrix.
                    let zero = self.literal(naga::Literal::F32(0.0), s);
                    (0..*c)
                        .map(|i| {
                            let comps = (0..*r).map(|j| if i == j { hs[0] } else { zero }).collect();
                            self.append(E::Compose { ty: col_ty, components: comps }, s)
                        })
                        .collect()
                } else {
                    hs.chunks(*r as usize).map(|col| self.append(E::Compose { ty: col_ty, components: col.to_vec() }, s)).collect()
                };
                self.append(E::Compose { ty: t, components: cols }, s)
            }
            _ => {
                let t = self.m.ty(ty);
                self.append(E::Compose { ty: t, components: hs }, s)
            }
        }
    }
}

/// Whether an interface global is read (an input) in this stage.
pub fn is_stage_input(kind: &GlobalKind, stage: naga::ShaderStage) -> bool {
    match kind {
        GlobalKind::Io { kind: IoKind::In, .. } => true,
        GlobalKind::Io { kind: IoKind::InOut, .. } => stage == naga::ShaderStage::Fragment,
        GlobalKind::Builtin(b) => !b.is_output(),
        _ => false,
    }
}

/// Whether an interface global is written (an output) in this stage.
pub fn is_stage_output(kind: &GlobalKind, stage: naga::ShaderStage) -> bool {
    match kind {
        GlobalKind::Io { kind: IoKind::Out, .. } => true,
        GlobalKind::Io { kind: IoKind::InOut, .. } => stage == naga::ShaderStage::Vertex,
        GlobalKind::Builtin(b) => b.is_output(),
        _ => false,
    }
}
