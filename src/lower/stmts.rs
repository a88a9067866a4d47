//! Statements: locals, assignments, control flow, returns.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::{block_for, break_block, span, FnBuilder, FnKind, LocalSlot};
use crate::sema::{Expr, ExprKind, Scalar, Stmt, Ty};
use crate::source::Span;
use crate::syntax::ast::BinaryOp;

impl FnBuilder<'_, '_> {
    pub(super) fn stmt(&mut self, s: &Stmt, block: &mut Block) {
        match s {
            Stmt::Local { local, init, span: sp } => {
                let l = &self.sema_locals[*local];
                if l.mutable {
                    let ty = self.m.ty(&l.ty);
                    let var = self.func.local_variables.append(naga::LocalVariable { name: Some(super::function::local_name(l.name.as_str())), ty, init: None }, span(l.span));
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
                        self.func.named_expressions.entry(h).or_insert_with(|| super::function::local_name(l.name.as_str()));
                    }
                    self.locals[*local] = LocalSlot::Value(h);
                }
            }
            Stmt::Assign { target, op, value, span: sp } => self.assign(target, *op, value, *sp, block),
            Stmt::Expr(e) => {
                if let ExprKind::Call(fid, args) = &e.kind {
                    let (function, args, write_back) = self.call(*fid, args, block);
                    let result = (e.ty != Ty::Void).then(|| self.append_plain(E::CallResult(function), e.span));
                    self.push(block, Statement::Call { function, arguments: args, result }, e.span);
                    self.write_back(write_back, block, e.span);
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
                for st in super::function::live(body) {
                    self.stmt(st, &mut lb);
                }
                self.flush(&mut lb);
                self.push(block, Statement::Loop { body: lb, continuing: Block::new(), break_if: None }, *sp);
            }
            Stmt::For { var, start, end, body, span: sp } => {
                let l = &self.sema_locals[*var];
                let ty = self.m.ty(&l.ty);
                let v = self.func.local_variables.append(naga::LocalVariable { name: Some(super::function::local_name(l.name.as_str())), ty, init: None }, span(l.span));
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
                for st in super::function::live(body) {
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

    pub(super) fn block_in(&mut self, stmts: &[Stmt], outer: &mut Block) -> Block {
        self.flush(outer);
        self.block(stmts)
    }

    pub(super) fn is_emitted(&self, h: Handle<E>) -> bool {
        !matches!(
            self.func.expressions[h],
            E::Literal(_) | E::Constant(_) | E::ZeroValue(_) | E::FunctionArgument(_) | E::GlobalVariable(_) | E::LocalVariable(_) | E::CallResult(_)
        )
    }

    pub(super) fn assign(&mut self, target: &Expr, op: Option<BinaryOp>, value: &Expr, sp: Span, block: &mut Block) {
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
}
