//! The builtin function table: names, signatures, and what each lowers to.
//!
//! Signatures are written in a small pattern language so that one table
//! both checks calls and prints the expected signatures in errors:
//! - `G`: float or floatN (every `G` in one signature is the same type)
//! - `X`: like `G`, or half or halfN; `x` is the scalar of that `X` (the
//!   functions WGSL and SPIR-V also have for `f16`); `XV`: an `X` that is a
//!   vector (naga's `dot`, `normalize`, `reflect`, `refract`, `faceforward`
//!   take vectors, though GLSL's take a float too)
//! - `N`: a numeric scalar or vector, any scalar type (all `N` alike); `S`
//!   is the scalar of that `N`; `NS`: a signed one (float or int: `sign`)
//! - `I`: int or intN / uint or uintN (all `I` alike)
//! - `B`: boolN; `V`: a numeric vector whose `B` result has the same width
//! - `f`, `i`, `b`: float, int, bool; `f2`, `f3`, `f4`: float vectors

use std::sync::OnceLock;

use super::types::{SamplerKind, Scalar, Ty, BOOL, FLOAT};
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
    // daslang's math module (`require math`), beyond GLSL's names.
    /// `mad(a, b, c)`: `a * b + c`, two roundings (as daslang's own GLSL
    /// prelude writes it; `fma` is the fused one). `b` may be a scalar.
    Mad,
    /// `length_sq(x)`: `dot(x, x)`.
    LengthSq,
    /// `distance_sq(a, b)`: `length_sq(a - b)`.
    DistanceSq,
    /// `inv_length(x)`: `1 / length(x)`.
    InvLength,
    /// `inv_length_sq(x)`: `1 / length_sq(x)`.
    InvLengthSq,
    /// `inv_distance(a, b)`: `1 / distance(a, b)`.
    InvDistance,
    /// `inv_distance_sq(a, b)`: `1 / distance_sq(a, b)`.
    InvDistanceSq,
    /// `floori`, `ceili`, `roundi`, `trunci`: the float function, then
    /// `int(...)`.
    ToInt(Mf),
    /// `uint32_hash(seed)`: Squirrel Eiserloh's integer hash, as daslang's
    /// math module computes it (wrapping `uint` arithmetic).
    Hash,
    /// `uint_noise_1D/2D/3D(position, seed)`: the hash of a position with a
    /// seed, over `int`, `int2`, `int3` positions.
    Noise,
    /// `identity3x3()`, `identity4x4()` (and `identity2x2()`).
    Identity,
    /// `packUnorm4x8`, `unpackHalf2x16`, ...: one of naga's pack/unpack
    /// functions (the GL modules compute the ones GLSL 330 or ES 300 lack).
    Pack(Mf),
    /// `barrier()` (a control barrier: every invocation of the workgroup
    /// waits, and workgroup memory is ordered), `memoryBarrier()`,
    /// `memoryBarrierShared()`, `memoryBarrierBuffer()`,
    /// `memoryBarrierImage()`, `groupMemoryBarrier()` (memory order only).
    Barrier { control: bool, flags: naga::Barrier },
    /// `atomicAdd(place, value)` and friends on an integer of a `@ssbo`
    /// or `@groupshared` variable: the value before.
    Atomic(AtomicOp),
    /// `imageLoad(image, coord)`, `imageStore(image, coord, value)`,
    /// `imageSize(image)`.
    ImageLoad,
    ImageStore,
    ImageSize,
    /// `length(buf.data)` of a run-time-sized array: its element count
    /// (`uint`; GLSL's `.length()` is an `int`, converted).
    ArrayLength,
    /// A subgroup operation (dasSpirv's names; sema/check/subgroup.rs).
    Subgroup(SubgroupFn),
    /// `SetMeshOutputsEXT(vertices, primitives)` (a mesh entry point's
    /// output counts) and `EmitMeshTasksEXT(x, y, z)` (a task entry
    /// point's mesh workgroups, and its end), both in the entry point's
    /// own body.
    SetMeshOutputs,
    EmitMeshTasks,
    /// `nonuniformEXT(i)`: marks an index as varying across a subgroup; the
    /// index as it is (umbrac has no descriptor arrays to index with it).
    NonUniform,
}

/// The subgroup operations, as naga's IR has them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubgroupFn {
    /// `subgroupElect()`: true on one active lane.
    Elect,
    /// `subgroupBallot(p)`: a `uint4` of one bit per lane where `p` holds.
    Ballot,
    /// A reduction or scan: `subgroupAdd`, `subgroupAll`,
    /// `subgroupInclusiveMul`, ...
    Collective(naga::CollectiveOperation, naga::SubgroupOperation),
    /// `subgroupBroadcastFirst(v)`, `subgroupBroadcast(v, lane)`,
    /// `subgroupShuffle*(v, n)`.
    Gather(Gather),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Gather {
    BroadcastFirst,
    /// The lane is a constant (SPIR-V before 1.5 and WGSL require one).
    Broadcast,
    Shuffle,
    ShuffleXor,
    ShuffleUp,
    ShuffleDown,
}

/// The atomic read-modify-write functions (GLSL's names).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtomicOp {
    Add,
    Min,
    Max,
    And,
    Or,
    Xor,
    Exchange,
    /// `atomicCompSwap(place, compare, value)`: stores `value` where the
    /// place holds `compare`; the value before either way.
    CompSwap,
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
const UNARY_X: &[Sig] = sigs!["X" <- ["X"]];
const BINARY_X: &[Sig] = sigs!["X" <- ["X", "X"]];

const TABLE: &[Entry] = &[
    Entry { name: "sin", builtin: Builtin::Math(Mf::Sin), sigs: UNARY_X },
    Entry { name: "cos", builtin: Builtin::Math(Mf::Cos), sigs: UNARY_X },
    Entry { name: "tan", builtin: Builtin::Math(Mf::Tan), sigs: UNARY_X },
    Entry { name: "asin", builtin: Builtin::Math(Mf::Asin), sigs: UNARY_X },
    Entry { name: "acos", builtin: Builtin::Math(Mf::Acos), sigs: UNARY_X },
    Entry { name: "atan", builtin: Builtin::Math(Mf::Atan), sigs: UNARY_X },
    Entry { name: "atan2", builtin: Builtin::Math(Mf::Atan2), sigs: BINARY_X },
    Entry { name: "sinh", builtin: Builtin::Math(Mf::Sinh), sigs: UNARY_X },
    Entry { name: "cosh", builtin: Builtin::Math(Mf::Cosh), sigs: UNARY_X },
    Entry { name: "tanh", builtin: Builtin::Math(Mf::Tanh), sigs: UNARY_X },
    Entry { name: "radians", builtin: Builtin::Math(Mf::Radians), sigs: UNARY_X },
    Entry { name: "degrees", builtin: Builtin::Math(Mf::Degrees), sigs: UNARY_X },
    Entry { name: "exp", builtin: Builtin::Math(Mf::Exp), sigs: UNARY_X },
    Entry { name: "exp2", builtin: Builtin::Math(Mf::Exp2), sigs: UNARY_X },
    Entry { name: "log", builtin: Builtin::Math(Mf::Log), sigs: UNARY_X },
    Entry { name: "log2", builtin: Builtin::Math(Mf::Log2), sigs: UNARY_X },
    Entry { name: "sqrt", builtin: Builtin::Math(Mf::Sqrt), sigs: UNARY_X },
    Entry { name: "inversesqrt", builtin: Builtin::Math(Mf::InverseSqrt), sigs: UNARY_X },
    Entry { name: "rsqrt", builtin: Builtin::Math(Mf::InverseSqrt), sigs: UNARY_X },
    Entry { name: "floor", builtin: Builtin::Math(Mf::Floor), sigs: UNARY_X },
    Entry { name: "ceil", builtin: Builtin::Math(Mf::Ceil), sigs: UNARY_X },
    Entry { name: "fract", builtin: Builtin::Math(Mf::Fract), sigs: UNARY_X },
    Entry { name: "trunc", builtin: Builtin::Math(Mf::Trunc), sigs: UNARY_X },
    Entry { name: "round", builtin: Builtin::Math(Mf::Round), sigs: UNARY_X },
    Entry { name: "roundEven", builtin: Builtin::Math(Mf::Round), sigs: UNARY_X },
    Entry { name: "abs", builtin: Builtin::Math(Mf::Abs), sigs: sigs!["N" <- ["N"]] },
    Entry { name: "sign", builtin: Builtin::Math(Mf::Sign), sigs: sigs!["N" <- ["NS"]] },
    Entry { name: "min", builtin: Builtin::Math(Mf::Min), sigs: sigs!["N" <- ["N", "N"]; "N" <- ["N", "S"]] },
    Entry { name: "max", builtin: Builtin::Math(Mf::Max), sigs: sigs!["N" <- ["N", "N"]; "N" <- ["N", "S"]] },
    Entry { name: "clamp", builtin: Builtin::Math(Mf::Clamp), sigs: sigs!["N" <- ["N", "N", "N"]; "N" <- ["N", "S", "S"]] },
    Entry { name: "saturate", builtin: Builtin::Saturate, sigs: UNARY_X },
    Entry { name: "rcp", builtin: Builtin::Rcp, sigs: UNARY_X },
    Entry { name: "mix", builtin: Builtin::Math(Mf::Mix), sigs: sigs!["X" <- ["X", "X", "X"]; "X" <- ["X", "X", "x"]] },
    Entry { name: "lerp", builtin: Builtin::Math(Mf::Mix), sigs: sigs!["X" <- ["X", "X", "X"]; "X" <- ["X", "X", "x"]] },
    Entry { name: "step", builtin: Builtin::Math(Mf::Step), sigs: sigs!["X" <- ["X", "X"]; "X" <- ["x", "X"]] },
    Entry { name: "smoothstep", builtin: Builtin::Math(Mf::SmoothStep), sigs: sigs!["X" <- ["X", "X", "X"]; "X" <- ["x", "x", "X"]] },
    Entry { name: "pow", builtin: Builtin::Math(Mf::Pow), sigs: BINARY_X },
    Entry { name: "mod", builtin: Builtin::Mod, sigs: sigs!["X" <- ["X", "X"]; "X" <- ["X", "x"]] },
    Entry { name: "fma", builtin: Builtin::Math(Mf::Fma), sigs: sigs!["X" <- ["X", "X", "X"]] },
    Entry { name: "length", builtin: Builtin::Math(Mf::Length), sigs: sigs!["x" <- ["X"]] },
    Entry { name: "distance", builtin: Builtin::Math(Mf::Distance), sigs: sigs!["x" <- ["X", "X"]] },
    Entry { name: "dot", builtin: Builtin::Math(Mf::Dot), sigs: sigs!["x" <- ["XV", "XV"]] },
    Entry { name: "cross", builtin: Builtin::Math(Mf::Cross), sigs: sigs!["f3" <- ["f3", "f3"]] },
    Entry { name: "normalize", builtin: Builtin::Math(Mf::Normalize), sigs: sigs!["X" <- ["XV"]] },
    Entry { name: "reflect", builtin: Builtin::Math(Mf::Reflect), sigs: sigs!["X" <- ["XV", "XV"]] },
    Entry { name: "refract", builtin: Builtin::Math(Mf::Refract), sigs: sigs!["X" <- ["XV", "XV", "x"]] },
    Entry { name: "faceforward", builtin: Builtin::Math(Mf::FaceForward), sigs: sigs!["X" <- ["XV", "XV", "XV"]] },
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
    // daslang's math module: its names for GLSL's functions, and the
    // functions daslang's own GLSL generator writes a prelude for.
    Entry { name: "fast_normalize", builtin: Builtin::Math(Mf::Normalize), sigs: UNARY_X },
    Entry { name: "rcp_est", builtin: Builtin::Rcp, sigs: UNARY_X },
    Entry { name: "rsqrt_est", builtin: Builtin::Math(Mf::InverseSqrt), sigs: UNARY_X },
    Entry { name: "atan_est", builtin: Builtin::Math(Mf::Atan), sigs: UNARY_X },
    Entry { name: "atan2_est", builtin: Builtin::Math(Mf::Atan2), sigs: BINARY_X },
    Entry { name: "mad", builtin: Builtin::Mad, sigs: sigs!["N" <- ["N", "N", "N"]; "N" <- ["N", "S", "N"]] },
    Entry { name: "length_sq", builtin: Builtin::LengthSq, sigs: sigs!["x" <- ["X"]] },
    Entry { name: "distance_sq", builtin: Builtin::DistanceSq, sigs: sigs!["x" <- ["X", "X"]] },
    Entry { name: "inv_length", builtin: Builtin::InvLength, sigs: sigs!["x" <- ["X"]] },
    Entry { name: "inv_length_sq", builtin: Builtin::InvLengthSq, sigs: sigs!["x" <- ["X"]] },
    Entry { name: "inv_distance", builtin: Builtin::InvDistance, sigs: sigs!["x" <- ["X", "X"]] },
    Entry { name: "inv_distance_sq", builtin: Builtin::InvDistanceSq, sigs: sigs!["x" <- ["X", "X"]] },
    Entry { name: "floori", builtin: Builtin::ToInt(Mf::Floor), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "ceili", builtin: Builtin::ToInt(Mf::Ceil), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "roundi", builtin: Builtin::ToInt(Mf::Round), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "trunci", builtin: Builtin::ToInt(Mf::Trunc), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "float_bits_to_int", builtin: Builtin::Bitcast(Scalar::Int), sigs: sigs!["GI" <- ["G"]] },
    Entry { name: "float_bits_to_uint", builtin: Builtin::Bitcast(Scalar::Uint), sigs: sigs!["GU" <- ["G"]] },
    Entry { name: "int_bits_to_float", builtin: Builtin::Bitcast(Scalar::Float), sigs: sigs!["G" <- ["GI"]] },
    Entry { name: "uint_bits_to_float", builtin: Builtin::Bitcast(Scalar::Float), sigs: sigs!["G" <- ["GU"]] },
    Entry { name: "uint32_hash", builtin: Builtin::Hash, sigs: sigs!["u" <- ["u"]] },
    Entry { name: "uint_noise_1D", builtin: Builtin::Noise, sigs: sigs!["u" <- ["i", "u"]] },
    Entry { name: "uint_noise_2D", builtin: Builtin::Noise, sigs: sigs!["u" <- ["i2", "u"]] },
    Entry { name: "uint_noise_3D", builtin: Builtin::Noise, sigs: sigs!["u" <- ["i3", "u"]] },
    Entry { name: "identity2x2", builtin: Builtin::Identity, sigs: sigs!["m2" <- []] },
    Entry { name: "identity3x3", builtin: Builtin::Identity, sigs: sigs!["m3" <- []] },
    Entry { name: "identity4x4", builtin: Builtin::Identity, sigs: sigs!["m4" <- []] },
    // Packing (GLSL's names; WGSL's `pack4x8unorm` ...).
    Entry { name: "packUnorm4x8", builtin: Builtin::Pack(Mf::Pack4x8unorm), sigs: sigs!["u" <- ["f4"]] },
    Entry { name: "packSnorm4x8", builtin: Builtin::Pack(Mf::Pack4x8snorm), sigs: sigs!["u" <- ["f4"]] },
    Entry { name: "packUnorm2x16", builtin: Builtin::Pack(Mf::Pack2x16unorm), sigs: sigs!["u" <- ["f2"]] },
    Entry { name: "packSnorm2x16", builtin: Builtin::Pack(Mf::Pack2x16snorm), sigs: sigs!["u" <- ["f2"]] },
    Entry { name: "packHalf2x16", builtin: Builtin::Pack(Mf::Pack2x16float), sigs: sigs!["u" <- ["f2"]] },
    Entry { name: "unpackUnorm4x8", builtin: Builtin::Pack(Mf::Unpack4x8unorm), sigs: sigs!["f4" <- ["u"]] },
    Entry { name: "unpackSnorm4x8", builtin: Builtin::Pack(Mf::Unpack4x8snorm), sigs: sigs!["f4" <- ["u"]] },
    Entry { name: "unpackUnorm2x16", builtin: Builtin::Pack(Mf::Unpack2x16unorm), sigs: sigs!["f2" <- ["u"]] },
    Entry { name: "unpackSnorm2x16", builtin: Builtin::Pack(Mf::Unpack2x16snorm), sigs: sigs!["f2" <- ["u"]] },
    Entry { name: "unpackHalf2x16", builtin: Builtin::Pack(Mf::Unpack2x16float), sigs: sigs!["f2" <- ["u"]] },
];

/// Constants of daslang's `math` and `builtin` modules that shaders can
/// use, with their `f32`/`i32`/`u32` values (a local or top-level name of
/// the program hides one).
pub const CONSTANTS: &[(&str, super::types::ConstValue)] = {
    use super::types::ConstValue as C;
    &[
        ("PI", C::Float(std::f32::consts::PI as f64)),
        ("FLT_EPSILON", C::Float(f32::EPSILON as f64)),
        ("FLT_MAX", C::Float(f32::MAX as f64)),
        ("FLT_MIN", C::Float(f32::MIN_POSITIVE as f64)),
        ("INT_MAX", C::Int(i32::MAX as i64)),
        ("INT_MIN", C::Int(i32::MIN as i64)),
        ("UINT_MAX", C::Uint(u32::MAX as u64)),
    ]
};

/// The value and type of a builtin constant.
pub fn constant(name: &str) -> Option<(super::types::ConstValue, Ty)> {
    use super::types::ConstValue as C;
    CONSTANTS.iter().find(|(n, _)| *n == name).map(|(_, v)| {
        let ty = match v {
            C::Int(_) => super::types::INT,
            C::Uint(_) => super::types::UINT,
            _ => FLOAT,
        };
        (v.clone(), ty)
    })
}

/// Names of daslang's module constants no shader type can hold, with what
/// to do instead.
pub const UNSUPPORTED_CONSTANTS: &[(&str, &str)] = &[
    ("DBL_PI", "shaders have no `double`: use `PI`"),
    ("DBL_EPSILON", "shaders have no `double`: use `FLT_EPSILON`"),
    ("DBL_MAX", "shaders have no `double`: use `FLT_MAX`"),
    ("DBL_MIN", "shaders have no `double`: use `FLT_MIN`"),
    ("LONG_MAX", "shaders have no 64-bit integers: use `INT_MAX`"),
    ("LONG_MIN", "shaders have no 64-bit integers: use `INT_MIN`"),
    ("ULONG_MAX", "shaders have no 64-bit integers: use `UINT_MAX`"),
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

/// GLSL 1.x's texture functions (`texture2D`, ...): the modern function
/// each is, the sampler type it takes, and that function's name. They
/// compile, with a warning.
pub const LEGACY_TEXTURE_FUNCTIONS: &[(&str, Builtin, SamplerKind, &str)] = &[
    ("texture2D", Builtin::Texture, SamplerKind::Sampler2D, "texture"),
    ("texture2DLod", Builtin::TextureLod, SamplerKind::Sampler2D, "textureLod"),
    ("texture3D", Builtin::Texture, SamplerKind::Sampler3D, "texture"),
    ("texture3DLod", Builtin::TextureLod, SamplerKind::Sampler3D, "textureLod"),
    ("textureCube", Builtin::Texture, SamplerKind::SamplerCube, "texture"),
    ("textureCubeLod", Builtin::TextureLod, SamplerKind::SamplerCube, "textureLod"),
];

/// Names of GLSL functions the DSL deliberately lacks, with the reason and
/// what to do instead.
pub const UNSUPPORTED: &[(&str, &str)] = &[
    ("isnan", "WGSL has no isnan, and GPU compilers may assume that values are never NaN"),
    ("isinf", "WGSL has no isinf; compare against a large bound instead"),
    ("textureGather", "not supported yet"),
    // daslang's math module: functions no target can run as daslang means
    // them, or that build host-side data.
    ("is_nan", "WGSL has no isnan, and GPU compilers may assume that values are never NaN"),
    ("is_finite", "WGSL has no isinf or isnan; compare against a large bound instead"),
    ("pack_float_to_byte", "daslang's byte rounding is its host CPU's; use packUnorm4x8(v / 255.0), which rounds to nearest on every target"),
    ("unpack_byte_to_float", "use unpackUnorm4x8(u) * 255.0"),
    ("quat_from_unit_arc", "quaternions are daslang host code; write the function in the shader"),
    ("quat_from_unit_vec_ang", "quaternions are daslang host code; write the function in the shader"),
    ("quat_from_euler", "quaternions are daslang host code; write the function in the shader"),
    ("euler_from_quat", "quaternions are daslang host code; write the function in the shader"),
    ("quat_mul", "quaternions are daslang host code; write the function in the shader"),
    ("quat_mul_vec", "quaternions are daslang host code; write the function in the shader"),
    ("quat_conjugate", "quaternions are daslang host code; write the function in the shader"),
    ("quat_slerp", "quaternions are daslang host code; write the function in the shader"),
    ("quat", "quaternions are daslang host code; write the function in the shader"),
    ("translation", "build the matrix on the host and pass it as a `@uniform`"),
    ("look_at", "build the matrix on the host and pass it as a `@uniform`"),
    ("persp_forward", "build the matrix on the host and pass it as a `@uniform`"),
    ("persp_reverse", "build the matrix on the host and pass it as a `@uniform`"),
    ("compose", "build the matrix on the host and pass it as a `@uniform`"),
    ("decompose", "decompose the matrix on the host and pass the parts as `@uniform`s"),
    ("orthonormal_inverse", "use transpose(m) for a rotation, or inverse(m)"),
    ("rotate", "daslang's `float3x4` is not umbrac's (docs/language.md); multiply by a `float3x3` instead"),
    ("identity", "assign `identity4x4()` (or `identity3x3()`) instead"),
    ("identity3x4", "daslang's `float3x4` is not umbrac's (docs/language.md); use `identity4x4()` or `float3x4(1.0)`"),
    // daslang host constructs its GLSL generator refuses by name
    // (glsl_internal.das): refused here by name too, never "unknown".
    ("memzero", "daslang's shader emitters refuse it too: a shader has no memory to clear; assign the zero value (`x = T()`) or declare `var x : T`, which starts at zero"),
    ("assert", "daslang's shader emitters refuse it too: a shader cannot stop or report; test the condition and write a result the host can see"),
    ("verify", "daslang's shader emitters refuse it too: a shader cannot stop or report; test the condition and write a result the host can see"),
    ("static_assert", "daslang's shader emitters refuse it too: check the constant on the host"),
    ("debug", "daslang's shader emitters refuse it too: a shader has no console; write the value to an output or a storage buffer"),
    ("print", "a shader has no console; write the value to an output or a storage buffer"),
    ("invoke", "daslang's shader emitters refuse it too: blocks and lambdas are host code; call a function"),
    ("typeinfo", "daslang's shader emitters refuse it too: reflection is host code"),
    ("erase", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("insert", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("find", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("key_exists", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("keys", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("values", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("push", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("push_clone", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("emplace", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("resize", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("reserve", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
    ("clear", "daslang's shader emitters refuse it too: dynamic arrays and tables are host code; shaders have fixed arrays (`T[N]`)"),
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
    /// `X`'s scalar (float or half) and width.
    xs: Option<Scalar>,
    xw: Option<u8>,
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
        "X" => match *ty {
            Ty::Scalar(s) if s.is_float() => unify(&mut bind.xs, s) && unify(&mut bind.xw, 1),
            Ty::Vector(s, n) if s.is_float() => unify(&mut bind.xs, s) && unify(&mut bind.xw, n),
            _ => false,
        },
        "x" => match *ty {
            Ty::Scalar(s) if s.is_float() => unify(&mut bind.xs, s),
            _ => false,
        },
        "XV" => match *ty {
            Ty::Vector(s, n) if s.is_float() => unify(&mut bind.xs, s) && unify(&mut bind.xw, n),
            _ => false,
        },
        "N" => match (ty.scalar(), ty.width()) {
            (Some(s), Some(w)) if s.is_numeric() => unify(&mut bind.n, (s, w)),
            _ => false,
        },
        "NS" => match (ty.scalar(), ty.width()) {
            (Some(s @ (Scalar::Float | Scalar::Half | Scalar::Int)), Some(w)) => unify(&mut bind.n, (s, w)),
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
        "i" => *ty == Ty::Scalar(Scalar::Int),
        "u" => *ty == Ty::Scalar(Scalar::Uint),
        "f2" => *ty == Ty::Vector(Scalar::Float, 2),
        "f3" => *ty == Ty::Vector(Scalar::Float, 3),
        "f4" => *ty == Ty::Vector(Scalar::Float, 4),
        "i2" => *ty == Ty::Vector(Scalar::Int, 2),
        "i3" => *ty == Ty::Vector(Scalar::Int, 3),
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
        "X" => Ty::vec(bind.xs.unwrap_or(Scalar::Float), bind.xw?),
        "x" => Ty::Scalar(bind.xs.unwrap_or(Scalar::Float)),
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
        "u" => Ty::Scalar(Scalar::Uint),
        "f2" => Ty::Vector(Scalar::Float, 2),
        "f3" => Ty::Vector(Scalar::Float, 3),
        "f4" => Ty::Vector(Scalar::Float, 4),
        "m2" => Ty::Matrix(2, 2),
        "m3" => Ty::Matrix(3, 3),
        "m4" => Ty::Matrix(4, 4),
        _ => return None,
    })
}

fn pattern_text(p: &str) -> &'static str {
    match p {
        "G" => "floatN",
        "X" => "floatN",
        "x" => "float",
        "XV" => "float2/3/4",
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
        "i" => "int",
        "u" => "uint",
        "f2" => "float2",
        "f3" => "float3",
        "f4" => "float4",
        "i2" => "int2",
        "i3" => "int3",
        "m2" => "float2x2",
        "m3" => "float3x3",
        "m4" => "float4x4",
        _ => "?",
    }
}

/// A builtin function's overloads, as editors show them: each one's text
/// and its parameters' (`[]` for a name that is no builtin function).
pub fn signatures(name: &str) -> Vec<(String, Vec<String>)> {
    if let Some(e) = entry(name) {
        return e.sigs.iter().map(|s| (format_sig(e.name, s), s.args.iter().map(|a| pattern_text(a).to_string()).collect())).collect();
    }
    super::builtin_docs::texture_signatures(name)
        .iter()
        .map(|sig| {
            let inner = sig.split_once('(').and_then(|(_, rest)| rest.rsplit_once(')')).map_or("", |(args, _)| args);
            (sig.to_string(), inner.split(", ").map(String::from).collect())
        })
        .collect()
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
