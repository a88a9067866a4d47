//! Constant subexpressions of function bodies.
//!
//! WGSL evaluates every expression whose operands are all constant when it
//! reads a shader, and refuses the shader if one overflows, divides by zero,
//! shifts out of range, is not finite, or calls a builtin outside its
//! domain; GLSL leaves most of those undefined. So after checking, every
//! such subexpression is evaluated here, with the rules of top-level
//! constants ([`consts`]), and one without a defined value is a located
//! error. So are the run-time operations naga refuses with a constant
//! operand: an integer division or remainder by a constant zero, a shift
//! by a constant of at least the bit width, a `clamp` whose constant bounds
//! are the wrong way round.
//!
//! One pass bottom-up over each body after the checker built it: linear in
//! the program's size, and nothing computed from a reported error is
//! reported again.

use std::borrow::Cow;

use super::super::consts::{self, is_undefined};
use super::super::tree::*;
use super::super::types::{Scalar, Ty};
use super::Builtin;
use crate::diag::{Diagnostic, Diagnostics};
use crate::source::Span;
use crate::syntax::ast::BinaryOp;

/// The most arguments of a builtin call the folder evaluates (no builtin
/// takes more).
const MAX_FOLDED_ARGS: usize = 8;

const NOTE: &str = "its operands are constants, so it is evaluated when compiling: WGSL rejects the shader, GLSL leaves the result undefined";

/// Reports every constant subexpression of every checked function without
/// a defined value.
pub(super) fn check_program(p: &Program, diags: &mut Diagnostics) {
    let mut f = Folder { program: p, lets: Vec::new(), locals: &[], diags };
    for func in p.functions.iter().chain(p.entry_points.iter().map(|e| &e.func)) {
        f.locals = &func.locals;
        f.lets.clear();
        f.lets.resize(func.locals.len(), None);
        f.block(&func.body);
    }
}

struct Folder<'p, 'd> {
    /// Its constants, and the struct names an error shows (looked up
    /// only then).
    program: &'p Program,
    /// The value of each `let` of the function initialised by a constant
    /// scalar: naga's writers put a literal bound by `let` in place of
    /// each use (`let x = 2147483647` then `x + 1` is written
    /// `2147483647i + 1i`, which WGSL evaluates), so its uses are
    /// constant too. (A vector or array value is written once, as a `let`.)
    lets: Vec<Option<ConstValue>>,
    locals: &'p [Local],
    diags: &'d mut Diagnostics,
}

type Val<'p> = Option<Cow<'p, ConstValue>>;

impl<'p> Folder<'p, '_> {
    fn block(&mut self, stmts: &'p [Stmt]) {
        for s in stmts {
            self.stmt(s);
        }
    }

    fn stmt(&mut self, s: &'p Stmt) {
        match s {
            Stmt::Local { local, init, .. } => {
                if let Some(e) = init {
                    let v = self.expr(e);
                    if !self.locals[*local].mutable {
                        self.lets[*local] = v.filter(|v| !matches!(**v, ConstValue::Composite(_))).map(Cow::into_owned);
                    }
                }
            }
            Stmt::Assign { target, op, value, span } => {
                self.expr(target);
                let v = self.expr(value);
                // `x /= 0`, `x <<= 40` are the binary operation on `x`.
                if let Some(op) = op {
                    if let Err(msg) = self.runtime_rules(*op, &target.ty, &value.ty, v.as_deref()) {
                        self.error(msg, *span);
                    }
                }
            }
            Stmt::Expr(e) => {
                self.expr(e);
            }
            Stmt::If { cond, then, otherwise, .. } => {
                self.expr(cond);
                self.block(then);
                self.block(otherwise);
            }
            Stmt::While { cond, body, .. } => {
                self.expr(cond);
                self.block(body);
            }
            Stmt::For { start, end, body, .. } => {
                self.expr(start);
                self.expr(end);
                self.block(body);
            }
            Stmt::Return(Some(e), _) => {
                self.expr(e);
            }
            Stmt::Return(None, _) | Stmt::Break(_) | Stmt::Continue(_) | Stmt::Discard(_) => {}
        }
    }

    fn error(&mut self, msg: String, span: Span) {
        self.diags.push(Diagnostic::error(msg, span).with_note(NOTE));
    }

    /// The value of `e` when all its operands are constant.
    fn expr(&mut self, e: &'p Expr) -> Val<'p> {
        if e.ty.is_error() {
            return None;
        }
        match &e.kind {
            ExprKind::Float(v) => Some(Cow::Owned(ConstValue::Float(*v as f32 as f64))),
            ExprKind::Int(v) => Some(Cow::Owned(ConstValue::Int(*v))),
            ExprKind::Uint(v) => Some(Cow::Owned(ConstValue::Uint(*v))),
            ExprKind::Bool(v) => Some(Cow::Owned(ConstValue::Bool(*v))),
            ExprKind::Const(c) => Some(Cow::Borrowed(&self.program.consts[*c].value)),
            ExprKind::Local(l) => self.lets.get(*l).and_then(|v| v.clone()).map(Cow::Owned),
            // A zero value (an unset field of a construction by name).
            ExprKind::Global(_) | ExprKind::Zero => None,
            ExprKind::Unary(op, x) => {
                let v = self.expr(x)?;
                match consts::unary(*op, &v) {
                    Some(r) => Some(Cow::Owned(r)),
                    None if *op == crate::syntax::ast::UnaryOp::Neg => {
                        self.error(format!("`-({})` overflows `{}`", show(&v), scalar_name(&x.ty)), e.span);
                        None
                    }
                    None => None,
                }
            }
            ExprKind::Binary(op, ab) => {
                let (a, b) = &**ab;
                let va = self.expr(a);
                let vb = self.expr(b);
                if let Err(msg) = self.runtime_rules(*op, &a.ty, &b.ty, vb.as_deref()) {
                    self.error(msg, e.span);
                    return None;
                }
                let (va, vb) = (va?, vb?);
                match consts::binary(*op, &va, &a.ty, &vb, &b.ty) {
                    Ok((v, _)) => Some(Cow::Owned(v)),
                    Err(msg) if is_undefined(&msg) => {
                        self.error(msg, e.span);
                        None
                    }
                    Err(_) => None,
                }
            }
            ExprKind::Select { cond, accept, reject } => {
                let c = self.expr(cond);
                let a = self.expr(accept);
                let r = self.expr(reject);
                let (c, a, r) = (c?, a?, r?);
                match &*c {
                    ConstValue::Bool(true) => Some(a),
                    ConstValue::Bool(false) => Some(r),
                    ConstValue::Composite(cs) => {
                        let pick = |i: usize, x: &ConstValue| match x {
                            ConstValue::Composite(xs) => xs.get(i).cloned(),
                            _ => None,
                        };
                        let parts = cs.iter().enumerate().map(|(i, c)| if *c == ConstValue::Bool(true) { pick(i, &a) } else { pick(i, &r) }).collect::<Option<Vec<_>>>()?;
                        Some(Cow::Owned(ConstValue::Composite(parts)))
                    }
                    _ => None,
                }
            }
            ExprKind::Call(_, args) => {
                for a in args {
                    self.expr(a);
                }
                None
            }
            ExprKind::Builtin(b, args) => {
                // Inline: every builtin call is folded, most with a run-time
                // argument, and no builtin takes more than a few.
                if args.len() > MAX_FOLDED_ARGS {
                    args.iter().for_each(|a| drop(self.expr(a)));
                    return None;
                }
                let vals: arrayvec::ArrayVec<Val<'p>, MAX_FOLDED_ARGS> = args.iter().map(|a| self.expr(a)).collect();
                // naga refuses a `clamp` whose constant bounds are reversed,
                // whatever the value clamped.
                if let (Builtin::Math(naga::MathFunction::Clamp), [_, Some(lo), Some(hi)]) = (b, &vals[..]) {
                    if let Some((l, h)) = reversed_bounds(lo, hi) {
                        self.error(format!("`clamp` with a lower bound ({l}) greater than its upper bound ({h}) is undefined"), e.span);
                        return None;
                    }
                }
                // WGSL computes `edge1 - edge0` of a `smoothstep` whose
                // edges are constant, whatever `x`, and rejects an overflow.
                if let (Builtin::Math(naga::MathFunction::SmoothStep), [Some(lo), Some(hi), _]) = (b, &vals[..]) {
                    if let Some(d) = super::super::fold::difference_past_f32(lo, hi) {
                        self.error(format!("`smoothstep`'s edge1 - edge0 is {d:e}, past the range of `float` (WGSL computes it from constant edges and rejects it)"), e.span);
                        return None;
                    }
                }
                // Most calls have a run-time argument: done, with nothing
                // more allocated.
                if vals.iter().any(Option::is_none) || b.is_texture() {
                    return None;
                }
                let vals: Vec<Cow<'p, ConstValue>> = vals.into_iter().collect::<Option<_>>()?;
                let typed: Vec<(&ConstValue, &Ty)> = vals.iter().map(|v| &**v).zip(args.iter().map(|a| &a.ty)).collect();
                match consts::eval_builtin(*b, &typed, &e.ty) {
                    Ok(v) => v.map(Cow::Owned),
                    Err(msg) => {
                        self.error(msg, e.span);
                        None
                    }
                }
            }
            ExprKind::Construct(xs) => {
                // Every part is walked (for its own errors); the values are
                // kept only while all are constant, so a construction with a
                // run-time part allocates nothing.
                let mut vals: Option<Vec<(ConstValue, Ty)>> = Some(Vec::new());
                for x in xs {
                    let v = self.expr(x);
                    match (v, &mut vals) {
                        (Some(v), Some(vs)) => {
                            if vs.is_empty() {
                                vs.reserve_exact(xs.len());
                            }
                            vs.push((v.into_owned(), x.ty.clone()));
                        }
                        (None, _) => vals = None,
                        (Some(_), None) => {}
                    }
                }
                let vals = vals?;
                // A conversion to `half` of a constant past its range: WGSL
                // evaluates it and rejects the shader.
                if matches!(e.ty, Ty::Scalar(Scalar::Half) | Ty::Vector(Scalar::Half, _)) {
                    if let Some(x) = vals.iter().flat_map(|(v, _)| scalars(v)).find_map(|c| match *c {
                        // WGSL: outside [-65504, 65504], not rounded into it.
                        ConstValue::Float(x) if x.abs() > 65504.0 => Some(x),
                        ConstValue::Int(k) if k.abs() > 65504 => Some(k as f64),
                        ConstValue::Uint(k) if k > 65504 => Some(k as f64),
                        _ => None,
                    }) {
                        self.error(format!("{x} is past the range of `half` (largest 65504): WGSL rejects its conversion in a constant"), e.span);
                        return None;
                    }
                }
                match &e.ty {
                    Ty::Struct(_) | Ty::Array(..) => Some(Cow::Owned(ConstValue::Composite(vals.into_iter().map(|v| v.0).collect()))),
                    ty => consts::construct(ty, vals).map(Cow::Owned),
                }
            }
            ExprKind::Swizzle(x, comps) => {
                let v = self.expr(x)?;
                let ConstValue::Composite(cs) = &*v else { return None };
                let parts = comps.iter().map(|&i| cs.get(i as usize).cloned()).collect::<Option<Vec<_>>>()?;
                Some(Cow::Owned(if parts.len() == 1 { parts.into_iter().next()? } else { ConstValue::Composite(parts) }))
            }
            ExprKind::Field(x, i) => {
                let v = self.expr(x)?;
                element(v, *i as usize)
            }
            ExprKind::Index(x, i) => {
                let v = self.expr(x);
                let k = self.expr(i);
                let k = match k.as_deref()? {
                    ConstValue::Int(k) => *k,
                    ConstValue::Uint(k) => *k as i64,
                    _ => return None,
                };
                // A constant index is checked against the static length
                // whatever the base (naga and WGSL refuse it out of bounds);
                // the checker did that for literal indices already.
                let len = match &x.ty {
                    Ty::Vector(_, n) => *n as i64,
                    Ty::Matrix(c, _) => *c as i64,
                    Ty::Array(_, n) => *n as i64,
                    Ty::RuntimeArray(_) => {
                        if !(0..=i32::MAX as i64).contains(&k) {
                            self.error(format!("constant index {k} into a run-time-sized array is not in 0 to {} (GLSL indexes arrays with an `int`, and WGSL as written with an `i32`)", i32::MAX), i.span);
                        }
                        return None;
                    }
                    _ => return None,
                };
                if !(0..len).contains(&k) {
                    let struct_names = self.program.struct_names();
                    let shown = super::super::types::TyDisplay { ty: &x.ty, struct_names: &struct_names, enum_names: &[] }.to_string();
                    self.error(format!("index {k} is out of bounds for `{shown}` (length {len})"), i.span);
                    return None;
                }
                element(v?, k as usize)
            }
        }
    }

    /// What naga refuses in a run-time operation with a constant right
    /// operand `b`: an integer division by zero, a shift by 32 or more.
    fn runtime_rules(&self, op: BinaryOp, ta: &Ty, tb: &Ty, b: Option<&ConstValue>) -> Result<(), String> {
        let Some(b) = b else { return Ok(()) };
        let integer = |t: &Ty| t.scalar().is_some_and(|s| s.is_integer());
        let zero = || scalars(b).any(|c| matches!(c, ConstValue::Int(0) | ConstValue::Uint(0)));
        match op {
            BinaryOp::Div | BinaryOp::Mod if integer(ta) && integer(tb) && zero() => {
                let what = if op == BinaryOp::Div { "integer division" } else { "integer remainder `%`" };
                return Err(format!("{what} by zero"));
            }
            BinaryOp::Shl | BinaryOp::Shr if integer(ta) => {
                if let Some(k) = scalars(b).find_map(|c| match *c {
                    ConstValue::Int(k) if !(0..32).contains(&k) => Some(k),
                    ConstValue::Uint(k) if k >= 32 => Some(k as i64),
                    _ => None,
                }) {
                    let sym = if op == BinaryOp::Shl { "<<" } else { ">>" };
                    return Err(format!("shift amount {k} is out of range: `{sym}` on a 32-bit `{}` shifts by 0 to 31", scalar_name(ta)));
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// Component `i` of a constant vector, array or struct.
fn element(v: Cow<'_, ConstValue>, i: usize) -> Option<Cow<'_, ConstValue>> {
    match v {
        Cow::Borrowed(ConstValue::Composite(cs)) => cs.get(i).map(Cow::Borrowed),
        Cow::Owned(ConstValue::Composite(mut cs)) if i < cs.len() => Some(Cow::Owned(cs.swap_remove(i))),
        _ => None,
    }
}

fn scalars(v: &ConstValue) -> Box<dyn Iterator<Item = &ConstValue> + '_> {
    match v {
        ConstValue::Composite(cs) => Box::new(cs.iter().flat_map(scalars)),
        c => Box::new(std::iter::once(c)),
    }
}

/// The first pair of bounds with `lo > hi`, shown.
fn reversed_bounds(lo: &ConstValue, hi: &ConstValue) -> Option<(String, String)> {
    let lo: Vec<&ConstValue> = scalars(lo).collect();
    let hi: Vec<&ConstValue> = scalars(hi).collect();
    let n = lo.len().max(hi.len());
    (0..n).find_map(|i| {
        let (l, h) = (lo[i.min(lo.len() - 1)], hi[i.min(hi.len() - 1)]);
        let greater = match (l, h) {
            (ConstValue::Float(l), ConstValue::Float(h)) => l > h,
            (ConstValue::Int(l), ConstValue::Int(h)) => l > h,
            (ConstValue::Uint(l), ConstValue::Uint(h)) => l > h,
            _ => false,
        };
        greater.then(|| (show(l), show(h)))
    })
}

fn show(c: &ConstValue) -> String {
    match *c {
        ConstValue::Float(x) => format!("{:?}", x as f32),
        ConstValue::Int(x) => x.to_string(),
        ConstValue::Uint(x) => format!("{x}u"),
        ConstValue::Bool(x) => x.to_string(),
        ConstValue::Composite(_) => "this value".into(),
    }
}

fn scalar_name(t: &Ty) -> &'static str {
    t.scalar().unwrap_or(Scalar::Int).name()
}
