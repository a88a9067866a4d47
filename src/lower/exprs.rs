//! Expressions: places (pointers to variables, fields, elements),
//! operators with GLSL's semantics, selects and constructors.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::{span, FnBuilder, LocalSlot};
use super::interface::Flavor;
use super::module::GlobalSlot;
use super::types::vector_size;
use crate::sema::{self, Expr, ExprKind, Scalar, Ty};
use crate::source::Span;
use crate::syntax::ast::{BinaryOp, UnaryOp};

impl FnBuilder<'_, '_> {
    /// A pointer to a place (variable, field, element, one component), if
    /// `e` is one.
    pub(super) fn pointer(&mut self, e: &Expr, block: &mut Block) -> Option<Handle<E>> {
        match &e.kind {
            ExprKind::Local(id) => match self.locals[*id] {
                LocalSlot::Var(v) => Some(self.append_plain(E::LocalVariable(v), e.span)),
                LocalSlot::Ptr(p) => Some(p),
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
    pub(super) fn global_slot(&self, g: sema::GlobalId) -> Option<LocalSlot> {
        match self.entry_globals.get(g) {
            Some(LocalSlot::Unset) | None => None,
            slot => slot.copied(),
        }
    }

    /// A pointer to global `g`, unless it is a held value or a sampler.
    pub(super) fn global_pointer(&mut self, g: sema::GlobalId, s: Span) -> Option<Handle<E>> {
        match self.global_slot(g) {
            Some(LocalSlot::Var(v)) => Some(self.append_plain(E::LocalVariable(v), s)),
            Some(_) => None,
            None => match self.m.globals[g] {
                GlobalSlot::Var(h) => Some(self.append_plain(E::GlobalVariable(h), s)),
                GlobalSlot::Sampler { .. } | GlobalSlot::Image(_) | GlobalSlot::Packed { .. } | GlobalSlot::Override(_) | GlobalSlot::Const(_) | GlobalSlot::Absent => None,
            },
        }
    }

    pub(super) fn expr(&mut self, e: &Expr, block: &mut Block) -> Handle<E> {
        let s = e.span;
        // An input the entry point holds as its argument.
        if let ExprKind::Global(g) = e.kind {
            if let Some(LocalSlot::Value(h)) = self.global_slot(g) {
                return h;
            }
        }
        // A specialization constant.
        if let ExprKind::Global(g) = e.kind {
            match self.m.globals[g] {
                GlobalSlot::Override(h) => return self.append_plain(E::Override(h), s),
                GlobalSlot::Const(h) => return self.append_plain(E::Constant(h), s),
                _ => {}
            }
        }
        // A loose uniform, or a part of one, in a uniform buffer.
        if let Some(v) = self.uniform_buffer_value(e, block) {
            return v;
        }
        match &e.kind {
            ExprKind::Float(v) => {
                let l = self.m.float_literal(*v, e.ty.scalar().unwrap_or(Scalar::Float));
                self.literal(l, s)
            }
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
                LocalSlot::Ptr(p) => self.append(E::Load { pointer: p }, s),
                LocalSlot::Unset => {
                    let ty = self.m.ty(&e.ty);
                    self.append_plain(E::ZeroValue(ty), s)
                }
                LocalSlot::Sampler(_) => unreachable!("sema allows a sampler only where a sampler is taken"),
            },
            ExprKind::Global(_) | ExprKind::Field(..) | ExprKind::Index(..) if self.is_place(e) => {
                let p = self.pointer(e, block).expect("is_place checked");
                if self.is_gl_uniform_block(e) {
                    return self.load_block_members(p, &e.ty, s);
                }
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
            ExprKind::Unary(UnaryOp::Neg, x) if matches!(x.ty, Ty::Matrix(..)) => {
                // naga negates scalars and vectors: a matrix column by column.
                let Ty::Matrix(c, _) = x.ty else { unreachable!("matched a matrix") };
                let v = self.expr(x, block);
                let cols = (0..c as u32)
                    .map(|i| {
                        let col = self.append(E::AccessIndex { base: v, index: i }, s);
                        self.append(E::Unary { op: naga::UnaryOperator::Negate, expr: col }, s)
                    })
                    .collect();
                let ty = self.m.ty(&e.ty);
                self.append(E::Compose { ty, components: cols }, s)
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
                let (function, args, write_back) = self.call(*fid, args, block);
                let result = self.append_plain(E::CallResult(function), s);
                self.push(block, Statement::Call { function, arguments: args, result: Some(result) }, s);
                self.write_back(write_back, block, s);
                result
            }
            ExprKind::Builtin(b, args) => self.builtin(*b, args, &e.ty, s, block),
            ExprKind::Construct(args) => self.construct(&e.ty, args, s, block),
            ExprKind::Zero => {
                let ty = self.m.ty(&e.ty);
                self.append_plain(E::ZeroValue(ty), s)
            }
        }
    }

    /// Whether `e` is a whole struct uniform of a GL module. GLSL declares
    /// it as a block with an instance name (`emit::glsl`), which is no
    /// value: it is read member by member.
    fn is_gl_uniform_block(&self, e: &Expr) -> bool {
        let ExprKind::Global(g) = e.kind else { return false };
        if self.m.flavor != Flavor::Gl || !matches!(e.ty, Ty::Struct(_)) || self.global_slot(g).is_some() {
            return false;
        }
        matches!(self.m.globals[g], GlobalSlot::Var(h) if self.m.module.global_variables[h].space == naga::AddressSpace::Uniform)
    }

    /// The struct at `ptr` composed from a load of each member.
    fn load_block_members(&mut self, ptr: Handle<E>, ty: &Ty, s: Span) -> Handle<E> {
        let Ty::Struct(id) = *ty else { unreachable!("checked by is_gl_uniform_block") };
        let count = self.m.p.structs[id].fields.len() as u32;
        let members = (0..count)
            .map(|i| {
                let member = self.append(E::AccessIndex { base: ptr, index: i }, s);
                self.append(E::Load { pointer: member }, s)
            })
            .collect();
        let t = self.m.ty(ty);
        self.append(E::Compose { ty: t, components: members }, s)
    }

    pub(super) fn is_place(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Local(id) => matches!(self.locals[*id], LocalSlot::Var(_) | LocalSlot::Ptr(_)),
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
    pub(super) fn binary(&mut self, op: BinaryOp, l: Handle<E>, lt: &Ty, r: Handle<E>, rt: &Ty, s: Span) -> Handle<E> {
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
                // ... as wide as the value shifted (`v << 2` shifts every component).
                r = self.splat_to(r, rt, lt, s);
                if op == BinaryOp::Shl {
                    Bo::ShiftLeft
                } else {
                    Bo::ShiftRight
                }
            }
        };
        self.append(E::Binary { op: bo, left: l, right: r }, s)
    }

    pub(super) fn construct(&mut self, ty: &Ty, args: &[Expr], s: Span, block: &mut Block) -> Handle<E> {
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
                let mut comps: Vec<Handle<E>> = hs.iter().zip(args).map(|(h, a)| self.convert(*h, &a.ty, *to, s)).collect();
                if comps.iter().all(|&h| !self.is_emitted(h)) {
                    comps = self.flatten_constant_vectors(comps, *to, s);
                }
                let t = self.m.ty(ty);
                self.append(E::Compose { ty: t, components: comps }, s)
            }
            Ty::Matrix(c, r) => {
                let t = self.m.ty(ty);
                if hs.len() == 1 && args[0].ty == *ty {
                    return hs[0];
                }
                if let (1, Ty::Matrix(from_c, from_r)) = (hs.len(), &args[0].ty) {
                    return self.matrix_from_matrix(hs[0], (*from_c, *from_r), (*c, *r), s);
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

    /// A `to_c` x `to_r` matrix from a `from_c` x `from_r` one, as GLSL
    /// defines it: element (column i, row j) comes from the argument where
    /// it has one, from the identity elsewhere.
    fn matrix_from_matrix(&mut self, m: Handle<E>, (from_c, from_r): (u8, u8), (to_c, to_r): (u8, u8), s: Span) -> Handle<E> {
        let col_ty = self.m.ty(&Ty::Vector(Scalar::Float, to_r));
        let (zero, one) = (self.literal(naga::Literal::F32(0.0), s), self.literal(naga::Literal::F32(1.0), s));
        let mut cols = Vec::with_capacity(to_c as usize);
        for i in 0..to_c {
            let col = if i < from_c {
                let src = self.append(E::AccessIndex { base: m, index: i as u32 }, s);
                if from_r == to_r {
                    src
                } else if from_r > to_r {
                    let comps: Vec<u8> = (0..to_r).collect();
                    self.swizzle(src, &comps, s)
                } else {
                    let mut parts: Vec<Handle<E>> = (0..from_r).map(|j| self.append(E::AccessIndex { base: src, index: j as u32 }, s)).collect();
                    parts.extend((from_r..to_r).map(|j| if i == j { one } else { zero }));
                    self.append(E::Compose { ty: col_ty, components: parts }, s)
                }
            } else {
                let parts = (0..to_r).map(|j| if i == j { one } else { zero }).collect();
                self.append(E::Compose { ty: col_ty, components: parts }, s)
            };
            cols.push(col);
        }
        let ty = self.m.ty(&Ty::Matrix(to_c, to_r));
        self.append(E::Compose { ty, components: cols }, s)
    }

    /// The components of a vector built only from constants, with each
    /// vector constant replaced by its scalar values. naga's SPIR-V writer
    /// turns such a `Compose` into one `OpConstantComposite`, which must
    /// list scalars; a vector constituent (`float4(C, 1.0)` with
    /// `let C = float3(...)`) is invalid SPIR-V.
    fn flatten_constant_vectors(&mut self, comps: Vec<Handle<E>>, scalar: Scalar, s: Span) -> Vec<Handle<E>> {
        let mut out = Vec::with_capacity(4);
        for h in comps {
            let value = match self.func.expressions[h] {
                E::Constant(k) => self.m.constant_value(k),
                _ => None,
            };
            match value {
                Some(sema::ConstValue::Composite(parts)) => {
                    for part in parts {
                        let lit = match part {
                            // `float` or `half`, as the vector built.
                            sema::ConstValue::Float(v) => self.m.float_literal(v, scalar),
                            sema::ConstValue::Int(v) => naga::Literal::I32(v as i32),
                            sema::ConstValue::Uint(v) => naga::Literal::U32(v as u32),
                            sema::ConstValue::Bool(v) => naga::Literal::Bool(v),
                            sema::ConstValue::Composite(_) => unreachable!("a vector's components are scalars"),
                        };
                        out.push(self.literal(lit, s));
                    }
                }
                _ => out.push(h),
            }
        }
        out
    }
}
