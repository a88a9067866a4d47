//! `for` over ranges and fixed arrays, several walked in parallel, and
//! `with`. Both bind names to parts of an expression evaluated once,
//! before the block: what a subject's indices and values depend on is
//! held in hidden `let`s first ([`Checker::stable`]), so each use of a
//! name reads the same element a daslang reference would.

use super::*;

/// One source of a `for`.
enum Source {
    /// `range(start, end)`: `start` is stable.
    Range { start: Expr, end: Expr },
    /// A fixed array (`subject` is stable) of `len` elements.
    Array { subject: Expr, len: u32 },
}

fn lit_int(k: i64, span: Span) -> Expr {
    Expr { kind: ExprKind::Int(k), ty: INT, span }
}

fn binary(op: BinaryOp, l: Expr, r: Expr, ty: Ty, span: Span) -> Expr {
    Expr { kind: ExprKind::Binary(op, Box::new((l, r))), ty, span }
}

/// `x` as a `uint` (its bits, for an `int`).
fn to_uint(x: Expr) -> Expr {
    if x.ty == UINT {
        return x;
    }
    let span = x.span;
    Expr { kind: ExprKind::Construct(vec![x]), ty: UINT, span }
}

/// `x` (a `uint`) as `ty` (`int`: its bits).
fn from_uint(x: Expr, ty: &Ty) -> Expr {
    if *ty == UINT {
        return x;
    }
    let span = x.span;
    Expr { kind: ExprKind::Construct(vec![x]), ty: ty.clone(), span }
}

fn break_if(cond: Expr, span: Span) -> Stmt {
    Stmt::If { cond, then: vec![Stmt::Break(span)], otherwise: Vec::new(), span }
}

fn is_literal(e: &Expr) -> bool {
    matches!(e.kind, ExprKind::Int(_) | ExprKind::Uint(_) | ExprKind::Const(_))
}

impl<'a, 'd> Checker<'a, 'd> {
    /// A local the compiler adds (not visible by name), held in `cx`.
    fn hidden_local(&mut self, cx: &mut FnCtx<'a>, name: String, ty: Ty, mutable: bool, span: Span) -> LocalId {
        cx.locals.push(Local { name: ast::Name::new(&name), ty, mutable, by_ref: false, span });
        cx.locals.len() - 1
    }

    /// `x` held in a hidden `let` (pushed to `pre`), as a read of it.
    fn hold(&mut self, cx: &mut FnCtx<'a>, x: Expr, name: String, pre: &mut Vec<Stmt>) -> Expr {
        let (ty, span) = (x.ty.clone(), x.span);
        let id = self.hidden_local(cx, name, ty.clone(), false, span);
        pre.push(Stmt::Local { local: id, init: Some(x), span });
        Expr { kind: ExprKind::Local(id), ty, span }
    }

    /// `x`, safe to evaluate again at every use: a variable, constant, or
    /// a field, component or element of one stays a place (reads see
    /// writes, writes reach it), its run-time indices held in hidden
    /// `let`s; any other value is held in a hidden `let`.
    pub(super) fn stable(&mut self, cx: &mut FnCtx<'a>, x: Expr, name: &str, pre: &mut Vec<Stmt>) -> Expr {
        let span = x.span;
        match x.kind {
            ExprKind::Global(_) | ExprKind::Const(_) => x,
            ExprKind::Local(_) => x,
            ExprKind::Field(b, i) => {
                let b = self.stable(cx, *b, name, pre);
                Expr { kind: ExprKind::Field(Box::new(b), i), ty: x.ty, span }
            }
            ExprKind::Swizzle(b, c) => {
                let b = self.stable(cx, *b, name, pre);
                Expr { kind: ExprKind::Swizzle(Box::new(b), c), ty: x.ty, span }
            }
            ExprKind::Index(b, i) => {
                let b = self.stable(cx, *b, name, pre);
                let fixed = is_literal(&i) || matches!(i.kind, ExprKind::Local(l) if !cx.locals[l].mutable);
                let i = if fixed { *i } else { self.hold(cx, *i, format!("{name}_index"), pre) };
                Expr { kind: ExprKind::Index(Box::new(b), Box::new(i)), ty: x.ty, span }
            }
            kind => self.hold(cx, Expr { kind, ..x }, name.to_string(), pre),
        }
    }

    /// `f() $ { ... }`: in a shader only daslang's `unroll() $ { for (i in
    /// range(N)) { ... } }`, which is that loop (an unrolling hint the
    /// targets' compilers may take). As daslang's `unroll` macro requires:
    /// one `for` over a `range` with compile-time bounds, and (the body is
    /// copied once per step, with no loop left) no `break`/`continue` of it.
    pub(super) fn check_call_block(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, args: &'a [ast::Expr], body: &'a ast::Block, span: Span, out: &mut Vec<Stmt>) {
        let name = callee.name.as_str();
        // `unroll` is daslang's macro (daslib/unroll), which `require
        // daslib/unroll` also declares as a function taking a block.
        if name != "unroll" {
            let d = Diagnostic::error(format!("`{name}` with a block argument is not supported in shader code"), callee.span)
                .with_label("called with a block (`$ { ... }`)")
                .with_note("daslang's blocks are host code; in a shader only `unroll() $ { for (...) { ... } }` takes one");
            self.diags.push(d);
            return;
        }
        if let Some(a) = args.first() {
            let d = Diagnostic::error("`unroll` takes only its block: `unroll() $ { for (i in range(N)) { ... } }`", a.span);
            self.diags.push(d);
            return;
        }
        let one_range_loop = match body.stmts.as_slice() {
            [ast::Stmt { kind: ast::StmtKind::For { vars, iters, body: loop_body }, span: loop_span }] if vars.len() == 1 && iters.len() == 1 => match &iters[0].kind {
                ast::ExprKind::Call { callee, args } if callee.name == "range" => Some((vars, iters, loop_body, *loop_span, args)),
                _ => None,
            },
            _ => None,
        };
        let Some((vars, iters, loop_body, loop_span, bounds)) = one_range_loop else {
            let d = Diagnostic::error("`unroll` takes one `for` loop over a `range`: `unroll() $ { for (i in range(N)) { ... } }`", body.span)
                .with_label("not a single `for (i in range(...))` loop")
                .with_note("daslang's `unroll` macro copies the body of that one loop once per step");
            self.diags.push(d);
            return;
        };
        for b in bounds {
            if let Some(Err(_)) = self.fold(b, None, b.span) {
                let d = Diagnostic::error("`unroll` needs the loop's bounds at compile time", b.span)
                    .with_label("not a constant")
                    .with_note("daslang's `unroll` copies the body once per step, so it must know the steps: use literals or top-level `let` constants");
                self.diags.push(d);
                return;
            }
        }
        if let Some((kw, at)) = loop_exit(&loop_body.stmts) {
            let d = Diagnostic::error(format!("`{kw}` in an unrolled loop"), at)
                .with_label(format!("would `{kw}` out of `unroll`'s copies"))
                .with_note("daslang's `unroll` copies the body once per step and leaves no loop, so this would leave an enclosing loop instead: use a plain `for`, or an `if` around the rest of the body");
            self.diags.push(d);
            return;
        }
        let _ = span;
        self.check_for(cx, vars, iters, loop_body, loop_span, out);
    }

    /// `for (a, b in x, y) body`: each variable takes the elements of its
    /// source (`range(...)` or a fixed array) in step; the loop stops at
    /// the end of the shortest.
    pub(super) fn check_for(&mut self, cx: &mut FnCtx<'a>, vars: &'a [ast::Ident], iters: &'a [ast::Expr], body: &'a ast::Block, span: Span, out: &mut Vec<Stmt>) {
        if vars.len() != iters.len() {
            let plural = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
            let d = Diagnostic::error(format!("`for` names {} for {}", plural(vars.len(), "loop variable"), plural(iters.len(), "source")), span)
                .with_note("help: give each source its variable, in order: `for (i, x in range(n), arr)`");
            self.diags.push(d);
            return;
        }
        let is_range = |e: &ast::Expr| matches!(&e.kind, ast::ExprKind::Call { callee, .. } if callee.name == "range");
        if let ([var], [iter]) = (vars, iters) {
            if is_range(iter) {
                // The plain counting loop.
                let (start, end) = self.check_range(cx, iter);
                cx.open_scope();
                let local = self.declare_local(cx, var, start.ty.clone(), false);
                cx.loop_depth += 1;
                let body = self.check_block(cx, &body.stmts);
                cx.loop_depth -= 1;
                cx.close_scope();
                out.push(Stmt::For { var: local, start, end, body, span });
                return;
            }
        }
        cx.open_scope();
        let mut pre = Vec::new();
        let mut sources = Vec::with_capacity(iters.len());
        for (var, iter) in vars.iter().zip(iters) {
            let name = var.name.as_str();
            let src = if is_range(iter) {
                let (start, end) = self.check_range(cx, iter);
                let start = if is_literal(&start) { start } else { self.hold(cx, start, format!("{name}_start"), &mut pre) };
                Some(Source::Range { start, end })
            } else {
                let x = self.check_expr(cx, iter);
                match &x.ty {
                    Ty::Error => None,
                    Ty::Array(_, n) => {
                        let len = *n;
                        let subject = self.stable(cx, x, &format!("{name}_array"), &mut pre);
                        Some(Source::Array { subject, len })
                    }
                    other => {
                        let d = Diagnostic::error(format!("`for` walks a `range(...)` or a fixed array; `{}` is neither", self.show(other)), x.span)
                            .with_note("help: index it in a counting loop: `for (i in range(n))`");
                        self.diags.push(d);
                        None
                    }
                }
            };
            sources.push(src);
        }
        if sources.iter().any(|s| s.is_none()) {
            cx.close_scope();
            return;
        }
        let sources: Vec<Source> = sources.into_iter().map(|s| s.expect("checked above")).collect();
        // The counter: the first range's own variable, or (the first
        // source an array) a hidden index up to the shortest array.
        let mut prelude = Vec::new();
        let (counter, start, end, first_start) = match &sources[0] {
            Source::Range { start, end } => {
                let local = self.declare_local(cx, &vars[0], start.ty.clone(), false);
                (local, start.clone(), end.clone(), Some(start.clone()))
            }
            Source::Array { .. } => {
                let shortest = sources.iter().filter_map(|s| if let Source::Array { len, .. } = s { Some(*len) } else { None }).min().unwrap_or(0);
                let local = self.hidden_local(cx, format!("{}_index", vars[0].name), INT, false, span);
                (local, lit_int(0, span), lit_int(shortest as i64, span), None)
            }
        };
        let counter_ty = cx.locals[counter].ty.clone();
        let counter_expr = Expr { kind: ExprKind::Local(counter), ty: counter_ty.clone(), span };
        // Steps taken so far, as a `uint` (exact however long the range).
        let from_zero = first_start.as_ref().is_some_and(|s0| matches!(s0.kind, ExprKind::Int(0) | ExprKind::Uint(0)));
        let steps = match &first_start {
            Some(_) if from_zero => Some(to_uint(counter_expr.clone())),
            Some(s0) if sources.len() > 1 => {
                let d = binary(BinaryOp::Sub, to_uint(counter_expr.clone()), to_uint(s0.clone()), UINT, span);
                let id = self.hidden_local(cx, format!("{}_step", vars[0].name), UINT, false, span);
                prelude.push(Stmt::Local { local: id, init: Some(d), span });
                Some(Expr { kind: ExprKind::Local(id), ty: UINT, span })
            }
            Some(_) => None,
            None => Some(to_uint(counter_expr.clone())),
        };
        let index = match &first_start {
            // Counting from 0: the counter is the index.
            Some(_) if from_zero && counter_ty == INT => Some(counter_expr.clone()),
            Some(_) => steps.clone().map(|s| from_uint(s, &INT)),
            None => Some(counter_expr.clone()),
        };
        let mut lets = Vec::new();
        for (k, (var, src)) in vars.iter().zip(&sources).enumerate() {
            match src {
                Source::Range { .. } if k == 0 => {}
                Source::Range { start, end } => {
                    let steps = steps.clone().expect("a second source has a step count");
                    // The range's length, once: `end - start` where positive.
                    let ty = start.ty.clone();
                    let longer = binary(BinaryOp::Gt, end.clone(), start.clone(), BOOL, span);
                    let diff = binary(BinaryOp::Sub, to_uint(end.clone()), to_uint(start.clone()), UINT, span);
                    let zero = Expr { kind: ExprKind::Uint(0), ty: UINT, span };
                    let len = Expr { kind: ExprKind::Select { cond: Box::new(longer), accept: Box::new(diff), reject: Box::new(zero) }, ty: UINT, span };
                    let len = self.hold(cx, len, format!("{}_count", var.name), &mut pre);
                    prelude.push(break_if(binary(BinaryOp::Ge, steps.clone(), len, BOOL, span), span));
                    let value = binary(BinaryOp::Add, start.clone(), from_uint(steps, &ty), ty.clone(), span);
                    let local = self.declare_local(cx, var, ty, false);
                    lets.push(Stmt::Local { local, init: Some(value), span });
                }
                Source::Array { subject, len } => {
                    if first_start.is_some() {
                        let steps = steps.clone().expect("a second source has a step count");
                        let n = Expr { kind: ExprKind::Uint(*len as u64), ty: UINT, span };
                        prelude.push(break_if(binary(BinaryOp::Ge, steps, n, BOOL, span), span));
                    }
                    let Ty::Array(elem, _) = &subject.ty else { unreachable!("an array source") };
                    let elem = (**elem).clone();
                    let i = index.clone().expect("an array source has an index");
                    let element = Expr { kind: ExprKind::Index(Box::new(subject.clone()), Box::new(i)), ty: elem.clone(), span: var.span };
                    let writable = self.place_ok(cx, subject).is_ok() && !matches!(subject.kind, ExprKind::Const(_));
                    let local = self.declare_local(cx, var, elem.clone(), writable);
                    if writable || elem.is_sampler_like() {
                        // A reference: each use is the element itself.
                        cx.aliases.insert(local, element);
                    } else {
                        cx.locals[local].mutable = false;
                        lets.push(Stmt::Local { local, init: Some(element), span });
                    }
                }
            }
        }
        prelude.extend(lets);
        cx.loop_depth += 1;
        let inner = self.check_block(cx, &body.stmts);
        cx.loop_depth -= 1;
        cx.close_scope();
        prelude.extend(inner);
        let for_stmt = Stmt::For { var: counter, start, end, body: prelude, span };
        if pre.is_empty() {
            out.push(for_stmt);
        } else {
            pre.push(for_stmt);
            out.push(Stmt::If { cond: Expr { kind: ExprKind::Bool(true), ty: BOOL, span }, then: pre, otherwise: Vec::new(), span });
        }
    }

    /// `with (subject) body`: the subject's fields are names in the body.
    pub(super) fn check_with(&mut self, cx: &mut FnCtx<'a>, subject: &'a ast::Expr, body: &'a ast::Block, span: Span, out: &mut Vec<Stmt>) {
        let x = self.check_expr(cx, subject);
        let id = match x.ty {
            Ty::Struct(id) => Some(id),
            Ty::Error => None,
            ref other => {
                let d = Diagnostic::error(format!("`with` brings a struct's fields into scope, and `{}` is not a struct", self.show(other)), x.span)
                    .with_note("help: name a struct value: `with (light) { ... }`");
                self.diags.push(d);
                None
            }
        };
        let mut pre = Vec::new();
        if let Some(id) = id {
            let name = format!("with_{}", self.out.structs[id].name);
            let subject = self.stable(cx, x, &name, &mut pre);
            cx.withs.push(WithScope { subject, id });
        }
        let inner = self.check_block(cx, &body.stmts);
        if id.is_some() {
            cx.withs.pop();
        }
        pre.extend(inner);
        out.push(Stmt::If { cond: Expr { kind: ExprKind::Bool(true), ty: BOOL, span }, then: pre, otherwise: Vec::new(), span });
    }

    /// The field `name` of an enclosing `with` subject (the innermost that
    /// has one). daslang looks a name up as a local variable first, then as
    /// a `with` field, then as a parameter or a global: a local hides a
    /// field, a field hides a parameter.
    pub(super) fn with_field(&self, cx: &FnCtx<'a>, name: &str, span: Span) -> Option<Expr> {
        if cx.lookup(name).is_some_and(|l| l >= cx.params) {
            return None;
        }
        for w in cx.withs.iter().rev() {
            let fields = &self.out.structs[w.id].fields;
            if let Some(i) = fields.iter().position(|(f, _, _)| f == name) {
                let ty = fields[i].1.clone();
                return Some(Expr { kind: ExprKind::Field(Box::new(w.subject.clone()), i as u32), ty, span });
            }
        }
        None
    }
}

/// The first `break` or `continue` in `stmts` that belongs to their loop
/// (not to a loop inside them).
fn loop_exit(stmts: &[ast::Stmt]) -> Option<(&'static str, Span)> {
    stmts.iter().find_map(|s| match &s.kind {
        ast::StmtKind::Break => Some(("break", s.span)),
        ast::StmtKind::Continue => Some(("continue", s.span)),
        ast::StmtKind::If { then, elifs, otherwise, .. } => loop_exit(&then.stmts)
            .or_else(|| elifs.iter().find_map(|(_, b)| loop_exit(&b.stmts)))
            .or_else(|| otherwise.as_ref().and_then(|b| loop_exit(&b.stmts))),
        ast::StmtKind::Block(b) | ast::StmtKind::With { body: b, .. } | ast::StmtKind::CallBlock { body: b, .. } => loop_exit(&b.stmts),
        _ => None,
    })
}
