//! Compile-time evaluation of builtin calls in constant expressions:
//! `let SUN = normalize(float3(0.45, 0.55, 0.85))`, `PI / 180.0 * x`.
//!
//! A folded constant is written into every output as the same literal, so
//! it has the same bits on every target. Each float function is computed
//! in `f64` from its `f32` arguments (transcendental functions through
//! `libm`, the same on every host) and rounded once to `f32`: the value the
//! exact function rounds to, or within an ulp of it; a GPU computing the
//! same call at run time is only as accurate as its own library. Operations
//! GLSL defines step by step (`fract`, `mod`, `rcp`) are computed that way,
//! in `f32`. A call that is undefined on some target, or infinite or NaN,
//! is an error, as for the operators (`consts`): `sqrt(-1.0)`,
//! `log(0.0)`, `pow(-2.0, 0.5)`, `atan2(0.0, 0.0)`, `clamp(x, 1.0, 0.0)`,
//! `normalize(float3(0.0))`.

use super::builtins::{self, Builtin};
use super::tree::ConstValue;
use super::types::{Scalar, Ty, TyDisplay};
use crate::syntax::ast::BinaryOp;
use naga::MathFunction as Mf;

type Folded = Result<(ConstValue, Ty), String>;

/// Why a call of builtin `name` is never a constant, whatever its
/// arguments (a texture read, a derivative).
pub fn never_constant(name: &str) -> Option<String> {
    if builtins::TEXTURE_FUNCTIONS.iter().any(|(n, _)| *n == name) || builtins::LEGACY_TEXTURE_FUNCTIONS.iter().any(|(n, ..)| *n == name) {
        return Some(format!("`{name}` reads a texture when the shader runs, so it is not a constant expression"));
    }
    matches!(name, "dFdx" | "dFdy" | "fwidth").then(|| format!("`{name}` is a derivative across pixels, so it is not a constant expression"))
}

/// The value of builtin `name` called with constant `args`; `None` when
/// `name` is no builtin function.
pub fn call(name: &str, args: &[(ConstValue, Ty)]) -> Option<Folded> {
    if let Some(why) = never_constant(name) {
        return Some(Err(why));
    }
    let (b, ret) = match builtins::resolve(name, args.iter().map(|a| &a.1)) {
        Ok(Some(found)) => found,
        Ok(None) => return None,
        Err(sigs) => {
            let given: Vec<String> = args.iter().map(|a| show(&a.1)).collect();
            return Some(Err(format!("no overload of `{name}` takes ({}); expected one of: {}", given.join(", "), sigs.join(", "))));
        }
    };
    let vals: Vec<&ConstValue> = args.iter().map(|a| &a.0).collect();
    let tys: Vec<&Ty> = args.iter().map(|a| &a.1).collect();
    let value = eval(name, b, &vals, &tys, &ret).and_then(|v| wgsl_steps(name, b, &vals).map(|()| v));
    // A `half` result: each component rounded (once more) to binary16.
    let value = if ret.has_half(&[]) { value.and_then(|v| to_half(name, &v)) } else { value };
    Some(value.map(|v| (v, ret)))
}

/// Whether `x`, computed as an `f32` operation, overflows.
fn past_f32(x: f64) -> bool {
    !(x as f32).is_finite()
}

/// The first of the products and partial sums of `a . b` past f32's range.
fn dot_steps(a: &[f64], b: &[f64]) -> Option<f64> {
    let mut sum = 0.0;
    for (x, y) in a.iter().zip(b) {
        let p = x * y;
        sum += p;
        if past_f32(p) {
            return Some(p);
        }
        if past_f32(sum) {
            return Some(sum);
        }
    }
    None
}

/// The first component of `hi - lo` past f32's range.
pub fn difference_past_f32(lo: &ConstValue, hi: &ConstValue) -> Option<f64> {
    let (lo, hi) = (floats(lo), floats(hi));
    (0..lo.len().max(hi.len())).map(|i| hi[i.min(hi.len() - 1)] - lo[i.min(lo.len() - 1)]).find(|d| past_f32(*d))
}

/// The first product or sum of a cofactor expansion of the determinant
/// past f32's range.
fn determinant_steps(m: &[Vec<f64>]) -> Option<f64> {
    if m.len() == 1 {
        return None;
    }
    let mut sum = 0.0;
    for row in 0..m.len() {
        let minor: Vec<Vec<f64>> = m[1..].iter().map(|c| c.iter().enumerate().filter(|(r, _)| *r != row).map(|(_, x)| *x).collect()).collect();
        if let Some(x) = determinant_steps(&minor) {
            return Some(x);
        }
        let p = m[0][row] * determinant(&minor);
        sum += p;
        if past_f32(p) || past_f32(sum) {
            return Some(if past_f32(p) { p } else { sum });
        }
    }
    None
}

/// Refuses a call whose value is finite but which WGSL evaluates (as a
/// constant expression, in `f32`) through a step past f32's range: tint
/// rejects the shader (`dot` inside `normalize(float3(3e38, 3e38, 0.0))`,
/// `edge1 - edge0` of `smoothstep(-3e38, 3e38, x)`, the products of
/// `determinant(float2x2(1e20))`).
pub(super) fn wgsl_steps(name: &str, b: Builtin, v: &[&ConstValue]) -> Result<(), String> {
    let diffs = |a: &ConstValue, c: &ConstValue| floats(a).iter().zip(floats(c)).map(|(x, y)| x - y).collect::<Vec<f64>>();
    let step = match b {
        Builtin::Math(Mf::Dot) => dot_steps(&floats(v[0]), &floats(v[1])),
        Builtin::Math(Mf::Length | Mf::Normalize) | Builtin::LengthSq | Builtin::InvLength | Builtin::InvLengthSq => dot_steps(&floats(v[0]), &floats(v[0])),
        Builtin::Math(Mf::Distance) | Builtin::DistanceSq | Builtin::InvDistance | Builtin::InvDistanceSq => {
            let d = diffs(v[0], v[1]);
            d.iter().copied().find(|x| past_f32(*x)).or_else(|| dot_steps(&d, &d))
        }
        Builtin::Math(Mf::Reflect | Mf::Refract) => dot_steps(&floats(v[1]), &floats(v[0])),
        Builtin::Math(Mf::FaceForward) => dot_steps(&floats(v[2]), &floats(v[1])),
        Builtin::Math(Mf::Determinant) | Builtin::Inverse => determinant_steps(&columns(v[0])),
        Builtin::Math(Mf::SmoothStep) => difference_past_f32(v[0], v[1]),
        _ => None,
    };
    match step {
        Some(x) => Err(format!("`{name}` computes {x:e} on the way to its value, past the range of `float` (WGSL evaluates a constant call step by step in `float` and rejects it)")),
        None => Ok(()),
    }
}

fn to_half(name: &str, v: &ConstValue) -> Result<ConstValue, String> {
    match v {
        ConstValue::Composite(cs) => cs.iter().map(|c| to_half(name, c)).collect::<Result<_, _>>().map(ConstValue::Composite),
        ConstValue::Float(f) => {
            let h = half::f16::from_f64(*f);
            if h.is_finite() {
                Ok(ConstValue::Float(h.to_f64()))
            } else {
                Err(format!("`{name}` is infinite in `half` here (largest 65504); constants must be finite"))
            }
        }
        c => Ok(c.clone()),
    }
}

fn show(ty: &Ty) -> String {
    TyDisplay { ty, struct_names: &[], enum_names: &[] }.to_string()
}

fn eval(name: &str, b: Builtin, v: &[&ConstValue], tys: &[&Ty], ret: &Ty) -> Result<ConstValue, String> {
    let n = ret.width().unwrap_or(1) as usize;
    let float = |x: &ConstValue| match *x {
        ConstValue::Float(f) => f,
        _ => f64::NAN,
    };
    match b {
        Builtin::Math(f @ (Mf::Dot | Mf::Length | Mf::Distance)) => {
            let r = match f {
                Mf::Dot => dot(&floats(v[0]), &floats(v[1])),
                Mf::Length => dot(&floats(v[0]), &floats(v[0])).sqrt(),
                _ => length_of_difference(v),
            };
            finite(name, r)
        }
        Builtin::LengthSq => finite(name, dot(&floats(v[0]), &floats(v[0]))),
        Builtin::DistanceSq => finite(name, length_of_difference(v).powi(2)),
        Builtin::InvLength => finite(name, 1.0 / dot(&floats(v[0]), &floats(v[0])).sqrt()),
        Builtin::InvLengthSq => finite(name, 1.0 / dot(&floats(v[0]), &floats(v[0]))),
        Builtin::InvDistance => finite(name, 1.0 / length_of_difference(v)),
        Builtin::InvDistanceSq => finite(name, 1.0 / length_of_difference(v).powi(2)),
        Builtin::Math(Mf::Cross) => {
            let (a, c) = (floats(v[0]), floats(v[1]));
            vector_of(name, &[a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]])
        }
        Builtin::Math(Mf::Normalize) => {
            let x = floats(v[0]);
            let len = dot(&x, &x).sqrt();
            if len == 0.0 {
                return Err(format!("`{name}` of a zero vector is undefined (NaN on the GPU)"));
            }
            vector_of(name, &x.iter().map(|c| c / len).collect::<Vec<_>>())
        }
        Builtin::Math(Mf::Reflect) => {
            let (i, nn) = (floats(v[0]), floats(v[1]));
            let d = dot(&nn, &i);
            vector_of(name, &i.iter().zip(&nn).map(|(i, n)| i - 2.0 * d * n).collect::<Vec<_>>())
        }
        Builtin::Math(Mf::Refract) => {
            let (i, nn, eta) = (floats(v[0]), floats(v[1]), float(v[2]));
            let d = dot(&nn, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            if k < 0.0 {
                return vector_of(name, &vec![0.0; i.len()]);
            }
            vector_of(name, &i.iter().zip(&nn).map(|(i, n)| eta * i - (eta * d + k.sqrt()) * n).collect::<Vec<_>>())
        }
        Builtin::Math(Mf::FaceForward) => {
            let (nn, i, nref) = (floats(v[0]), floats(v[1]), floats(v[2]));
            let sign = if dot(&nref, &i) < 0.0 { 1.0 } else { -1.0 };
            vector_of(name, &nn.iter().map(|n| sign * n).collect::<Vec<_>>())
        }
        Builtin::Math(Mf::Transpose) => {
            let cols = columns(v[0]);
            let (c, r) = (cols.len(), cols[0].len());
            Ok(matrix((0..r).map(|i| (0..c).map(|j| cols[j][i]).collect()).collect()))
        }
        Builtin::Math(Mf::Determinant) => finite(name, determinant(&columns(v[0]))),
        Builtin::Inverse => {
            let m = columns(v[0]);
            let det = determinant(&m);
            if det == 0.0 {
                return Err(format!("`{name}` of a singular matrix (determinant 0) is undefined"));
            }
            let k = m.len();
            // Column j of the inverse: the cofactors of row j, over the determinant.
            let inv: Vec<Vec<f64>> = (0..k).map(|j| (0..k).map(|i| cofactor(&m, j, i) / det).collect()).collect();
            for x in inv.iter().flatten() {
                finite(name, *x)?;
            }
            Ok(matrix(inv))
        }
        Builtin::Identity => {
            let Ty::Matrix(k, _) = *ret else { unreachable!("identities are square matrices") };
            let k = k as usize;
            Ok(matrix((0..k).map(|i| (0..k).map(|j| if i == j { 1.0 } else { 0.0 }).collect()).collect()))
        }
        Builtin::Any | Builtin::All => {
            let bs = bools(v[0]);
            Ok(ConstValue::Bool(if b == Builtin::Any { bs.iter().any(|b| *b) } else { bs.iter().all(|b| *b) }))
        }
        Builtin::Not => Ok(ConstValue::Composite(bools(v[0]).into_iter().map(|b| ConstValue::Bool(!b)).collect())),
        Builtin::Compare(op) => {
            let (a, c) = (components(v[0]), components(v[1]));
            let out = a.iter().zip(&c).map(|(x, y)| compare(op, x, y)).collect::<Option<Vec<bool>>>().ok_or_else(|| format!("`{name}` cannot compare these values"))?;
            Ok(ConstValue::Composite(out.into_iter().map(ConstValue::Bool).collect()))
        }
        Builtin::Bitcast(to) => {
            let out: Vec<ConstValue> = components(v[0])
                .iter()
                .map(|c| match (c, to) {
                    (ConstValue::Float(f), Scalar::Int) => Ok(ConstValue::Int((*f as f32).to_bits() as i32 as i64)),
                    (ConstValue::Float(f), _) => Ok(ConstValue::Uint((*f as f32).to_bits() as u64)),
                    (ConstValue::Int(i), _) => finite_f32(name, f32::from_bits(*i as i32 as u32)),
                    (ConstValue::Uint(u), _) => finite_f32(name, f32::from_bits(*u as u32)),
                    _ => Err(format!("`{name}` cannot convert this value")),
                })
                .collect::<Result<_, _>>()?;
            Ok(rebuild(out))
        }
        Builtin::ToInt(f) => {
            let rounded: Vec<ConstValue> = floats(v[0]).iter().map(|x| ConstValue::Float(unary(f, *x))).collect();
            let out = rounded.iter().map(|c| convert(c, Scalar::Int)).collect::<Option<Vec<_>>>().ok_or_else(|| format!("`{name}` cannot convert this value"))?;
            Ok(rebuild(out))
        }
        Builtin::Hash => Ok(ConstValue::Uint(noise_hash(uint(v[0]), None) as u64)),
        Builtin::Noise => {
            let p = ints(v[0]);
            let primes = [1u32, 198_491_317, 6_542_989];
            let position = p.iter().zip(primes).fold(0u32, |acc, (c, k)| acc.wrapping_add(k.wrapping_mul(*c as i32 as u32)));
            Ok(ConstValue::Uint(noise_hash(position, Some(uint(v[1]))) as u64))
        }
        Builtin::Pack(f) => pack(name, f, v[0]),
        Builtin::Mod => component_wise(name, n, v, |x| Ok(float_mod(x[0], x[1]))),
        Builtin::Rcp => component_wise(name, n, v, |x| Ok(((1.0f32) / (x[0] as f32)) as f64)),
        Builtin::Saturate => component_wise(name, n, v, |x| Ok(x[0].clamp(0.0, 1.0))),
        Builtin::Mad if !tys[0].scalar().is_some_and(Scalar::is_float) => int_component_wise(name, n, v, |x| x[0].checked_mul(x[1]).and_then(|p| p.checked_add(x[2]))),
        Builtin::Mad => component_wise(name, n, v, |x| Ok(x[0] * x[1] + x[2])),
        Builtin::Math(f) if !tys[0].scalar().is_some_and(Scalar::is_float) => match f {
            Mf::Abs => int_component_wise(name, n, v, |x| x[0].checked_abs()),
            Mf::Sign => int_component_wise(name, n, v, |x| Some(x[0].signum())),
            Mf::Min => int_component_wise(name, n, v, |x| Some(x[0].min(x[1]))),
            Mf::Max => int_component_wise(name, n, v, |x| Some(x[0].max(x[1]))),
            Mf::Clamp => {
                if let Some(msg) = clamp_bounds_wrong(name, n, v) {
                    return Err(msg);
                }
                int_component_wise(name, n, v, |x| Some(x[0].max(x[1]).min(x[2])))
            }
            _ => Err(format!("`{name}` is not a constant expression here")),
        },
        Builtin::Math(Mf::Clamp) => {
            if let Some(msg) = clamp_bounds_wrong(name, n, v) {
                return Err(msg);
            }
            component_wise(name, n, v, |x| Ok(x[0].max(x[1]).min(x[2])))
        }
        Builtin::Math(f) => component_wise(name, n, v, |x| float_function(name, f, x)),
        Builtin::Derivative(..) => Err(format!("`{name}` is a derivative across pixels, so it is not a constant expression")),
        _ => Err(format!("`{name}` is not a constant expression")),
    }
}

/// A float function of daslang or GLSL applied to one component's
/// arguments, in `f64`; `Err` where it is undefined.
fn float_function(name: &str, f: Mf, x: &[f64]) -> Result<f64, String> {
    let undefined = |why: &str| Err(format!("`{name}` is undefined {why} (GLSL leaves it undefined; WGSL rejects it in a constant, and gives NaN at run time)"));
    Ok(match f {
        Mf::Sqrt if x[0] < 0.0 => return undefined(&format!("for the negative argument {}", x[0])),
        Mf::InverseSqrt if x[0] <= 0.0 => return undefined(&format!("for the argument {}, which is not positive", x[0])),
        Mf::Log | Mf::Log2 if x[0] <= 0.0 => return undefined(&format!("for the argument {}, which is not positive", x[0])),
        Mf::Asin | Mf::Acos if x[0].abs() > 1.0 => return undefined(&format!("for {}, outside [-1, 1]", x[0])),
        Mf::Atan2 if x[0] == 0.0 && x[1] == 0.0 => return undefined("for atan2(0, 0)"),
        Mf::Pow if x[0] < 0.0 || (x[0] == 0.0 && x[1] <= 0.0) => return undefined(&format!("for pow({}, {})", x[0], x[1])),
        Mf::SmoothStep if x[0] >= x[1] => return undefined(&format!("when edge0 ({}) is not below edge1 ({})", x[0], x[1])),
        Mf::Atan2 => libm::atan2(x[0], x[1]),
        Mf::Pow => libm::pow(x[0], x[1]),
        Mf::Min => x[0].min(x[1]),
        Mf::Max => x[0].max(x[1]),
        Mf::Step => {
            if x[1] < x[0] {
                0.0
            } else {
                1.0
            }
        }
        Mf::Mix => x[0] * (1.0 - x[2]) + x[1] * x[2],
        Mf::Fma => x[0] * x[1] + x[2],
        Mf::SmoothStep => {
            let t = ((x[2] - x[0]) / (x[1] - x[0])).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        }
        // GLSL's definition, in the float arithmetic it names.
        Mf::Fract => ((x[0] as f32) - (x[0] as f32).floor()) as f64,
        f => unary(f, x[0]),
    })
}

fn unary(f: Mf, x: f64) -> f64 {
    match f {
        Mf::Sin => libm::sin(x),
        Mf::Cos => libm::cos(x),
        Mf::Tan => libm::tan(x),
        Mf::Asin => libm::asin(x),
        Mf::Acos => libm::acos(x),
        Mf::Atan => libm::atan(x),
        Mf::Sinh => libm::sinh(x),
        Mf::Cosh => libm::cosh(x),
        Mf::Tanh => libm::tanh(x),
        Mf::Radians => x * (std::f64::consts::PI / 180.0),
        Mf::Degrees => x * (180.0 / std::f64::consts::PI),
        Mf::Exp => libm::exp(x),
        Mf::Exp2 => libm::exp2(x),
        Mf::Log => libm::log(x),
        Mf::Log2 => libm::log2(x),
        Mf::Sqrt => x.sqrt(),
        Mf::InverseSqrt => 1.0 / x.sqrt(),
        Mf::Floor => x.floor(),
        Mf::Ceil => x.ceil(),
        Mf::Trunc => x.trunc(),
        // naga's Round (GLSL `roundEven`, WGSL `round`): ties to even.
        Mf::Round => x.round_ties_even(),
        Mf::Abs => x.abs(),
        Mf::Sign => {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        _ => f64::NAN,
    }
}

/// Reports `clamp(x, lo, hi)` with `lo > hi` in some component: GLSL leaves
/// it undefined and WGSL's constant evaluation rejects it.
fn clamp_bounds_wrong(name: &str, n: usize, v: &[&ConstValue]) -> Option<String> {
    let (lo, hi) = (components(v[1]), components(v[2]));
    (0..n).find_map(|i| {
        let (a, b) = (&lo[if lo.len() == 1 { 0 } else { i }], &hi[if hi.len() == 1 { 0 } else { i }]);
        let wrong = match (a, b) {
            (ConstValue::Float(a), ConstValue::Float(b)) => a > b,
            (ConstValue::Int(a), ConstValue::Int(b)) => a > b,
            (ConstValue::Uint(a), ConstValue::Uint(b)) => a > b,
            _ => false,
        };
        wrong.then(|| format!("`{name}` with a lower bound above the upper bound is undefined"))
    })
}

/// Applies `f` to the float arguments of each of `n` components (a scalar
/// argument serves every component) and rounds each result to `f32`.
fn component_wise(name: &str, n: usize, v: &[&ConstValue], f: impl Fn(&[f64]) -> Result<f64, String>) -> Result<ConstValue, String> {
    let args: Vec<Vec<f64>> = v.iter().map(|x| floats(x)).collect();
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let xi: Vec<f64> = args.iter().map(|a| a[if a.len() == 1 { 0 } else { i }]).collect();
        out.push(finite(name, f(&xi)?)?);
    }
    Ok(rebuild(out))
}

/// [`component_wise`] over `int` or `uint` components; `None` from `f` is
/// an overflow.
fn int_component_wise(name: &str, n: usize, v: &[&ConstValue], f: impl Fn(&[i64]) -> Option<i64>) -> Result<ConstValue, String> {
    let unsigned = matches!(components(v[0])[0], ConstValue::Uint(_));
    let args: Vec<Vec<i64>> = v.iter().map(|x| ints(x)).collect();
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let xi: Vec<i64> = args.iter().map(|a| a[if a.len() == 1 { 0 } else { i }]).collect();
        let r = f(&xi).filter(|r| if unsigned { (0..=u32::MAX as i64).contains(r) } else { (i32::MIN as i64..=i32::MAX as i64).contains(r) });
        let r = r.ok_or_else(|| format!("integer overflow in `{name}` in a constant"))?;
        out.push(if unsigned { ConstValue::Uint(r as u64) } else { ConstValue::Int(r) });
    }
    Ok(rebuild(out))
}

fn finite(name: &str, x: f64) -> Result<ConstValue, String> {
    finite_f32(name, x as f32)
}

fn finite_f32(name: &str, x: f32) -> Result<ConstValue, String> {
    if x.is_finite() {
        Ok(ConstValue::Float(x as f64))
    } else {
        let what = if x.is_nan() { "NaN" } else { "infinite" };
        Err(format!("`{name}` is {what} in `float` here; constants must be finite: WGSL rejects non-finite constant expressions"))
    }
}

fn vector_of(name: &str, xs: &[f64]) -> Result<ConstValue, String> {
    Ok(rebuild(xs.iter().map(|x| finite(name, *x)).collect::<Result<_, _>>()?))
}

/// A scalar for one component, else a vector.
fn rebuild(mut comps: Vec<ConstValue>) -> ConstValue {
    if comps.len() == 1 {
        comps.pop().expect("one component")
    } else {
        ConstValue::Composite(comps)
    }
}

fn matrix(cols: Vec<Vec<f64>>) -> ConstValue {
    ConstValue::Composite(cols.into_iter().map(|c| ConstValue::Composite(c.into_iter().map(|x| ConstValue::Float(x as f32 as f64)).collect())).collect())
}

fn components(v: &ConstValue) -> Vec<ConstValue> {
    match v {
        ConstValue::Composite(cs) => cs.clone(),
        c => vec![c.clone()],
    }
}

fn floats(v: &ConstValue) -> Vec<f64> {
    components(v)
        .iter()
        .map(|c| match *c {
            ConstValue::Float(f) => f,
            ConstValue::Int(i) => i as f64,
            ConstValue::Uint(u) => u as f64,
            _ => f64::NAN,
        })
        .collect()
}

fn ints(v: &ConstValue) -> Vec<i64> {
    components(v)
        .iter()
        .map(|c| match *c {
            ConstValue::Int(i) => i,
            ConstValue::Uint(u) => u as i64,
            _ => 0,
        })
        .collect()
}

fn uint(v: &ConstValue) -> u32 {
    match *v {
        ConstValue::Uint(u) => u as u32,
        ConstValue::Int(i) => i as i32 as u32,
        _ => 0,
    }
}

fn bools(v: &ConstValue) -> Vec<bool> {
    components(v).iter().map(|c| matches!(c, ConstValue::Bool(true))).collect()
}

fn columns(v: &ConstValue) -> Vec<Vec<f64>> {
    components(v).iter().map(floats).collect()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn length_of_difference(v: &[&ConstValue]) -> f64 {
    let d: Vec<f64> = floats(v[0]).iter().zip(floats(v[1])).map(|(a, b)| a - b).collect();
    dot(&d, &d).sqrt()
}

/// GLSL's float `mod`, `x - y * floor(x / y)`, in `f32` operations.
fn float_mod(x: f64, y: f64) -> f64 {
    let (x, y) = (x as f32, y as f32);
    (x - y * (x / y).floor()) as f64
}

fn compare(op: BinaryOp, a: &ConstValue, b: &ConstValue) -> Option<bool> {
    use std::cmp::Ordering;
    let ord = match (a, b) {
        (ConstValue::Float(x), ConstValue::Float(y)) => x.partial_cmp(y)?,
        (ConstValue::Int(x), ConstValue::Int(y)) => x.cmp(y),
        (ConstValue::Uint(x), ConstValue::Uint(y)) => x.cmp(y),
        (ConstValue::Bool(x), ConstValue::Bool(y)) => x.cmp(y),
        _ => return None,
    };
    Some(match op {
        BinaryOp::Lt => ord == Ordering::Less,
        BinaryOp::Le => ord != Ordering::Greater,
        BinaryOp::Gt => ord == Ordering::Greater,
        BinaryOp::Ge => ord != Ordering::Less,
        BinaryOp::Eq => ord == Ordering::Equal,
        _ => ord != Ordering::Equal,
    })
}

/// The determinant of a square matrix given by columns (cofactor
/// expansion along the first column; at most 4 x 4).
fn determinant(m: &[Vec<f64>]) -> f64 {
    match m.len() {
        1 => m[0][0],
        k => (0..k).map(|row| m[0][row] * cofactor(m, 0, row)).sum(),
    }
}

/// The cofactor of element (column `col`, row `row`).
fn cofactor(m: &[Vec<f64>], col: usize, row: usize) -> f64 {
    let minor: Vec<Vec<f64>> = m.iter().enumerate().filter(|(c, _)| *c != col).map(|(_, c)| c.iter().enumerate().filter(|(r, _)| *r != row).map(|(_, x)| *x).collect()).collect();
    let sign = if (col + row).is_multiple_of(2) { 1.0 } else { -1.0 };
    sign * determinant(&minor)
}

/// `x op y` of two `half` constants: computed exactly in `f64` (53 bits
/// hold every sum, product and correctly rounded quotient of binary16
/// values closely enough) and rounded once to binary16.
pub fn half_op(op: BinaryOp, x: f64, y: f64) -> Result<ConstValue, String> {
    let r = match op {
        BinaryOp::Add => x + y,
        BinaryOp::Sub => x - y,
        BinaryOp::Mul => x * y,
        BinaryOp::Div if y == 0.0 => return Err("division by zero in constant".into()),
        BinaryOp::Div => x / y,
        BinaryOp::Mod if y == 0.0 => return Err("division by zero in constant".into()),
        // GLSL mod, each operation rounded to binary16 as the GPU does.
        BinaryOp::Mod => {
            let q = half::f16::from_f64(x / y).to_f64().floor();
            let p = half::f16::from_f64(y * q).to_f64();
            x - p
        }
        _ => return Err(format!("`{}` does not apply to `half` constants", crate::sema::op_text(op))),
    };
    let h = half::f16::from_f64(r);
    if h.is_finite() {
        Ok(ConstValue::Float(h.to_f64()))
    } else {
        Err(format!("this constant is {} in `half` (largest 65504); constants must be finite: WGSL rejects non-finite constant expressions", if h.is_nan() { "NaN" } else { "infinite" }))
    }
}

/// A `c` x `r` matrix from another (GLSL's rule, as the lowering builds
/// it): the argument's elements where it has them, the identity's
/// elsewhere.
pub fn matrix_from_matrix(m: &ConstValue, c: u8, r: u8) -> ConstValue {
    let cols = columns(m);
    matrix((0..c as usize).map(|i| (0..r as usize).map(|j| cols.get(i).and_then(|col| col.get(j).copied()).unwrap_or(if i == j { 1.0 } else { 0.0 })).collect()).collect())
}

/// daslang's `uint32_hash` / `uint_noise_*` mixing (wrapping `uint`).
pub fn noise_hash(mut m: u32, seed: Option<u32>) -> u32 {
    m = m.wrapping_mul(0x68E3_1DA4);
    if let Some(seed) = seed {
        m = m.wrapping_add(seed);
    }
    m ^= m >> 8;
    m = m.wrapping_add(0xB529_7A4D);
    m ^= m << 8;
    m = m.wrapping_mul(0x1B56_C4E9);
    m ^ (m >> 8)
}

/// The pack and unpack functions, as WGSL defines them.
fn pack(name: &str, f: Mf, v: &ConstValue) -> Result<ConstValue, String> {
    let lanes = |scale: f64, signed: bool, bits: u32| -> u32 {
        floats(v).iter().enumerate().fold(0u32, |acc, (i, x)| {
            let x = if signed { x.clamp(-1.0, 1.0) } else { x.clamp(0.0, 1.0) };
            // floor(0.5 + scale * x), computed as the targets do in f32.
            let t = (0.5f32 + (scale as f32) * (x as f32)).floor() as i32;
            acc | (((t as u32) & ((1u32 << bits) - 1)) << (bits * i as u32))
        })
    };
    let unlanes = |scale: f32, signed: bool, bits: u32, n: u32| -> ConstValue {
        let u = uint(v);
        ConstValue::Composite(
            (0..n)
                .map(|i| {
                    let raw = (u >> (bits * i)) & ((1u32 << bits) - 1);
                    let x = if signed { (((raw << (32 - bits)) as i32) >> (32 - bits)) as f32 } else { raw as f32 };
                    let r = x / scale;
                    ConstValue::Float((if signed { r.max(-1.0) } else { r }) as f64)
                })
                .collect(),
        )
    };
    Ok(match f {
        Mf::Pack4x8unorm => ConstValue::Uint(lanes(255.0, false, 8) as u64),
        Mf::Pack4x8snorm => ConstValue::Uint(lanes(127.0, true, 8) as u64),
        Mf::Pack2x16unorm => ConstValue::Uint(lanes(65535.0, false, 16) as u64),
        Mf::Pack2x16snorm => ConstValue::Uint(lanes(32767.0, true, 16) as u64),
        Mf::Pack2x16float => {
            let x = floats(v);
            let h = |x: f64| half::f16::from_f32(x as f32).to_bits() as u32;
            ConstValue::Uint((h(x[0]) | (h(x[1]) << 16)) as u64)
        }
        Mf::Unpack4x8unorm => unlanes(255.0, false, 8, 4),
        Mf::Unpack4x8snorm => unlanes(127.0, true, 8, 4),
        Mf::Unpack2x16unorm => unlanes(65535.0, false, 16, 2),
        Mf::Unpack2x16snorm => unlanes(32767.0, true, 16, 2),
        Mf::Unpack2x16float => {
            let u = uint(v);
            let lanes: Vec<ConstValue> = [u & 0xFFFF, u >> 16].iter().map(|h| finite_f32(name, half::f16::from_bits(*h as u16).to_f32())).collect::<Result<_, _>>()?;
            ConstValue::Composite(lanes)
        }
        _ => return Err(format!("`{name}` is not a constant expression")),
    })
}

/// A scalar conversion as the constructors `float(x)`, `int(x)`, `uint(x)`,
/// `bool(x)` define it: int <-> uint keep the bits (two's complement);
/// float -> int/uint truncates toward zero after clamping to the largest
/// f32 values inside the type's range (2147483520.0, 4294967040.0; what
/// WGSL defines and naga's WGSL and SPIR-V outputs compute; GLSL leaves
/// out-of-range conversions undefined); to float rounds to nearest f32;
/// to bool is `!= 0`.
pub fn convert(c: &ConstValue, to: Scalar) -> Option<ConstValue> {
    // To its own type: the value as it is (an `int` above 2^24 does not
    // survive a trip through f32).
    match (c, to) {
        (ConstValue::Int(_), Scalar::Int) | (ConstValue::Uint(_), Scalar::Uint) | (ConstValue::Bool(_), Scalar::Bool) => return Some(c.clone()),
        _ => {}
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sema::types::FLOAT;

    fn f3(x: f32, y: f32, z: f32) -> (ConstValue, Ty) {
        (ConstValue::Composite(vec![ConstValue::Float(x as f64), ConstValue::Float(y as f64), ConstValue::Float(z as f64)]), Ty::Vector(Scalar::Float, 3))
    }

    fn f(x: f32) -> (ConstValue, Ty) {
        (ConstValue::Float(x as f64), FLOAT)
    }

    #[test]
    fn normalize_rounds_the_exact_quotients_once() {
        let (v, ty) = call("normalize", &[f3(3.0, 0.0, 4.0)]).unwrap().unwrap();
        assert_eq!(ty, Ty::Vector(Scalar::Float, 3));
        assert_eq!(v, ConstValue::Composite(vec![ConstValue::Float(0.6f32 as f64), ConstValue::Float(0.0), ConstValue::Float(0.8f32 as f64)]));
    }

    #[test]
    fn undefined_calls_are_errors() {
        for (name, args) in [("sqrt", vec![f(-1.0)]), ("log", vec![f(0.0)]), ("pow", vec![f(-2.0), f(0.5)]), ("atan2", vec![f(0.0), f(0.0)]), ("clamp", vec![f(0.5), f(1.0), f(0.0)]), ("smoothstep", vec![f(1.0), f(1.0), f(0.5)])] {
            assert!(call(name, &args).unwrap().is_err(), "{name}");
        }
        assert!(call("normalize", &[f3(0.0, 0.0, 0.0)]).unwrap().is_err());
        assert!(call("rcp", &[f(0.0)]).unwrap().is_err());
        assert!(call("texture", &[f(0.0)]).unwrap().is_err());
        assert!(call("no_such_function", &[f(0.0)]).is_none());
    }

    #[test]
    fn the_noise_hash_is_daslangs() {
        // Squirrel Eiserloh's reference values, computed by hand from the
        // published constants: hash(0) mixes only the additive constant.
        assert_eq!(noise_hash(0, None), {
            let mut m = 0xB529_7A4Du32;
            m ^= m << 8;
            m = m.wrapping_mul(0x1B56_C4E9);
            m ^ (m >> 8)
        });
        let (v, _) = call("uint_noise_2D", &[(ConstValue::Composite(vec![ConstValue::Int(1), ConstValue::Int(-1)]), Ty::Vector(Scalar::Int, 2)), (ConstValue::Uint(5), Ty::Scalar(Scalar::Uint))]).unwrap().unwrap();
        assert_eq!(v, ConstValue::Uint(noise_hash(1u32.wrapping_sub(198_491_317), Some(5)) as u64));
    }

    #[test]
    fn packing_matches_wgsl_rules() {
        let v = |xs: &[f32]| (ConstValue::Composite(xs.iter().map(|x| ConstValue::Float(*x as f64)).collect()), Ty::Vector(Scalar::Float, xs.len() as u8));
        assert_eq!(call("packUnorm4x8", &[v(&[0.0, 1.0, 0.5, 2.0])]).unwrap().unwrap().0, ConstValue::Uint(0xFF80_FF00));
        assert_eq!(call("packSnorm4x8", &[v(&[-1.0, 1.0, 0.0, -2.0])]).unwrap().unwrap().0, ConstValue::Uint(0x8100_7F81));
        assert_eq!(call("packHalf2x16", &[v(&[1.0, -2.0])]).unwrap().unwrap().0, ConstValue::Uint(0xC000_3C00));
        let (u, _) = call("unpackSnorm4x8", &[(ConstValue::Uint(0x0000_0080), Ty::Scalar(Scalar::Uint))]).unwrap().unwrap();
        assert_eq!(components(&u)[0], ConstValue::Float(-1.0));
    }
}
