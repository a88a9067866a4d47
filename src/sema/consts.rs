//! Compile-time evaluation of top-level `let` constants and array lengths.
//!
//! Constants become naga constants, whose initialisers must be constant
//! expressions; evaluating them here keeps the IR simple (literals and
//! composes) and catches overflow and division by zero with a location.

use std::borrow::Cow;

use super::tree::ConstValue;
use super::types::{Scalar, Ty, BOOL, FLOAT, INT, UINT};
use crate::diag::Diagnostic;
use crate::syntax::ast::{BinaryOp, Expr, ExprKind, IntSuffix, UnaryOp};

/// What the evaluator may look up.
pub trait ConstEnv {
    /// An already evaluated constant.
    fn lookup(&self, name: &str) -> Option<(ConstValue, Ty)>;
    /// A struct type and its field types.
    fn struct_type(&self, name: &str) -> Option<(Ty, Vec<Ty>)>;
    /// The value of `Enum.member`, where `ty` names an enumeration.
    fn enum_value(&self, _ty: &str, _member: &str) -> Option<(ConstValue, Ty)> {
        None
    }
    /// Why a name is not a constant, where there is more to say.
    fn why_not_const(&self, _name: &str) -> Option<String> {
        None
    }
}

/// Every name an expression mentions (so the constants it uses can be
/// evaluated first).
pub fn collect_names<'e>(e: &'e Expr, out: &mut Vec<&'e str>) {
    collect_names_depth(e, out, 0)
}

fn collect_names_depth<'e>(e: &'e Expr, out: &mut Vec<&'e str>, depth: usize) {
    if depth > super::limits::MAX_DEPTH {
        return;
    }
    let d = depth + 1;
    match &e.kind {
        ExprKind::Name(id) => out.push(&id.name),
        ExprKind::Unary(_, x) | ExprKind::Paren(x) | ExprKind::Field(x, _) => collect_names_depth(x, out, d),
        ExprKind::Binary(_, ab) => {
            collect_names_depth(&ab.0, out, d);
            collect_names_depth(&ab.1, out, d);
        }
        ExprKind::Index(a, b) => {
            collect_names_depth(a, out, d);
            collect_names_depth(b, out, d);
        }
        ExprKind::Ternary(a, b, c) => {
            collect_names_depth(a, out, d);
            collect_names_depth(b, out, d);
            collect_names_depth(c, out, d);
        }
        ExprKind::Call { args, .. } | ExprKind::Array { items: args, .. } => args.iter().for_each(|a| collect_names_depth(a, out, d)),
        _ => {}
    }
}

fn not_const(e: &Expr, what: &str) -> Diagnostic {
    Diagnostic::error(format!("{what} is not a constant expression"), e.span)
        .with_note("top-level `let` values and array lengths must be computable at compile time: literals, other constants, arithmetic, constructors and builtin functions")
}

pub fn eval_const(e: &Expr, env: &dyn ConstEnv) -> Result<(ConstValue, Ty), Diagnostic> {
    eval(e, env, 0)
}

fn eval(e: &Expr, env: &dyn ConstEnv, depth: usize) -> Result<(ConstValue, Ty), Diagnostic> {
    if depth > super::limits::MAX_DEPTH {
        return Err(Diagnostic::error(format!("constant expression nests deeper than the limit of {}", super::limits::MAX_DEPTH), e.span));
    }
    let d = depth + 1;
    match &e.kind {
        ExprKind::Int(v, IntSuffix::None) => {
            let v = i32::try_from(*v).map_err(|_| Diagnostic::error(format!("integer literal {v} does not fit in `int`"), e.span))?;
            Ok((ConstValue::Int(v as i64), INT))
        }
        ExprKind::Int(v, IntSuffix::Unsigned) => {
            let v = u32::try_from(*v).map_err(|_| Diagnostic::error(format!("integer literal {v} does not fit in `uint`"), e.span))?;
            Ok((ConstValue::Uint(v as u64), UINT))
        }
        ExprKind::Float(v) => Ok((ConstValue::Float(*v as f32 as f64), FLOAT)),
        ExprKind::Bool(b) => Ok((ConstValue::Bool(*b), BOOL)),
        ExprKind::Half(v) => Ok((ConstValue::Float(*v), super::types::HALF)),
        ExprKind::Reinterpret(..) => Err(not_const(e, "`reinterpret`")),
        ExprKind::Paren(x) => eval(x, env, d),
        ExprKind::Name(id) => env.lookup(&id.name).ok_or_else(|| {
            let d = not_const(e, &format!("`{}`", id.name));
            match env.why_not_const(&id.name) {
                Some(why) => d.with_note(why),
                None => d,
            }
        }),
        ExprKind::Unary(op, x) => {
            if let (UnaryOp::Neg, ExprKind::Int(2147483648, IntSuffix::None)) = (op, &x.kind) {
                return Ok((ConstValue::Int(i32::MIN as i64), INT));
            }
            let (v, ty) = eval(x, env, d)?;
            unary(*op, &v).map(|v| (v, ty)).ok_or_else(|| not_const(e, "this operation"))
        }
        ExprKind::Binary(op, ab) => {
            let (va, ta) = eval(&ab.0, env, d)?;
            let (vb, tb) = eval(&ab.1, env, d)?;
            binary(*op, &va, &ta, &vb, &tb).map_err(|msg| Diagnostic::error(msg, e.span))
        }
        ExprKind::Ternary(c, a, b) => match eval(c, env, d)? {
            (ConstValue::Bool(true), _) => eval(a, env, d),
            (ConstValue::Bool(false), _) => eval(b, env, d),
            _ => Err(not_const(e, "this condition")),
        },
        ExprKind::Call { callee, args } => {
            if let Some(why) = super::fold::never_constant(&callee.name) {
                return Err(Diagnostic::error(why, e.span));
            }
            let vals = args.iter().map(|a| eval(a, env, d)).collect::<Result<Vec<_>, _>>()?;
            if let Some(ty) = Ty::from_builtin_name(&callee.name) {
                return construct(&ty, vals).map(|v| (v, ty.clone())).ok_or_else(|| Diagnostic::error(format!("wrong arguments for `{}(...)` in a constant", callee.name), e.span));
            }
            if let Some((ty, fields)) = env.struct_type(&callee.name) {
                if fields.len() != vals.len() || fields.iter().zip(&vals).any(|(f, (_, t))| f != t) {
                    return Err(Diagnostic::error(format!("wrong arguments for `{}(...)` in a constant", callee.name), e.span));
                }
                return Ok((ConstValue::Composite(vals.into_iter().map(|v| v.0).collect()), ty));
            }
            if let Some((msg, help)) = super::types::unsupported_type(&callee.name) {
                return Err(Diagnostic::error(msg, callee.span).with_note(format!("help: {help}")));
            }
            // `length` of a fixed array: its type's length.
            if let ([(_, Ty::Array(_, n))], "length") = (vals.as_slice(), callee.name.as_str()) {
                return Ok((ConstValue::Int(*n as i64), INT));
            }
            // Builtin functions: `sema::fold`.
            if let Some(folded) = super::fold::call(&callee.name, &vals) {
                return folded.map_err(|msg| Diagnostic::error(msg, e.span).with_note("this call is evaluated at compile time"));
            }
            Err(not_const(e, &format!("a call of `{}`", callee.name)))
        }
        ExprKind::Array { items, .. } => {
            let vals = items.iter().map(|a| eval(a, env, d)).collect::<Result<Vec<_>, _>>()?;
            let Some(first) = vals.first().map(|v| v.1.clone()) else {
                return Err(Diagnostic::error("an empty array has no type", e.span));
            };
            if vals.iter().any(|v| v.1 != first) {
                return Err(Diagnostic::error("array elements have different types", e.span));
            }
            let n = vals.len() as u32;
            Ok((ConstValue::Composite(vals.into_iter().map(|v| v.0).collect()), Ty::Array(Box::new(first), n)))
        }
        ExprKind::Field(base, member) => match &base.kind {
            ExprKind::Name(ty) => env.enum_value(&ty.name, &member.name).ok_or_else(|| not_const(e, "field access")),
            _ => Err(not_const(e, "field access")),
        },
        ExprKind::Index(..) => Err(not_const(e, "element access")),
        ExprKind::Named(..) => Err(Diagnostic::error("a construction by field name is not supported in a top-level `let`", e.span)
            .with_note("help: give every field in order (`S(a, b)`), or construct it inside the function that uses it")),
        ExprKind::Str(_) => Err(Diagnostic::error("strings are not shader values", e.span)),
    }
}

/// `op v` on a constant; `None` where it does not apply or overflows
/// (`-(-2147483648)`).
pub fn unary(op: UnaryOp, v: &ConstValue) -> Option<ConstValue> {
    map_components(v, &mut |c| match (op, c) {
        (UnaryOp::Neg, ConstValue::Float(f)) => Some(ConstValue::Float(-f)),
        (UnaryOp::Neg, ConstValue::Int(i)) => (*i as i32).checked_neg().map(|n| ConstValue::Int(n as i64)),
        (UnaryOp::Plus, c) => Some(c.clone()),
        (UnaryOp::Not, ConstValue::Bool(b)) => Some(ConstValue::Bool(!b)),
        (UnaryOp::BitNot, ConstValue::Int(i)) => Some(ConstValue::Int(!(*i as i32) as i64)),
        (UnaryOp::BitNot, ConstValue::Uint(u)) => Some(ConstValue::Uint(!(*u as u32) as u64)),
        _ => None,
    })
}

/// Whether an error of [`binary`] means the operation is undefined (an
/// overflow, a division by zero, a non-finite result), rather than one the
/// constant folder does not do (matrix arithmetic, vector comparisons) or
/// operands it was not meant for.
pub fn is_undefined(msg: &str) -> bool {
    !msg.contains("not supported") && !msg.contains("mismatch")
}

/// Applies `f` to every scalar of a value.
fn map_components(v: &ConstValue, f: &mut dyn FnMut(&ConstValue) -> Option<ConstValue>) -> Option<ConstValue> {
    match v {
        ConstValue::Composite(cs) => cs.iter().map(|c| map_components(c, f)).collect::<Option<Vec<_>>>().map(ConstValue::Composite),
        c => f(c),
    }
}

fn scalars(v: &ConstValue) -> Vec<ConstValue> {
    match v {
        ConstValue::Composite(cs) => cs.iter().flat_map(scalars).collect(),
        c => vec![c.clone()],
    }
}

/// The scalars of a value, borrowed where they already lie flat (a scalar,
/// or a vector): the type checker folds every literal operation through
/// [`binary`].
fn flat_scalars(v: &ConstValue) -> Cow<'_, [ConstValue]> {
    match v {
        ConstValue::Composite(cs) if cs.iter().any(|c| matches!(c, ConstValue::Composite(_))) => Cow::Owned(scalars(v)),
        ConstValue::Composite(cs) => Cow::Borrowed(cs),
        c => Cow::Borrowed(std::slice::from_ref(c)),
    }
}

pub(crate) fn construct(ty: &Ty, vals: Vec<(ConstValue, Ty)>) -> Option<ConstValue> {
    if let (Ty::Matrix(c, r), [(m, Ty::Matrix(..))]) = (ty, vals.as_slice()) {
        return Some(super::fold::matrix_from_matrix(m, *c, *r));
    }
    // Every scalar of the arguments in one buffer, converted in place: the
    // folder constructs each constant vector of a shader this way.
    let single = vals.len() == 1;
    let mut flat: Vec<ConstValue> = Vec::with_capacity(vals.len());
    for (v, _) in vals {
        push_scalars(v, &mut flat);
    }
    let convert_all = |mut flat: Vec<ConstValue>, s: Scalar| -> Option<Vec<ConstValue>> {
        for c in flat.iter_mut() {
            *c = super::fold::convert(c, s)?;
        }
        Some(flat)
    };
    match *ty {
        Ty::Scalar(s) => (flat.len() == 1 && single).then(|| super::fold::convert(&flat[0], s)).flatten(),
        Ty::Vector(s, n) => {
            let n = n as usize;
            if flat.len() == 1 {
                let c = super::fold::convert(&flat[0], s)?;
                flat = vec![c; n];
            } else if single && flat.len() >= n {
                flat.truncate(n);
            } else if flat.len() != n {
                return None;
            }
            convert_all(flat, s).map(ConstValue::Composite)
        }
        Ty::Matrix(c, r) => {
            let (c, r) = (c as usize, r as usize);
            let flat: Vec<ConstValue> = if flat.len() == 1 {
                (0..c * r).map(|i| if i / r == i % r { flat[0].clone() } else { ConstValue::Float(0.0) }).collect()
            } else if flat.len() == c * r {
                flat
            } else {
                return None;
            };
            let flat = convert_all(flat, Scalar::Float)?;
            Some(ConstValue::Composite(flat.chunks(r).map(|col| ConstValue::Composite(col.to_vec())).collect()))
        }
        _ => None,
    }
}

/// Moves the scalars of `v` onto `out`, in order.
fn push_scalars(v: ConstValue, out: &mut Vec<ConstValue>) {
    match v {
        ConstValue::Composite(cs) => cs.into_iter().for_each(|c| push_scalars(c, out)),
        c => out.push(c),
    }
}

/// The result of folding one integer operation.
enum Folded<T> {
    /// The value, or `None` for overflow or division by zero.
    Value(Option<T>),
    /// A comparison.
    Bool(bool),
}

/// Folds `x op y` for one integer type (`i32` or `u32`); `None` when the
/// operator does not apply to integers.
macro_rules! fold_int {
    ($op:expr, $x:expr, $y:expr, $shift:expr) => {{
        let (x, y) = ($x, $y);
        match $op {
            Add => Some(Folded::Value(x.checked_add(y))),
            Sub => Some(Folded::Value(x.checked_sub(y))),
            Mul => Some(Folded::Value(x.checked_mul(y))),
            Div => Some(Folded::Value(x.checked_div(y))),
            Mod => Some(Folded::Value(x.checked_rem(y))),
            BitAnd => Some(Folded::Value(Some(x & y))),
            BitOr => Some(Folded::Value(Some(x | y))),
            BitXor => Some(Folded::Value(Some(x ^ y))),
            Shl => Some(Folded::Value(x.checked_shl($shift))),
            Shr => Some(Folded::Value(x.checked_shr($shift))),
            Eq => Some(Folded::Bool(x == y)),
            Ne => Some(Folded::Bool(x != y)),
            Lt => Some(Folded::Bool(x < y)),
            Le => Some(Folded::Bool(x <= y)),
            Gt => Some(Folded::Bool(x > y)),
            Ge => Some(Folded::Bool(x >= y)),
            _ => None,
        }
    }};
}

pub fn binary(op: BinaryOp, a: &ConstValue, ta: &Ty, b: &ConstValue, tb: &Ty) -> Result<(ConstValue, Ty), String> {
    use BinaryOp::*;
    let show = |t: &Ty| super::types::TyDisplay { ty: t, struct_names: &[], enum_names: &[] }.to_string();
    let mismatch = || format!("type mismatch in constant: `{}` and `{}` operands", show(ta), show(tb));
    if matches!(op, Shl | Shr) && ta.scalar().is_some_and(|s| s.is_integer()) && tb.scalar().is_some_and(|s| s.is_integer()) && (ta.width() == tb.width() || tb.width() == Some(1)) {
        // The amount may be int or uint; the result has the left operand's type.
        let amounts: Vec<i64> = scalars(b).iter().map(|c| match c {
            ConstValue::Int(i) => *i,
            ConstValue::Uint(u) => *u as i64,
            _ => -1,
        }).collect();
        let values = scalars(a);
        let mut out = Vec::new();
        for (i, v) in values.iter().enumerate() {
            let k = amounts[if amounts.len() == 1 { 0 } else { i }];
            if !(0..32).contains(&k) {
                return Err(format!("shift amount {k} is out of range (0..32) in constant: overflow"));
            }
            // WGSL refuses a constant `<<` that loses bits (for `int`, the
            // sign bit included: `1 << 31`), like an overflowing `*`.
            let lost = match (v, op) {
                (ConstValue::Int(x), Shl) => ((*x as i32) << k) >> k != *x as i32,
                (ConstValue::Uint(x), Shl) => ((*x as u32) << k) >> k != *x as u32,
                _ => false,
            };
            if lost {
                let shown = match v {
                    ConstValue::Uint(x) => format!("{x}u"),
                    ConstValue::Int(x) => x.to_string(),
                    _ => String::new(),
                };
                return Err(format!("`{shown} << {k}` overflows `{}` in constant: bits are shifted out", show(&Ty::Scalar(ta.scalar().unwrap_or(Scalar::Int)))));
            }
            out.push(match (v, op) {
                (ConstValue::Int(x), Shl) => ConstValue::Int(((*x as i32) << k) as i64),
                (ConstValue::Int(x), _) => ConstValue::Int(((*x as i32) >> k) as i64),
                (ConstValue::Uint(x), Shl) => ConstValue::Uint(((*x as u32) << k) as u64),
                (ConstValue::Uint(x), _) => ConstValue::Uint(((*x as u32) >> k) as u64),
                _ => return Err(mismatch()),
            });
        }
        let v = if out.len() == 1 { out.pop().expect("one component") } else { ConstValue::Composite(out) };
        return Ok((v, ta.clone()));
    }
    if matches!(ta, Ty::Matrix(..) | Ty::Array(..) | Ty::Struct(_)) || matches!(tb, Ty::Matrix(..) | Ty::Array(..) | Ty::Struct(_)) {
        return Err("matrix, array and struct arithmetic is not supported in constants".into());
    }
    if ta.scalar() != tb.scalar() {
        return Err(mismatch());
    }
    let (wa, wb) = (ta.width().unwrap_or(1), tb.width().unwrap_or(1));
    if wa != wb && wa != 1 && wb != 1 {
        return Err(mismatch());
    }
    let w = wa.max(wb) as usize;
    let sa = flat_scalars(a);
    let sb = flat_scalars(b);
    let get = |s: &[ConstValue], i: usize| if s.len() == 1 { s[0].clone() } else { s[i].clone() };
    let result_ty = if wa >= wb { ta.clone() } else { tb.clone() };
    let cmp = matches!(op, Eq | Ne | Lt | Le | Gt | Ge | And | Or | Xor);
    // `half` arithmetic rounds to binary16 (`sema::fold`).
    let is_half = ta.scalar() == Some(Scalar::Half);
    if cmp && w != 1 {
        return Err("vector comparisons are not supported in constants".into());
    }
    // One component at a time; a scalar result needs no vector.
    let fold = |x: ConstValue, y: ConstValue| -> Result<ConstValue, String> {
        Ok(match (x, y) {
            (ConstValue::Float(x), ConstValue::Float(y)) if is_half && !cmp => super::fold::half_op(op, x, y)?,
            (ConstValue::Float(x), ConstValue::Float(y)) => {
                // In f32, one rounding per operation, as the GPU computes.
                let (x, y) = (x as f32, y as f32);
                if matches!(op, Div | Mod) && y == 0.0 {
                    return Err("division by zero in constant".into());
                }
                let r = match op {
                    Add => x + y,
                    Sub => x - y,
                    Mul => x * y,
                    Div => x / y,
                    // GLSL mod: x - y * floor(x / y).
                    Mod => x - y * (x / y).floor(),
                    _ => 0.0,
                };
                if !r.is_finite() {
                    let what = if r.is_nan() { "NaN" } else { "infinite" };
                    return Err(format!(
                        "this constant is {what} in `float` ({x:?} {} {y:?}); constants must be finite: WGSL rejects non-finite constant expressions and naga non-finite literals",
                        crate::sema::op_text(op)
                    ));
                }
                let f = |v: f32| ConstValue::Float(v as f64);
                match op {
                    Add => f(x + y),
                    Sub => f(x - y),
                    Mul => f(x * y),
                    Div => f(x / y),
                    // GLSL mod: x - y * floor(x / y).
                    Mod => f(x - y * (x / y).floor()),
                    Eq => ConstValue::Bool(x == y),
                    Ne => ConstValue::Bool(x != y),
                    Lt => ConstValue::Bool(x < y),
                    Le => ConstValue::Bool(x <= y),
                    Gt => ConstValue::Bool(x > y),
                    Ge => ConstValue::Bool(x >= y),
                    _ => return Err(mismatch()),
                }
            }
            (ConstValue::Int(x), ConstValue::Int(y)) => match fold_int!(op, x as i32, y as i32, y as u32) {
                Some(Folded::Bool(b)) => ConstValue::Bool(b),
                Some(Folded::Value(v)) => ConstValue::Int(v.ok_or("integer overflow or division by zero in constant")? as i64),
                None => return Err(mismatch()),
            },
            (ConstValue::Uint(x), ConstValue::Uint(y)) => match fold_int!(op, x as u32, y as u32, y as u32) {
                Some(Folded::Bool(b)) => ConstValue::Bool(b),
                Some(Folded::Value(v)) => ConstValue::Uint(v.ok_or("integer overflow or division by zero in constant")? as u64),
                None => return Err(mismatch()),
            },
            (ConstValue::Bool(x), ConstValue::Bool(y)) => match op {
                And => ConstValue::Bool(x && y),
                Or => ConstValue::Bool(x || y),
                Xor | Ne => ConstValue::Bool(x != y),
                Eq => ConstValue::Bool(x == y),
                _ => return Err(mismatch()),
            },
            _ => return Err(mismatch()),
        })
    };
    if w == 1 {
        let v = fold(get(&sa, 0), get(&sb, 0))?;
        return Ok((v, if cmp { BOOL } else { result_ty }));
    }
    // `cmp` with vectors was rejected above.
    let out = (0..w).map(|i| fold(get(&sa, i), get(&sb, i))).collect::<Result<Vec<_>, _>>()?;
    Ok((ConstValue::Composite(out), result_ty))
}

// ---------------------------------------------------------------- builtin calls on constants
//
// The rules for what a builtin call on constant arguments means, in one
// place: the checker's pass over function bodies (`check/folding.rs`)
// uses them for every constant subexpression, and top-level constants can
// use them for their initialisers. A call whose result is undefined in
// GLSL or an error in WGSL (which evaluates constant expressions when it
// reads a shader, with naga's front end as one consumer) is an error here,
// so that every target means the same: docs/language.md, "Constant
// expressions".

/// Why a constant builtin call has no value: the message of a compile error.
pub type Undefined = String;

/// The value of builtin `b` called with constant arguments (`args`: the
/// values and their types; `ret`: the call's type). `Ok(None)`: umbrac
/// does not evaluate this builtin (textures, derivatives, matrix functions),
/// so the call is left to the targets; `Err`: the call is undefined for
/// these arguments.
pub fn eval_builtin(b: super::builtins::Builtin, args: &[(&ConstValue, &Ty)], ret: &Ty) -> Result<Option<ConstValue>, Undefined> {
    let value = builtin_value(b, args, ret)?;
    // A finite value may still be reached through steps WGSL computes in
    // `float` past its range (matrices included).
    let vals: arrayvec::ArrayVec<&ConstValue, 4> = args.iter().take(4).map(|a| a.0).collect();
    super::fold::wgsl_steps(super::builtins::name_of(b), b, &vals)?;
    Ok(value)
}

fn builtin_value(b: super::builtins::Builtin, args: &[(&ConstValue, &Ty)], ret: &Ty) -> Result<Option<ConstValue>, Undefined> {
    use super::builtins::Builtin as B;
    use naga::MathFunction as M;
    let name = super::builtins::name_of(b);
    // A component of argument `k` (a scalar argument is broadcast).
    let comp = |k: usize, i: usize| -> ConstValue {
        match args[k].0 {
            ConstValue::Composite(cs) => cs.get(i).cloned().unwrap_or(ConstValue::Bool(false)),
            c => c.clone(),
        }
    };
    let width = |t: &Ty| t.width().unwrap_or(1) as usize;
    if args.iter().any(|(_, t)| matches!(t, Ty::Matrix(..) | Ty::Array(..) | Ty::Struct(_) | Ty::Sampler(_))) {
        return Ok(None);
    }
    let f = |c: &ConstValue| match *c {
        ConstValue::Float(x) => x as f32,
        _ => f32::NAN,
    };
    let out = |v: Vec<ConstValue>| if v.len() == 1 { v.into_iter().next().expect("one") } else { ConstValue::Composite(v) };
    let finite = |x: f32, what: &str| -> Result<ConstValue, Undefined> {
        if x.is_finite() {
            Ok(ConstValue::Float(x as f64))
        } else {
            Err(format!("`{name}` {what} is {} in `float`", if x.is_nan() { "NaN" } else { "infinite" }))
        }
    };
    let w = width(ret).max(args.iter().map(|(_, t)| width(t)).max().unwrap_or(1));
    match b {
        B::Math(m @ (M::Length | M::Distance | M::Dot | M::Normalize | M::Cross | M::Reflect | M::Refract | M::FaceForward)) => {
            let v = |k: usize| (0..width(args[k].1)).map(|i| f(&comp(k, i))).collect::<Vec<f32>>();
            let dot = |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f32>();
            let vec_out = |xs: Vec<f32>, what: &str| xs.into_iter().map(|x| finite(x, what)).collect::<Result<Vec<_>, _>>().map(out);
            let r = match m {
                M::Length => finite(dot(&v(0), &v(0)).sqrt(), "of this value")?,
                M::Distance => {
                    let d: Vec<f32> = v(0).iter().zip(v(1)).map(|(a, b)| a - b).collect();
                    finite(dot(&d, &d).sqrt(), "of these values")?
                }
                M::Dot => finite(dot(&v(0), &v(1)), "of these vectors")?,
                M::Normalize => {
                    let a = v(0);
                    let len = dot(&a, &a).sqrt();
                    if len == 0.0 {
                        return Err("`normalize` of a zero vector is undefined (it divides by its length, 0)".into());
                    }
                    vec_out(a.iter().map(|x| x / len).collect(), "of this vector")?
                }
                M::Cross => {
                    let (a, b) = (v(0), v(1));
                    vec_out(vec![a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]], "of these vectors")?
                }
                M::Reflect => {
                    let (i, n) = (v(0), v(1));
                    let k = 2.0 * dot(&n, &i);
                    vec_out(i.iter().zip(&n).map(|(i, n)| i - k * n).collect(), "of these vectors")?
                }
                M::Refract => {
                    let (i, n, eta) = (v(0), v(1), f(args[2].0));
                    let d = dot(&n, &i);
                    let k = 1.0 - eta * eta * (1.0 - d * d);
                    if k < 0.0 {
                        vec_out(vec![0.0; i.len()], "of these vectors")?
                    } else {
                        vec_out(i.iter().zip(&n).map(|(i, n)| eta * i - (eta * d + k.sqrt()) * n).collect(), "of these vectors")?
                    }
                }
                M::FaceForward => {
                    let (n, i, nref) = (v(0), v(1), v(2));
                    let s = if dot(&nref, &i) < 0.0 { 1.0 } else { -1.0 };
                    vec_out(n.iter().map(|x| s * x).collect(), "of these vectors")?
                }
                _ => unreachable!("matched above"),
            };
            Ok(Some(r))
        }
        B::Math(M::Transpose | M::Determinant | M::Inverse) | B::Inverse | B::Derivative(..) => Ok(None),
        B::Math(m) => {
            let mut cs = Vec::with_capacity(w);
            for i in 0..w {
                let a: Vec<ConstValue> = (0..args.len()).map(|k| comp(k, i)).collect();
                cs.push(math_component(m, name, &a)?);
            }
            Ok(Some(out(cs)))
        }
        B::Saturate => (0..w).map(|i| finite(f(&comp(0, i)).clamp(0.0, 1.0), "of this value")).collect::<Result<Vec<_>, _>>().map(|v| Some(out(v))),
        B::Rcp => (0..w)
            .map(|i| {
                let x = f(&comp(0, i));
                if x == 0.0 {
                    Err("`rcp(0.0)` divides by zero".into())
                } else {
                    finite(1.0 / x, "of this value")
                }
            })
            .collect::<Result<Vec<_>, _>>()
            .map(|v| Some(out(v))),
        B::Mod => (0..w)
            .map(|i| {
                let (x, y) = (f(&comp(0, i)), f(&comp(1, i)));
                if y == 0.0 {
                    Err("`mod(x, 0.0)` divides by zero".into())
                } else {
                    finite(x - y * (x / y).floor(), "of these values")
                }
            })
            .collect::<Result<Vec<_>, _>>()
            .map(|v| Some(out(v))),
        B::Any | B::All => {
            let bs: Vec<bool> = (0..width(args[0].1)).map(|i| comp(0, i) == ConstValue::Bool(true)).collect();
            Ok(Some(ConstValue::Bool(if b == B::Any { bs.iter().any(|&x| x) } else { bs.iter().all(|&x| x) })))
        }
        B::Not => Ok(Some(out((0..w).map(|i| ConstValue::Bool(comp(0, i) != ConstValue::Bool(true))).collect()))),
        B::Compare(op) => {
            let mut cs = Vec::with_capacity(w);
            for i in 0..w {
                let (x, y) = (comp(0, i), comp(1, i));
                let s = args[0].1.scalar().map(Ty::Scalar).unwrap_or(BOOL);
                match binary(op, &x, &s, &y, &s) {
                    Ok((v, _)) => cs.push(v),
                    Err(_) => return Ok(None),
                }
            }
            Ok(Some(out(cs)))
        }
        B::Bitcast(to) => {
            let mut cs = Vec::with_capacity(w);
            for i in 0..w {
                let bits = match comp(0, i) {
                    ConstValue::Float(x) => (x as f32).to_bits(),
                    ConstValue::Int(x) => x as i32 as u32,
                    ConstValue::Uint(x) => x as u32,
                    _ => return Ok(None),
                };
                cs.push(match to {
                    Scalar::Int => ConstValue::Int(bits as i32 as i64),
                    Scalar::Uint => ConstValue::Uint(bits as u64),
                    Scalar::Float => {
                        let x = f32::from_bits(bits);
                        if !x.is_finite() {
                            return Err(format!("`{name}` of 0x{bits:08X} is {} in `float`, which WGSL rejects as a constant", if x.is_nan() { "NaN" } else { "infinite" }));
                        }
                        ConstValue::Float(x as f64)
                    }
                    // 32 bits are no `half`; left to the target.
                    Scalar::Half | Scalar::Bool => return Ok(None),
                });
            }
            Ok(Some(out(cs)))
        }
        _ => Ok(None),
    }
}

/// One component of a component-wise math builtin on constants.
fn math_component(m: naga::MathFunction, name: &str, a: &[ConstValue]) -> Result<ConstValue, Undefined> {
    use naga::MathFunction as M;
    let show = |c: &ConstValue| match *c {
        ConstValue::Float(x) => format!("{:?}", x as f32),
        ConstValue::Int(x) => x.to_string(),
        ConstValue::Uint(x) => format!("{x}u"),
        ConstValue::Bool(x) => x.to_string(),
        ConstValue::Composite(_) => "...".into(),
    };
    let call = || format!("`{name}({})`", a.iter().map(show).collect::<Vec<_>>().join(", "));
    let undefined = |why: &str| Err(format!("{} is undefined: {why}", call()));
    // Integer forms: abs, sign, min, max, clamp.
    if let Some(ints) = a.iter().map(|c| match *c {
        ConstValue::Int(x) => Some(x as i32 as i64),
        ConstValue::Uint(x) => Some(x as u32 as i64),
        _ => None,
    }).collect::<Option<Vec<i64>>>() {
        let unsigned = matches!(a[0], ConstValue::Uint(_));
        let r = match m {
            M::Abs if ints[0] == i32::MIN as i64 && !unsigned => return Err(format!("{} overflows `int`", call())),
            M::Abs => ints[0].abs(),
            M::Sign => ints[0].signum(),
            M::Min => ints[0].min(ints[1]),
            M::Max => ints[0].max(ints[1]),
            M::Clamp if ints[1] > ints[2] => return undefined("the lower bound is greater than the upper bound"),
            M::Clamp => ints[0].clamp(ints[1], ints[2]),
            _ => return Err(format!("{} has no integer form", call())),
        };
        return Ok(if unsigned { ConstValue::Uint(r as u64) } else { ConstValue::Int(r) });
    }
    let x: Vec<f32> = a.iter().map(|c| match *c {
        ConstValue::Float(v) => v as f32,
        _ => f32::NAN,
    }).collect();
    let r = match m {
        M::Sin => x[0].sin(),
        M::Cos => x[0].cos(),
        M::Tan => x[0].tan(),
        M::Asin | M::Acos if x[0].abs() > 1.0 => return undefined("its argument must lie in [-1, 1]"),
        M::Asin => x[0].asin(),
        M::Acos => x[0].acos(),
        M::Atan => x[0].atan(),
        M::Atan2 if x[0] == 0.0 && x[1] == 0.0 => return undefined("GLSL leaves `atan(0, 0)` undefined"),
        M::Atan2 => x[0].atan2(x[1]),
        M::Sinh => x[0].sinh(),
        M::Cosh => x[0].cosh(),
        M::Tanh => x[0].tanh(),
        M::Radians => x[0].to_radians(),
        M::Degrees => x[0].to_degrees(),
        M::Exp => x[0].exp(),
        M::Exp2 => x[0].exp2(),
        M::Log | M::Log2 if x[0] <= 0.0 => return undefined("its argument must be greater than 0"),
        M::Log => x[0].ln(),
        M::Log2 => x[0].log2(),
        M::Sqrt if x[0] < 0.0 => return undefined("its argument must not be negative"),
        M::Sqrt => x[0].sqrt(),
        M::InverseSqrt if x[0] <= 0.0 => return undefined("its argument must be greater than 0"),
        M::InverseSqrt => 1.0 / x[0].sqrt(),
        M::Floor => x[0].floor(),
        M::Ceil => x[0].ceil(),
        M::Fract => x[0] - x[0].floor(),
        M::Trunc => x[0].trunc(),
        M::Round => x[0].round_ties_even(),
        M::Abs => x[0].abs(),
        M::Sign => {
            if x[0] == 0.0 {
                0.0
            } else {
                x[0].signum()
            }
        }
        M::Min => x[0].min(x[1]),
        M::Max => x[0].max(x[1]),
        M::Clamp if x[1] > x[2] => return undefined("the lower bound is greater than the upper bound"),
        M::Clamp => x[0].clamp(x[1], x[2]),
        M::Mix => x[0] * (1.0 - x[2]) + x[1] * x[2],
        M::Step => {
            if x[1] < x[0] {
                0.0
            } else {
                1.0
            }
        }
        M::SmoothStep if x[0] >= x[1] => return undefined("GLSL leaves `smoothstep` undefined unless edge0 < edge1"),
        M::SmoothStep => {
            let t = ((x[2] - x[0]) / (x[1] - x[0])).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        }
        M::Pow if x[0] < 0.0 => return undefined("the base must not be negative"),
        M::Pow if x[0] == 0.0 && x[1] <= 0.0 => return undefined("a zero base needs a positive exponent"),
        M::Pow => x[0].powf(x[1]),
        M::Fma => x[0].mul_add(x[1], x[2]),
        _ => return Err(format!("{} cannot be evaluated when compiling", call())),
    };
    if !r.is_finite() {
        return Err(format!("{} is {} in `float`", call(), if r.is_nan() { "NaN" } else { "infinite" }));
    }
    Ok(ConstValue::Float(r as f64))
}
