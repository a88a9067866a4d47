//! The function builder: what every function body is lowered with.
//!
//! Expressions that naga wants covered by `Statement::Emit` are appended
//! while the emitter runs; the others (literals, constants, variables,
//! arguments, call results) are appended with the emitter paused. Every
//! statement push flushes the pending range first. Statements are lowered
//! in `stmts`, expressions in `exprs`, builtin calls in `builtins` and
//! `textures`, an entry point's inputs and outputs in `entry`.

use naga::{Block, Expression as E, Handle, Statement};

use super::module::{ModuleBuilder, SamplerRef};
use super::types::{naga_scalar, vector_size};
use crate::sema::{self, BuiltinVar, Scalar, Stmt, Ty};
use crate::source::Span;

/// How a sema local lives in naga.
#[derive(Clone, Copy)]
pub(super) enum LocalSlot {
    /// A `var`, loop counter or parameter copy: a function-local variable.
    Var(Handle<naga::LocalVariable>),
    /// A `let` or an unmodified parameter: an expression.
    Value(Handle<E>),
    /// A `var p : T&` parameter: the argument, a pointer to the caller's
    /// variable (GLSL `inout`), read and written through.
    Ptr(Handle<E>),
    /// A sampler parameter: the sampler this specialisation was made for.
    Sampler(SamplerRef),
    Unset,
}

/// What a `return` does in this function.
pub(super) enum FnKind {
    Helper,
    /// An entry point: `return` builds the output struct from its outputs.
    Entry(EntryOutputs),
}

/// The entry point's outputs, in result-struct member order.
pub(super) struct EntryOutputs {
    pub(super) result_ty: Option<Handle<naga::Type>>,
    /// The output global of each member, read where it lives (a local
    /// variable of the entry function or a private global). `None` for an
    /// output the shader never writes (gl_Position of a vertex shader that
    /// ignores it): zero.
    pub(super) members: Vec<(Option<sema::GlobalId>, Option<BuiltinVar>, Handle<naga::Type>)>,
    pub(super) stage: naga::ShaderStage,
    pub(super) dialect: crate::syntax::ast::Dialect,
    /// A mesh entry point's outputs (`lower::mesh`).
    pub(super) mesh: Option<super::mesh::MeshOut>,
}

pub(super) struct FnBuilder<'m, 'p> {
    pub(super) m: &'m mut ModuleBuilder<'p>,
    pub(super) func: naga::Function,
    pub(super) emitter: naga::proc::Emitter,
    pub(super) locals: Vec<LocalSlot>,
    pub(super) sema_locals: &'p [sema::Local],
    pub(super) kind: FnKind,
    /// Emit ranges closed by `append_plain`, waiting for the next statement.
    pub(super) pending: Vec<(Statement, naga::Span)>,
    /// Implicit-LOD sampling samples level 0 (vertex entry points and the
    /// helpers lowered for them): naga, WGSL and SPIR-V allow implicit LOD
    /// only in fragment shaders.
    pub(super) vertex_lod: bool,
    /// Per sema global, in an entry point: an input held as its argument
    /// (`Value`) or an output held in a local variable (`Var`) instead of
    /// the module's private global. Empty in helpers.
    pub(super) entry_globals: Vec<LocalSlot>,
    /// The expressions naga never emits (literals, constants, variables'
    /// pointers, zero values), one of each per function: naga may use them
    /// anywhere in it, so a second use takes the first's handle instead of
    /// a new expression (and a new split of the running emit range).
    plain: rustc_hash::FxHashMap<PlainKey, Handle<E>>,
}

/// What identifies an expression [`FnBuilder::append_plain`] shares.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum PlainKey {
    /// A literal: its kind and its bits (`-0.0` and `0.0` differ).
    Literal(u8, u64),
    Constant(Handle<naga::Constant>),
    /// A specialization constant of the GPU module.
    Override(Handle<naga::Override>),
    Global(Handle<naga::GlobalVariable>),
    Local(Handle<naga::LocalVariable>),
    Zero(Handle<naga::Type>),
}

impl PlainKey {
    fn of(e: &E) -> Option<PlainKey> {
        use naga::Literal as L;
        Some(match *e {
            E::Literal(l) => match l {
                L::F64(v) => PlainKey::Literal(0, v.to_bits()),
                L::F32(v) => PlainKey::Literal(1, v.to_bits() as u64),
                L::U32(v) => PlainKey::Literal(2, v as u64),
                L::I32(v) => PlainKey::Literal(3, v as u32 as u64),
                L::U64(v) => PlainKey::Literal(4, v),
                L::I64(v) => PlainKey::Literal(5, v as u64),
                L::Bool(v) => PlainKey::Literal(6, v as u64),
                L::F16(v) => PlainKey::Literal(7, v.to_bits() as u64),
                L::AbstractInt(v) => PlainKey::Literal(8, v as u64),
                L::AbstractFloat(v) => PlainKey::Literal(9, v.to_bits()),
                L::U16(v) => PlainKey::Literal(10, v as u64),
                L::I16(v) => PlainKey::Literal(11, v as u16 as u64),
            },
            E::Constant(h) => PlainKey::Constant(h),
            E::Override(h) => PlainKey::Override(h),
            E::GlobalVariable(h) => PlainKey::Global(h),
            E::LocalVariable(h) => PlainKey::Local(h),
            E::ZeroValue(h) => PlainKey::Zero(h),
            _ => return None,
        })
    }
}

pub(super) fn span(s: Span) -> naga::Span {
    s.into()
}

/// An empty block with room for what `n` checked statements usually
/// become (a statement each, after one or two emit ranges: every plain
/// expression splits a range), so pushing rarely grows its two vectors.
pub(super) fn block_for(n: usize) -> Block {
    match n {
        0 => Block::new(),
        _ => Block::with_capacity(3 * n + 2),
    }
}

/// A block of one `break`.
pub(super) fn break_block(s: Span) -> Block {
    let mut b = Block::with_capacity(1);
    b.push(Statement::Break, span(s));
    b
}


impl<'m, 'p> FnBuilder<'m, 'p> {
    pub(super) fn new(m: &'m mut ModuleBuilder<'p>, name: &str, sema_locals: &'p [sema::Local], kind: FnKind) -> Self {
        let mut func = naga::Function { name: Some(name.to_string()), ..Default::default() };
        // A `let` names its expression: room for all of them up front.
        func.named_expressions.reserve(sema_locals.iter().filter(|l| !l.mutable).count());
        let mut b = FnBuilder { m, func, emitter: Default::default(), locals: vec![LocalSlot::Unset; sema_locals.len()], sema_locals, kind, pending: Vec::new(), vertex_lod: false, entry_globals: Vec::new(), plain: Default::default() };
        b.emitter.start(&b.func.expressions);
        b
    }

    /// Declares parameter `i` as a function argument. An immutable
    /// parameter's argument expression serves directly; a `var` one is
    /// copied into a local variable at the start (`prologue`); a `var p :
    /// T&` one is a pointer argument. A sampler parameter is no argument:
    /// it stands for `sampler`, the one this copy of the function is
    /// specialised for.
    pub(super) fn add_param(&mut self, i: usize, sampler: Option<SamplerRef>, prologue: &mut Block) {
        let l = &self.sema_locals[i];
        if let Some(r) = sampler {
            self.locals[i] = LocalSlot::Sampler(r);
            return;
        }
        let value_ty = self.m.ty(&l.ty);
        let ty = match l.by_ref {
            true => self.m.add_type(None, naga::TypeInner::Pointer { base: value_ty, space: naga::AddressSpace::Function }),
            false => value_ty,
        };
        let idx = self.func.arguments.len() as u32;
        self.func.arguments.push(naga::FunctionArgument { name: Some(local_name(l.name.as_str())), ty, binding: None });
        let h = self.append_plain(E::FunctionArgument(idx), l.span);
        self.locals[i] = match (l.by_ref, l.mutable) {
            (true, _) => LocalSlot::Ptr(h),
            (false, false) => LocalSlot::Value(h),
            (false, true) => {
                // A mutable copy: the argument is its initial value.
                let var = self.func.local_variables.append(naga::LocalVariable { name: Some(local_name(l.name.as_str())), ty: value_ty, init: None }, span(l.span));
                let ptr = self.append_plain(E::LocalVariable(var), l.span);
                self.push(prologue, Statement::Store { pointer: ptr, value: h }, l.span);
                LocalSlot::Var(var)
            }
        };
    }

    /// Appends an expression that must not be emitted.
    pub(super) fn append_plain(&mut self, e: E, s: Span) -> Handle<E> {
        let key = PlainKey::of(&e);
        if let Some(&h) = key.as_ref().and_then(|k| self.plain.get(k)) {
            return h;
        }
        // Close the running range, append outside it, and start again.
        let pending = self.emitter.finish(&self.func.expressions);
        let h = self.func.expressions.append(e, span(s));
        self.emitter.start(&self.func.expressions);
        if let Some((stmt, sp)) = pending {
            // The range ends before `h`; it is pushed with the next statement.
            self.pending.push((stmt, sp));
        }
        if let Some(k) = key {
            self.plain.insert(k, h);
        }
        h
    }

    /// Appends an expression that must be emitted.
    pub(super) fn append(&mut self, e: E, s: Span) -> Handle<E> {
        self.func.expressions.append(e, span(s))
    }

    /// Pushes a statement after flushing pending emit ranges.
    pub(super) fn push(&mut self, block: &mut Block, stmt: Statement, s: Span) {
        self.flush(block);
        block.push(stmt, span(s));
    }

    pub(super) fn flush(&mut self, block: &mut Block) {
        for (stmt, sp) in self.pending.drain(..) {
            block.push(stmt, sp);
        }
        if let Some((stmt, sp)) = self.emitter.finish(&self.func.expressions) {
            block.push(stmt, sp);
        }
        self.emitter.start(&self.func.expressions);
    }

    pub(super) fn finish(mut self, mut body: Block, ret: Option<naga::FunctionResult>) -> naga::Function {
        self.flush(&mut body);
        let _ = self.emitter.finish(&self.func.expressions);
        self.func.body = body;
        self.func.result = ret;
        self.func
    }

    pub(super) fn block(&mut self, stmts: &[Stmt]) -> Block {
        let mut b = block_for(stmts.len());
        for s in live(stmts) {
            self.stmt(s, &mut b);
        }
        self.flush(&mut b);
        b
    }

    /// Lowers statements onto the end of `block`.
    pub(super) fn stmts_into(&mut self, stmts: &[Stmt], block: &mut Block) {
        for s in live(stmts) {
            self.stmt(s, block);
        }
        self.flush(block);
    }

    pub(super) fn literal(&mut self, l: naga::Literal, s: Span) -> Handle<E> {
        self.append_plain(E::Literal(l), s)
    }

    /// Broadcasts a scalar to the vector shape of `to` (no-op otherwise).
    pub(super) fn splat_to(&mut self, h: Handle<E>, from: &Ty, to: &Ty, s: Span) -> Handle<E> {
        match (from, to) {
            (Ty::Scalar(_), Ty::Vector(_, n)) => self.append(E::Splat { size: vector_size(*n), value: h }, s),
            _ => h,
        }
    }

    pub(super) fn swizzle(&mut self, v: Handle<E>, comps: &[u8], s: Span) -> Handle<E> {
        if comps.len() == 1 {
            return self.append(E::AccessIndex { base: v, index: comps[0] as u32 }, s);
        }
        let mut pattern = [naga::SwizzleComponent::X; 4];
        for (i, &c) in comps.iter().enumerate() {
            pattern[i] = naga::SwizzleComponent::XYZW[c as usize];
        }
        self.append(E::Swizzle { size: vector_size(comps.len() as u8), vector: v, pattern }, s)
    }

    pub(super) fn math(&mut self, fun: naga::MathFunction, args: &[Handle<E>], s: Span) -> Handle<E> {
        self.append(E::Math { fun, arg: args[0], arg1: args.get(1).copied(), arg2: args.get(2).copied(), arg3: args.get(3).copied() }, s)
    }

    pub(super) fn convert(&mut self, h: Handle<E>, from: &Ty, to: Scalar, s: Span) -> Handle<E> {
        // An enumeration value is its storage scalar.
        let from_scalar = match from {
            Ty::Enum(id) => Some(self.m.p.enums[*id as usize].base),
            _ => from.scalar(),
        };
        if from_scalar == Some(to) {
            return h;
        }
        let width = match to {
            Scalar::Bool => 1,
            Scalar::Half => super::types::half_scalar(self.m.flavor).width,
            _ => 4,
        };
        self.append(E::As { expr: h, kind: naga_scalar(to).kind, convert: Some(width) }, s)
    }
}

/// The statements of a block up to its first `return`, `break` or
/// `continue`: what follows is never run, and is not lowered. (Code after
/// an entry point's `return` made naga's GLSL writer declare its
/// `_tmp_return` twice in one scope, which glslang refuses.) What follows
/// a `discard()` is kept: WGSL's `discard` does not end the function (the
/// invocation goes on as a helper), so a `return v` after it is what makes
/// the function return a value for tint and glslang.
pub(super) fn live(stmts: &[Stmt]) -> &[Stmt] {
    match stmts.iter().position(|s| matches!(s, Stmt::Return(..) | Stmt::Break(_) | Stmt::Continue(_))) {
        Some(i) => &stmts[..=i],
        None => stmts,
    }
}

/// Whether control can reach the end of `block` without a `return`, as
/// WGSL's behaviour analysis sees it (a `discard` does not end a path):
/// a function with a result must not, for tint and glslang.
pub(super) fn falls_through(block: &Block) -> bool {
    match block.last() {
        Some(Statement::Return { .. }) => false,
        Some(Statement::Block(b)) => falls_through(b),
        Some(Statement::If { accept, reject, .. }) => falls_through(accept) || falls_through(reject),
        _ => true,
    }
}

/// The IR name of a parameter or local: its source name, with `l` in front
/// of one that starts as the names naga's writers make up for themselves
/// (`_tmp_return`, `_e12`, `_group_0_binding_1_fs`, `const_...`,
/// `naga_modf`), which their namers do not keep clear of (glslang: a local
/// `_tmp_return` is a redefinition). Locals are named in no interface.
pub(super) fn local_name(name: &str) -> String {
    if name.starts_with('_') || name.starts_with("const_") || name.starts_with("naga_") {
        ["l", name].concat()
    } else {
        name.to_owned()
    }
}
