//! Barriers and uniform control flow: every invocation of a workgroup
//! must reach each barrier (WGSL and SPIR-V require it, GLSL leaves it
//! undefined), so a barrier under a branch whose condition can differ
//! between invocations is an error that points at the branch.
//!
//! A value is non-uniform when it depends on an invocation's own identity
//! or on memory other invocations write: `gl_LocalInvocationID`,
//! `gl_LocalInvocationIndex`, `gl_GlobalInvocationID`, read-write `@ssbo`
//! buffers, storage images, `@groupshared` variables, atomics, or a local
//! assigned such a value anywhere in its function (flow-insensitive, so
//! conservative). Control flow is non-uniform inside an `if` or loop on a
//! non-uniform condition, in a loop whose `break`/`continue` sits under
//! one, and after a `return` under one. A helper called from non-uniform
//! control flow (or with non-uniform arguments) is checked in that state.
//! WGSL has only control barriers, so the memory barriers are held to the
//! same rule. Barriers outside compute programs are errors too.

use super::super::tree::*;
use super::super::types::Access;
use super::Builtin;
use crate::diag::{Diagnostic, Diagnostics};
use crate::source::Span;

use std::collections::BTreeSet;

pub(super) fn check_program(p: &Program, diags: &mut Diagnostics) {
    let has_barrier = barrier_reach(p);
    for ep in &p.entry_points {
        // Mesh and task workgroups have barriers as compute ones do.
        if !matches!(ep.stage, naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task) {
            if let Some(span) = first_barrier(p, &ep.func.body, &has_barrier) {
                let d = Diagnostic::error(format!("barriers are only available in compute, mesh and task programs, and `{}` is a {} entry point", ep.name, super::stmts::stage_name(ep.stage)), span);
                diags.push(d);
            }
            continue;
        }
        if !body_has_barrier(&ep.func.body, &has_barrier) {
            continue;
        }
        let mut walk = Walk { p, has_barrier: &has_barrier, diags, seen: BTreeSet::new(), reported: false };
        walk.function(&ep.func, None, &[]);
    }
}

/// Per helper function, whether it reaches a barrier (callees come first).
fn barrier_reach(p: &Program) -> Vec<bool> {
    let mut reach = vec![false; p.functions.len()];
    for (i, f) in p.functions.iter().enumerate() {
        reach[i] = body_has_barrier(&f.body, &reach);
    }
    reach
}

fn body_has_barrier(stmts: &[Stmt], reach: &[bool]) -> bool {
    let mut found = false;
    visit_exprs(stmts, &mut |e| found |= expr_has_barrier(e, reach));
    found
}

fn expr_has_barrier(e: &Expr, reach: &[bool]) -> bool {
    match &e.kind {
        ExprKind::Builtin(Builtin::Barrier { .. }, _) => true,
        ExprKind::Call(f, args) => reach.get(*f).copied().unwrap_or(false) || args.iter().any(|a| expr_has_barrier(a, reach)),
        _ => children(e).iter().any(|c| expr_has_barrier(c, reach)),
    }
}

/// The span of the first barrier `stmts` reach (directly or in helpers).
fn first_barrier(p: &Program, stmts: &[Stmt], reach: &[bool]) -> Option<Span> {
    fn in_expr(p: &Program, e: &Expr, reach: &[bool]) -> Option<Span> {
        match &e.kind {
            ExprKind::Builtin(Builtin::Barrier { .. }, _) => Some(e.span),
            ExprKind::Call(f, _) if reach.get(*f).copied().unwrap_or(false) => first_barrier(p, &p.functions[*f].body, reach).or(Some(e.span)),
            _ => children(e).iter().find_map(|c| in_expr(p, c, reach)),
        }
    }
    let mut found = None;
    visit_exprs(stmts, &mut |e| {
        if found.is_none() {
            found = in_expr(p, e, reach);
        }
    });
    found
}

/// The direct subexpressions of `e`.
pub(super) fn children(e: &Expr) -> Vec<&Expr> {
    match &e.kind {
        ExprKind::Unary(_, x) | ExprKind::Swizzle(x, _) | ExprKind::Field(x, _) => vec![x],
        ExprKind::Binary(_, lr) => vec![&lr.0, &lr.1],
        ExprKind::Select { cond, accept, reject } => vec![cond, accept, reject],
        ExprKind::Call(_, xs) | ExprKind::Builtin(_, xs) | ExprKind::Construct(xs) => xs.iter().collect(),
        ExprKind::Index(b, i) => vec![b, i],
        _ => Vec::new(),
    }
}

/// Calls `f` on every top-level expression of the statements, nested
/// statements included.
pub(super) fn visit_exprs<'e>(stmts: &'e [Stmt], f: &mut impl FnMut(&'e Expr)) {
    for s in stmts {
        match s {
            Stmt::Local { init, .. } => init.iter().for_each(&mut *f),
            Stmt::Assign { target, value, .. } => {
                f(target);
                f(value);
            }
            Stmt::Expr(e) => f(e),
            Stmt::If { cond, then, otherwise, .. } => {
                f(cond);
                visit_exprs(then, f);
                visit_exprs(otherwise, f);
            }
            Stmt::While { cond, body, .. } => {
                f(cond);
                visit_exprs(body, f);
            }
            Stmt::For { start, end, body, .. } => {
                f(start);
                f(end);
                visit_exprs(body, f);
            }
            Stmt::Return(Some(e), _) => f(e),
            Stmt::Return(None, _) | Stmt::Break(_) | Stmt::Continue(_) | Stmt::Discard(_) => {}
        }
    }
}

struct Walk<'p, 'd> {
    p: &'p Program,
    has_barrier: &'p [bool],
    diags: &'d mut Diagnostics,
    /// Helpers already walked in a state: (function, disrupted, tainted params).
    seen: BTreeSet<(FuncId, bool, Vec<bool>)>,
    /// One error per entry point: the first barrier explains the rest.
    reported: bool,
}

/// Why control flow is non-uniform: the span of the branch (or loop,
/// or return) and what it depends on.
type Disruptor = Option<(Span, &'static str)>;

impl Walk<'_, '_> {
    /// Walks one function body in state `disrupted`, with `params` the
    /// parameters holding non-uniform values.
    fn function(&mut self, f: &Function, disrupted: Disruptor, params: &[bool]) {
        let tainted = self.tainted_locals(f, params);
        let mut cx = Cx { tainted };
        self.block(&f.body, disrupted, &mut cx);
    }

    /// The locals of `f` that may hold a non-uniform value: a fixpoint
    /// over every assignment in the body (assignments under non-uniform
    /// control taint their target too).
    fn tainted_locals(&self, f: &Function, params: &[bool]) -> Vec<bool> {
        let mut t = vec![false; f.locals.len()];
        for (i, &p) in params.iter().enumerate() {
            if i < t.len() {
                t[i] = p;
            }
        }
        loop {
            let before = t.clone();
            self.taint_block(&f.body, false, &mut t);
            if t == before {
                return t;
            }
        }
    }

    fn taint_block(&self, stmts: &[Stmt], under: bool, t: &mut Vec<bool>) {
        for s in stmts {
            match s {
                Stmt::Local { local, init: Some(e), .. } if under || self.non_uniform(e, t).is_some() => t[*local] = true,
                Stmt::Assign { target, value, .. } if under || self.non_uniform(value, t).is_some() => {
                    if let Some(l) = root_local(target) {
                        t[l] = true;
                    }
                }
                Stmt::If { cond, then, otherwise, .. } => {
                    let u = under || self.non_uniform(cond, t).is_some();
                    self.taint_block(then, u, t);
                    self.taint_block(otherwise, u, t);
                }
                Stmt::While { cond, body, .. } => {
                    let u = under || self.non_uniform(cond, t).is_some() || self.loop_exit_disruptor(body, t).is_some();
                    self.taint_block(body, u, t);
                }
                Stmt::For { var, start, end, body, .. } => {
                    let bound = self.non_uniform(start, t).is_some() || self.non_uniform(end, t).is_some();
                    if under || bound {
                        t[*var] = true;
                    }
                    let u = under || bound || self.loop_exit_disruptor(body, t).is_some();
                    self.taint_block(body, u, t);
                }
                _ => {}
            }
        }
    }

    /// Whether `e` can differ between the invocations of a workgroup, and
    /// what makes it so.
    fn non_uniform(&self, e: &Expr, t: &[bool]) -> Option<&'static str> {
        match &e.kind {
            ExprKind::Local(l) => t.get(*l).copied().unwrap_or(false).then_some("a local variable that holds a per-invocation value"),
            ExprKind::Global(g) => match &self.p.globals[*g].kind {
                GlobalKind::Builtin(BuiltinVar::LocalInvocationId | BuiltinVar::LocalInvocationIndex | BuiltinVar::GlobalInvocationId) => Some("the invocation's own ID"),
                GlobalKind::Storage { access: Access::ReadWrite, .. } => Some("a storage buffer other invocations may write"),
                GlobalKind::Workgroup => Some("workgroup memory other invocations may write"),
                _ => None,
            },
            ExprKind::Builtin(Builtin::Atomic(_) | Builtin::ImageLoad, _) => Some("memory other invocations may write"),
            _ => children(e).into_iter().find_map(|c| self.non_uniform(c, t)),
        }
    }

    /// A `break` or `continue` of this loop under a non-uniform branch:
    /// the loop's later iterations are non-uniform.
    fn loop_exit_disruptor(&self, body: &[Stmt], t: &[bool]) -> Disruptor {
        fn find(w: &Walk, stmts: &[Stmt], t: &[bool], under: Disruptor) -> Disruptor {
            for s in stmts {
                match s {
                    Stmt::Break(_) | Stmt::Continue(_) if under.is_some() => return under,
                    Stmt::If { cond, then, otherwise, span } => {
                        let u = under.or_else(|| w.non_uniform(cond, t).map(|why| (*span, why)));
                        if let Some(d) = find(w, then, t, u).or_else(|| find(w, otherwise, t, u)) {
                            return Some(d);
                        }
                    }
                    // A nested loop's own break and continue stay in it.
                    _ => {}
                }
            }
            None
        }
        find(self, body, t, None)
    }

    fn block(&mut self, stmts: &[Stmt], mut disrupted: Disruptor, cx: &mut Cx) {
        for s in stmts {
            match s {
                Stmt::Local { init: Some(e), .. } => self.expr(e, disrupted, cx),
                Stmt::Local { .. } | Stmt::Break(_) | Stmt::Continue(_) | Stmt::Discard(_) | Stmt::Return(None, _) => {}
                Stmt::Assign { target, value, .. } => {
                    self.expr(target, disrupted, cx);
                    self.expr(value, disrupted, cx);
                }
                Stmt::Expr(e) | Stmt::Return(Some(e), _) => self.expr(e, disrupted, cx),
                Stmt::If { cond, then, otherwise, span } => {
                    self.expr(cond, disrupted, cx);
                    let inner = disrupted.or_else(|| self.non_uniform(cond, &cx.tainted).map(|why| (*span, why)));
                    self.block(then, inner, cx);
                    self.block(otherwise, inner, cx);
                    // A `return` under a non-uniform branch: the rest of
                    // the function runs in only some invocations.
                    if disrupted.is_none() && inner.is_some() && (returns(then) || returns(otherwise)) {
                        disrupted = inner;
                    }
                }
                Stmt::While { cond, body, span } => {
                    self.expr(cond, disrupted, cx);
                    // A non-uniform exit first: it is why the loop's own
                    // variables vary too.
                    let inner = disrupted
                        .or_else(|| self.loop_exit_disruptor(body, &cx.tainted))
                        .or_else(|| self.non_uniform(cond, &cx.tainted).map(|why| (*span, why)));
                    self.block(body, inner, cx);
                    if disrupted.is_none() && inner.is_some() && returns(body) {
                        disrupted = inner;
                    }
                }
                Stmt::For { start, end, body, span, .. } => {
                    self.expr(start, disrupted, cx);
                    self.expr(end, disrupted, cx);
                    let bound = self.non_uniform(start, &cx.tainted).or_else(|| self.non_uniform(end, &cx.tainted));
                    let inner = disrupted.or_else(|| self.loop_exit_disruptor(body, &cx.tainted)).or_else(|| bound.map(|why| (*span, why)));
                    self.block(body, inner, cx);
                    if disrupted.is_none() && inner.is_some() && returns(body) {
                        disrupted = inner;
                    }
                }
            }
        }
    }

    fn expr(&mut self, e: &Expr, disrupted: Disruptor, cx: &mut Cx) {
        match &e.kind {
            ExprKind::Builtin(Builtin::Barrier { .. }, _) => {
                if let (Some((at, why)), false) = (disrupted, self.reported) {
                    self.reported = true;
                    let d = Diagnostic::error("barrier in non-uniform control flow: not every invocation of the workgroup reaches it", e.span)
                        .with_label("a barrier every invocation must reach")
                        .with_secondary(at, format!("this branch depends on {why}"))
                        .with_note("help: move the barrier out of the branch, or branch on values every invocation shares (uniforms, gl_WorkGroupID, constants)");
                    self.diags.push(d);
                }
            }
            ExprKind::Call(f, args) => {
                for a in args {
                    self.expr(a, disrupted, cx);
                }
                if !self.has_barrier.get(*f).copied().unwrap_or(false) {
                    return;
                }
                let callee = &self.p.functions[*f];
                let params: Vec<bool> = args.iter().map(|a| self.non_uniform(a, &cx.tainted).is_some()).collect();
                if self.seen.insert((*f, disrupted.is_some(), params.clone())) {
                    self.function(callee, disrupted, &params);
                }
            }
            _ => {
                for c in children(e) {
                    self.expr(c, disrupted, cx);
                }
            }
        }
    }
}

struct Cx {
    tainted: Vec<bool>,
}

/// The local a place is rooted in, if any.
fn root_local(e: &Expr) -> Option<LocalId> {
    match &e.kind {
        ExprKind::Local(l) => Some(*l),
        ExprKind::Field(b, _) | ExprKind::Index(b, _) | ExprKind::Swizzle(b, _) => root_local(b),
        _ => None,
    }
}

/// Whether a `return` is anywhere in the statements.
fn returns(stmts: &[Stmt]) -> bool {
    stmts.iter().any(|s| match s {
        Stmt::Return(..) => true,
        Stmt::If { then, otherwise, .. } => returns(then) || returns(otherwise),
        Stmt::While { body, .. } | Stmt::For { body, .. } => returns(body),
        _ => false,
    })
}
