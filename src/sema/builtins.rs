//! The builtin function table: names, signatures, and what each lowers to.
//!
//! Signatures are written in a small pattern language so that one table
//! both checks calls and prints the expected signatures in errors:
//! - `G`: float or floatN (every `G` in one signature is the same type);
//!   `GV`: floatN only, N >= 2 (naga's `dot`, `normalize`, `reflect`,
//!   `refract`, `faceforward` take vectors, though GLSL's take a float too)
//! - `N`: a numeric scalar or vector, any scalar type (all `N` alike); `S`
//!   is the scalar of that `N`; `NS`: a signed one (float or int: `sign`)
//! - `I`: int or intN / uint or uintN (all `I` alike)
//! - `B`: boolN; `V`: a numeric vector whose `B` result has the same width
//! - `f`, `i`, `b`: float, int, bool; `f2`, `f3`, `f4`: float vectors

use std::sync::OnceLock;

use super::types::{Scalar, Ty, BOOL, FLOAT};
use rustc_hash::FxHashMap;
use naga::MathFunction as Mf;

/// What a builtin call lowers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// A naga math function; scalar arguments of vector calls are splatted.
    Math(Mf),
    /// `saturate(x)`: clamp(x, 0, 1).
    Saturate,
    /// `rcp(x)`: 1 / x.
    Rcp,
    /// GLSL `mod`: x - y * floor(x / y).
    Mod,
    /// `any`, `all` on bool vectors.
    Any,
    All,
    /// `not` on a bool vector.
    Not,
    /// `lessThan`, `equal`, ... on vectors: component-wise comparison.
    Compare(crate::syntax::ast::BinaryOp),
    Derivative(naga::DerivativeAxis, naga::DerivativeControl),
    /// `texture(s, uv)` / `texture(s, uv, bias)`.
    Texture,
    TextureLod,
    /// `textureGrad(s, uv, dPdx, dPdy)`.
    TextureGrad,
    /// `floatBitsToInt` and friends: reinterpret the bits as this scalar.
    Bitcast(Scalar),
    /// `textureCompare(s, uv, ref)`: depth compare on a shadow sampler.
    TextureCompare,
    /// `textureProj(s, uvq)`: uv / q, then `texture`; on a shadow sampler,
    /// `textureProj(s, uvzq)` compares z / q.
    TextureProj,
    TexelFetch,
    TextureSize,
    /// `textureOffset(s, uv, offset[, bias])`, `textureLodOffset(s, uv,
    /// lod, offset)`, `textureCompareOffset(s, uv, ref, offset)`,
    /// `texelFetchOffset(s, icoord, lod, offset)` (GLSL's argument
    /// order): the call without `Offset`, sampling `offset` texels away (a
    /// constant `int2`, `int3` for 3D, each component in [-8, 7]).
    TextureOffset,
    TextureLodOffset,
    TextureCompareOffset,
    TexelFetchOffset,
    /// `inverse(m)` of a square matrix: a helper function on every target
    /// (WGSL has none).
    Inverse,
}

/// The range every target guarantees for a texel offset (GLSL's minimum
/// `MIN/MAX_PROGRAM_TEXEL_OFFSET`, WGSL's rule for `offset`).
pub const TEXEL_OFFSET_RANGE: std::ops::RangeInclusive<i64> = -8..=7;

impl Builtin {
    /// A texture function (checked by `check_texture_call`, lowered per
    /// sampler).
    pub fn is_texture(self) -> bool {
        TEXTURE_FUNCTIONS.iter().any(|(_, b)| *b == self)
    }

    /// The function an `...Offset` texture function offsets, and which
    /// argument is the offset; any other builtin as it is, with none.
    pub fn split_offset(self) -> (Builtin, Option<usize>) {
        match self {
            Builtin::TextureOffset => (Builtin::Texture, Some(2)),
            Builtin::TextureLodOffset => (Builtin::TextureLod, Some(3)),
            Builtin::TextureCompareOffset => (Builtin::TextureCompare, Some(3)),
            Builtin::TexelFetchOffset => (Builtin::TexelFetch, Some(3)),
            b => (b, None),
        }
    }
}

/// One overload: argument patterns and result pattern.
struct Sig {
    args: &'static [&'static str],
    ret: &'static str,
}

macro_rules! sigs {
    ($($ret:literal <- [$($a:literal),*]);* $(;)?) => {
        &[$(Sig { args: &[$($a),*], ret: $ret }),*]
    };
}

struct Entry {
    name: &'static str,
    builtin: Builtin,
    sigs: &'static [Sig],
}

const UNARY_G: &[Sig] = sigs!["G" <- ["G"]];
const BINARY_G: &[Sig] = sigs!["G" <- ["G", "G"]];

const TABLE: &[Entry] = &[
    Entry { name: "sin", builtin: Builtin::Math(Mf::Sin), sigs: UNARY_G },
    Entry { name: "cos", builtin: Builtin::Math(Mf::Cos), sigs: UNARY_G },
    Entry { name: "tan", builtin: Builtin::Math(Mf::Tan), sigs: UNARY_G },
    Entry { name: "asin", builtin: Builtin::Math(Mf::Asin), sigs: UNARY_G },
    Entry { name: "acos", builtin: Builtin::Math(Mf::Acos), sigs: UNARY_G },
    Entry { name: "atan", builtin: Builtin::Math(Mf::Atan), sigs: UNARY_G },
    Entry { name: "atan2", builtin: Builtin::Math(Mf::Atan2), sigs: BINARY_G },
    Entry { name: "sinh", builtin: Builtin::Math(Mf::Sinh), sigs: UNARY_G },
    Entry { name: "cosh", builtin: Builtin::Math(Mf::Cosh), sigs: UNARY_G },
    Entry { name: "tanh", builtin: Builtin::Math(Mf::Tanh), sigs: UNARY_G },
    Entry { name: "radians", builtin: Builtin::Math(Mf::Radians), sigs: UNARY_G },
    Entry { name: "degrees", builtin: Builtin::Math(Mf::Degrees), sigs: UNARY_G },
    Entry { name: "exp", builtin: Builtin::Math(Mf::Exp), sigs: UNARY_G },
    Entry { name: "exp2", builtin: Builtin::Math(Mf::Exp2), sigs: UNARY_G },
    Entry { name: "log", builtin: Builtin::Math(Mf::Log), sigs: UNARY_G },
    Entry { name: "log2", builtin: Builtin::Math(Mf::Log2), sigs: UNARY_G },
    Entry { name: "sqrt", builtin: Builtin::Math(Mf::Sqrt), sigs: UNARY_G },
    Entry { name: "inversesqrt", builtin: Builtin::Math(Mf::InverseSqrt), sigs: UNARY_G },
    Entry { name: "rsqrt", builtin: Builtin::Math(Mf::InverseSqrt), sigs: UNARY_G },
    Entry { name: "floor", builtin: Builtin::Math(Mf::Floor), sigs: UNARY_G },
    Entry { name: "ceil", builtin: Builtin::Math(Mf::Ceil), sigs: UNARY_G },
    Entry { name: "fract", builtin: Builtin::Math(Mf::Fract), sigs: UNARY_G },
    Entry { name: "trunc", builtin: Builtin::Math(Mf::Trunc), sigs: UNARY_G },
    Entry { name: "round", builtin: Builtin::Math(Mf::Round), sigs: UNARY_G },
    Entry { name: "roundEven", builtin: Builtin::Math(Mf::Round), sigs: UNARY_G },
    Entry { name: "abs", builtin: Builtin::Math(Mf::Abs), sigs: sigs!["N" <- ["N"]] },
    Entry { name: "sign", builtin: Builtin::Math(Mf::Sign), sigs: sigs!["N" <- ["NS"]] },
    Entry { name: "min", builtin: Builtin::Math(Mf::Min), sigs: sigs!["N" <- ["N", "N"]; "N" <- ["N", "S"]] },
    Entry { name: "max", builtin: Builtin::Math(Mf::Max), sigs: sigs!["N" <- ["N", "N"]; "N" <- ["N", "S"]] },
    Entry { name: "clamp", builtin: Builtin::Math(Mf::Clamp), sigs: sigs!["N" <- ["N", "N", "N"]; "N" <- ["N", "S", "S"]] },
    Entry { name: "saturate", builtin: Builtin::Saturate, sigs: UNARY_G },
    Entry { name: "rcp", builtin: Builtin::Rcp, sigs: UNARY_G },
    Entry { name: "mix", builtin: Builtin::Math(Mf::Mix), sigs: sigs!["G" <- ["G", "G", "G"]; "G" <- ["G", "G", "f"]] },
    Entry { name: "lerp", builtin: Builtin::Math(Mf::Mix), sigs: sigs!["G" <- ["G", "G", "G"]; "G" <- ["G", "G", "f"]] },
    Entry { name: "step", builtin: Builtin::Math(Mf::Step), sigs: sigs!["G" <- ["G", "G"]; "G" <- ["f", "G"]] },
    Entry { name: "smoothstep", builtin: Builtin::Math(Mf::SmoothStep), sigs: sigs!["G" <- ["G", "G", "G"]; "G" <- ["f", "f", "G"]] },
    Entry { name: "pow", builtin: Builtin::Math(Mf::Pow), sigs: BINARY_G },
    Entry { name: "mod", builtin: Builtin::Mod, sigs: sigs!["G" <- ["G", "G"]; "G" <- ["G", "f"]] },
    Entry { name: "fma", builtin: Builtin::Math(Mf::Fma), sigs: sigs!["G" <- ["G", "G", "G"]] },
    Entry { name: "length", builtin: Builtin::Math(Mf::Length), sigs: sigs!["f" <- ["G"]] },
    Entry { name: "distance", builtin: Builtin::Math(Mf::Distance), sigs: sigs!["f" <- ["G", "G"]] },
    Entry { name: "dot", builtin: Builtin::Math(Mf::Dot), sigs: sigs!["f" <- ["GV", "GV"]] },
    Entry { name: "cross", builtin: Builtin::Math(Mf::Cross), sigs: sigs!["f3" <- ["f3", "f3"]] },
    Entry { name: "normalize", builtin: Builtin::Math(Mf::Normalize), sigs: sigs!["G" <- ["GV"]] },
    Entry { name: "reflect", builtin: Builtin::Math(Mf::Reflect), sigs: sigs!["G" <- ["GV", "GV"]] },
    Entry { name: "refract", builtin: Builtin::Math(Mf::Refract), sigs: sigs!["G" <- ["GV", "GV", "f"]] },
    Entry { name: "faceforward", builtin: Builtin::Math(Mf::FaceForward), sigs: sigs!["G" <- ["GV", "GV", "GV"]] },
    Entry { name: "transpose", builtin: Builtin::Math(Mf::Transpose), sigs: sigs!["M" <- ["M"]] },
    Entry { name: "determinant", builtin: Builtin::Math(Mf::Determinant), sigs: sigs!["f" <- ["M"]] },
    Entry { name: "inverse", builtin: Builtin::Inverse, sigs: sigs!["M" <- ["M"]] },
    Entry { name: "any", builtin: Builtin::Any, sigs: sigs!["b" <- ["B"]] },
    Entry { name: "all", builtin: Builtin::All, sigs: sigs!["b" <- ["B"]] },
    Entry { name: "not", builtin: Builtin::Not, sigs: sigs!["B" <- ["B"]] },
    Entry { name: "lessThan", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Lt), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "lessThanEqual", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Le), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "greaterThan", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Gt), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "greaterThanEqual", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Ge), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "equal", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Eq), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "notEqual", builtin: Builtin::Compare(crate::syntax::ast::BinaryOp::Ne), sigs: sigs!["B" <- ["V", "V"]] },
    Entry { name: "floatBitsToInt", builtin: Builtin::Bitcast(Scalar::Int), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "floatBitsToUint", builtin: Builtin::Bitcast(Scalar::Uint), sigs: sigs!["GU" <- ["G"]] },
    Entry { name: "intBitsToFloat", builtin: Builtin::Bitcast(Scalar::Float), sigs: sigs!["G" <- ["GI"]] },
    Entry { name: "uintBitsToFloat", builtin: Builtin::Bitcast(Scalar::Float), sigs: sigs!["G" <- ["GU"]] },
    Entry {
        name: "dFdx",
        builtin: Builtin::Derivative(naga::DerivativeAxis::X, naga::DerivativeControl::None),
        sigs: UNARY_G,
    },
    Entry {
        name: "dFdy",
        builtin: Builtin::Derivative(naga::DerivativeAxis::Y, naga::DerivativeControl::None),
        sigs: UNARY_G,
    },
    Entry {
        name: "fwidth",
        builtin: Builtin::Derivative(naga::DerivativeAxis::Width, naga::DerivativeControl::None),
        sigs: UNARY_G,
    },
];

/// Texture builtins: checked by `check_texture_call` (their signatures depend
/// on the sampler type).
pub const TEXTURE_FUNCTIONS: &[(&str, Builtin)] = &[
    ("texture", Builtin::Texture),
    ("textureLod", Builtin::TextureLod),
    ("textureGrad", Builtin::TextureGrad),
    ("textureCompare", Builtin::TextureCompare),
    ("textureProj", Builtin::TextureProj),
    ("texelFetch", Builtin::TexelFetch),
    ("textureSize", Builtin::TextureSize),
    ("textureOffset", Builtin::TextureOffset),
    ("textureLodOffset", Builtin::TextureLodOffset),
    ("textureCompareOffset", Builtin::TextureCompareOffset),
    ("texelFetchOffset", Builtin::TexelFetchOffset),
];

/// Names of GLSL functions the DSL deliberately lacks, with the reason and
/// what to do instead.
pub const UNSUPPORTED: &[(&str, &str)] = &[
    ("isnan", "WGSL has no isnan, and GPU compilers may assume that values are never NaN"),
    ("isinf", "WGSL has no isinf; compare against a large bound instead"),
    ("textureGather", "not supported yet"),
];

/// Every builtin function name, for "did you mean" suggestions.
pub fn all_names() -> impl Iterator<Item = &'static str> {
    TABLE.iter().map(|e| e.name).chain(TEXTURE_FUNCTIONS.iter().map(|(n, _)| *n))
}

/// The name a builtin is called by in messages (the first of the names that
/// lower to it: `inversesqrt`, not `rsqrt`).
pub fn name_of(b: Builtin) -> &'static str {
    TABLE.iter().find(|e| e.builtin == b).map(|e| e.name).or_else(|| TEXTURE_FUNCTIONS.iter().find(|(_, t)| *t == b).map(|(n, _)| *n)).unwrap_or("builtin")
}

pub fn is_builtin(name: &str) -> bool {
    entry(name).is_some() || TEXTURE_FUNCTIONS.iter().any(|(n, _)| *n == name)
}

/// The table's entry for a name (each name has one), through an index built
/// on first use: every call in a shader looks its name up here.
fn entry(name: &str) -> Option<&'static Entry> {
    static INDEX: OnceLock<FxHashMap<&'static str, usize>> = OnceLock::new();
    let index = INDEX.get_or_init(|| TABLE.iter().enumerate().map(|(i, e)| (e.name, i)).collect());
    index.get(name).map(|&i| &TABLE[i])
}

/// Resolves a call of a non-texture builtin by argument types.
/// `Ok(None)`: not a builtin of this table. `Err(signatures)`: no overload fits.
pub fn resolve<'t>(name: &str, args: impl ExactSizeIterator<Item = &'t Ty> + Clone) -> Result<Option<(Builtin, Ty)>, Vec<String>> {
    let Some(e) = entry(name) else {
        return Ok(None);
    };
    for sig in e.sigs {
        if let Some(ret) = match_sig(sig, args.clone()) {
            return Ok(Some((e.builtin, ret)));
        }
    }
    Err(e.sigs.iter().map(|s| format_sig(e.name, s)).collect())
}

/// Bindings of the pattern variables while matching one signature.
#[derive(Default)]
struct Bind {
    g: Option<u8>,
    n: Option<(Scalar, u8)>,
    v: Option<(Scalar, u8)>,
    b: Option<u8>,
    m: Option<(u8, u8)>,
}

fn match_one(pat: &str, ty: &Ty, bind: &mut Bind) -> bool {
    fn unify<T: PartialEq + Copy>(slot: &mut Option<T>, v: T) -> bool {
        match *slot {
            Some(old) => old == v,
            None => {
                *slot = Some(v);
                true
            }
        }
    }
    match pat {
        "G" => match *ty {
            Ty::Scalar(Scalar::Float) => unify(&mut bind.g, 1),
            Ty::Vector(Scalar::Float, n) => unify(&mut bind.g, n),
            _ => false,
        },
        "GV" => match *ty {
            Ty::Vector(Scalar::Float, n) => unify(&mut bind.g, n),
            _ => false,
        },
        "N" => match (ty.scalar(), ty.width()) {
            (Some(s), Some(w)) if s.is_numeric() => unify(&mut bind.n, (s, w)),
            _ => false,
        },
        "NS" => match (ty.scalar(), ty.width()) {
            (Some(s @ (Scalar::Float | Scalar::Int)), Some(w)) => unify(&mut bind.n, (s, w)),
            _ => false,
        },
        "GI" => match *ty {
            Ty::Scalar(Scalar::Int) => unify(&mut bind.g, 1),
            Ty::Vector(Scalar::Int, n) => unify(&mut bind.g, n),
            _ => false,
        },
        "GU" => match *ty {
            Ty::Scalar(Scalar::Uint) => unify(&mut bind.g, 1),
            Ty::Vector(Scalar::Uint, n) => unify(&mut bind.g, n),
            _ => false,
        },
        "S" => match *ty {
            Ty::Scalar(s) if s.is_numeric() => bind.n.is_none_or(|(ns, _)| ns == s),
            _ => false,
        },
        "V" => match *ty {
            Ty::Vector(s, n) if s.is_numeric() || s == Scalar::Bool => unify(&mut bind.v, (s, n)),
            _ => false,
        },
        "B" => match *ty {
            Ty::Vector(Scalar::Bool, n) => unify(&mut bind.b, n),
            _ => false,
        },
        "M" => match *ty {
            Ty::Matrix(c, r) => unify(&mut bind.m, (c, r)),
            _ => false,
        },
        "f" => *ty == FLOAT,
        "b" => *ty == BOOL,
        "f3" => *ty == Ty::Vector(Scalar::Float, 3),
        _ => false,
    }
}

fn match_sig<'t>(sig: &Sig, args: impl ExactSizeIterator<Item = &'t Ty> + Clone) -> Option<Ty> {
    if sig.args.len() != args.len() {
        return None;
    }
    let mut bind = Bind::default();
    // Two passes so that `S` sees `N` bound by a later argument too.
    for _ in 0..2 {
        for (p, a) in sig.args.iter().zip(args.clone()) {
            if !match_one(p, a, &mut bind) {
                return None;
            }
        }
    }
    Some(match sig.ret {
        "G" => Ty::vec(Scalar::Float, bind.g?),
        "GI" => Ty::vec(Scalar::Int, bind.g?),
        "GU" => Ty::vec(Scalar::Uint, bind.g?),
        "N" => {
            let (s, w) = bind.n?;
            Ty::vec(s, w)
        }
        "B" => Ty::Vector(Scalar::Bool, bind.b.or(bind.v.map(|v| v.1))?),
        "M" => {
            let (c, r) = bind.m?;
            Ty::Matrix(r, c)
        }
        "f" => FLOAT,
        "b" => BOOL,
        "f3" => Ty::Vector(Scalar::Float, 3),
        _ => return None,
    })
}

fn pattern_text(p: &str) -> &'static str {
    match p {
        "G" => "floatN",
        "GV" => "float2/3/4",
        "NS" => "T (float or int)",
        "GI" => "intN",
        "GU" => "uintN",
        "N" => "T",
        "S" => "scalar of T",
        "V" => "vecN",
        "B" => "boolN",
        "M" => "floatCxR",
        "f" => "float",
        "b" => "bool",
        "f3" => "float3",
        _ => "?",
    }
}

fn format_sig(name: &str, sig: &Sig) -> String {
    let args: Vec<&str> = sig.args.iter().map(|a| pattern_text(a)).collect();
    format!("{name}({}) : {}", args.join(", "), pattern_text(sig.ret))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `entry` finds one entry per name, so every name must be listed once.
    #[test]
    fn names_are_unique() {
        let mut names: Vec<&str> = all_names().collect();
        let n = names.len();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), n);
    }
}
