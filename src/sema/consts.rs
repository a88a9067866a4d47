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
        ExprKind::Paren(x) => eval(x, env, d),
        ExprKind::Name(id) => env.lookup(&id.name).ok_or_else(|| not_const(e, &format!("`{}`", id.name))),
        ExprKind::Unary(op, x) => {
            if let (UnaryOp::Neg, ExprKind::Int(2147483648, IntSuffix::None)) = (op, &x.kind) {
                return Ok((ConstValue::Int(i32::MIN as i64), INT));
            }
            let (v, ty) = eval(x, env, d)?;
            let r = map_components(&v, &mut |c| match (op, c) {
                (UnaryOp::Neg, ConstValue::Float(f)) => Some(ConstValue::Float(-f)),
                (UnaryOp::Neg, ConstValue::Int(i)) => (*i as i32).checked_neg().map(|n| ConstValue::Int(n as i64)),
                (UnaryOp::Plus, c) => Some(c.clone()),
                (UnaryOp::Not, ConstValue::Bool(b)) => Some(ConstValue::Bool(!b)),
                (UnaryOp::BitNot, ConstValue::Int(i)) => Some(ConstValue::Int(!(*i as i32) as i64)),
                (UnaryOp::BitNot, ConstValue::Uint(u)) => Some(ConstValue::Uint(!(*u as u32) as u64)),
                _ => None,
            });
            r.map(|v| (v, ty)).ok_or_else(|| not_const(e, "this operation"))
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

/// A scalar conversion as the constructors `float(x)`, `int(x)`, `uint(x)`,
/// `bool(x)` define it: int <-> uint keep the bits (two's complement);
/// float -> int/uint truncates toward zero after clamping to the largest
/// f32 values inside the type's range (2147483520.0, 4294967040.0; what
/// WGSL defines and naga's WGSL and SPIR-V outputs compute; GLSL leaves
/// out-of-range conversions undefined); to float rounds to nearest f32;
/// to bool is `!= 0`.
pub fn convert(c: &ConstValue, to: Scalar) -> Option<ConstValue> {
    let f = match *c {
        ConstValue::Float(f) => f,
        ConstValue::Int(i) => i as f64,
        ConstValue::Uint(u) => u as f64,
        ConstValue::Bool(b) => b as u8 as f64,
        ConstValue::Composite(_) => return None,
    };
    Some(match to {
        Scalar::Float => ConstValue::Float(f as f32 as f64),
        Scalar::Int => ConstValue::Int(match *c {
            ConstValue::Uint(u) => u as u32 as i32 as i64,
            // WGSL: clamp to the f32 values that fit, then truncate.
            _ => (f as f32).clamp(-2147483648.0, 2147483520.0) as i32 as i64,
        }),
        Scalar::Uint => ConstValue::Uint(match *c {
            ConstValue::Int(i) => i as i32 as u32 as u64,
            _ => (f as f32).clamp(0.0, 4294967040.0) as u32 as u64,
        }),
        Scalar::Bool => ConstValue::Bool(f != 0.0),
        // Rounded once, to nearest even (from an f32 value or an integer).
        Scalar::Half => ConstValue::Float(half::f16::from_f64(f).to_f64()),
    })
}

fn construct(ty: &Ty, vals: Vec<(ConstValue, Ty)>) -> Option<ConstValue> {
    let flat: Vec<ConstValue> = vals.iter().flat_map(|v| scalars(&v.0)).collect();
    match *ty {
        Ty::Scalar(s) => (flat.len() == 1 && vals.len() == 1).then(|| convert(&flat[0], s)).flatten(),
        Ty::Vector(s, n) => {
            let n = n as usize;
            let comps: Vec<ConstValue> = if flat.len() == 1 {
                vec![flat[0].clone(); n]
            } else if vals.len() == 1 && flat.len() >= n {
                flat[..n].to_vec()
            } else if flat.len() == n {
                flat
            } else {
                return None;
            };
            comps.iter().map(|c| convert(c, s)).collect::<Option<Vec<_>>>().map(ConstValue::Composite)
        }
        Ty::Matrix(c, r) => {
            if let [(m, Ty::Matrix(..))] = vals.as_slice() {
                return Some(super::fold::matrix_from_matrix(m, c, r));
            }
            let (c, r) = (c as usize, r as usize);
            let flat: Vec<ConstValue> = if flat.len() == 1 {
                (0..c * r).map(|i| if i / r == i % r { flat[0].clone() } else { ConstValue::Float(0.0) }).collect()
            } else if flat.len() == c * r {
                flat
            } else {
                return None;
            };
            let flat = flat.iter().map(|x| convert(x, Scalar::Float)).collect::<Option<Vec<_>>>()?;
            Some(ConstValue::Composite(flat.chunks(r).map(|col| ConstValue::Composite(col.to_vec())).collect()))
        }
        _ => None,
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
