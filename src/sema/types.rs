//! The DSL's types.

use std::fmt;

use crate::source::Span;


#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    Float,
    Int,
    Uint,
    Bool,
    /// `half` (`float16`): 16-bit float, WGSL's `f16` and SPIR-V's Float16;
    /// no GLSL target has it.
    Half,
}

impl Scalar {
    pub fn name(self) -> &'static str {
        match self {
            Scalar::Float => "float",
            Scalar::Int => "int",
            Scalar::Uint => "uint",
            Scalar::Bool => "bool",
            Scalar::Half => "half",
        }
    }

    /// `float` or `half`.
    pub fn is_float(self) -> bool {
        matches!(self, Scalar::Float | Scalar::Half)
    }

    pub fn is_numeric(self) -> bool {
        self != Scalar::Bool
    }

    pub fn is_integer(self) -> bool {
        matches!(self, Scalar::Int | Scalar::Uint)
    }
}

/// The sampler types of the DSL.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerKind {
    Sampler2D,
    Sampler2DShadow,
    Sampler2DArray,
    Sampler2DArrayShadow,
    Sampler3D,
    SamplerCube,
    SamplerCubeShadow,
    ISampler2D,
    USampler2D,
}

impl SamplerKind {
    pub const ALL: [SamplerKind; 9] = [
        SamplerKind::Sampler2D,
        SamplerKind::Sampler2DShadow,
        SamplerKind::Sampler2DArray,
        SamplerKind::Sampler2DArrayShadow,
        SamplerKind::Sampler3D,
        SamplerKind::SamplerCube,
        SamplerKind::SamplerCubeShadow,
        SamplerKind::ISampler2D,
        SamplerKind::USampler2D,
    ];

    /// The DSL (and GLSL) type name.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Sampler2D => "sampler2D",
            SamplerKind::Sampler2DShadow => "sampler2DShadow",
            SamplerKind::Sampler2DArray => "sampler2DArray",
            SamplerKind::Sampler2DArrayShadow => "sampler2DArrayShadow",
            SamplerKind::Sampler3D => "sampler3D",
            SamplerKind::SamplerCube => "samplerCube",
            SamplerKind::SamplerCubeShadow => "samplerCubeShadow",
            SamplerKind::ISampler2D => "isampler2D",
            SamplerKind::USampler2D => "usampler2D",
        }
    }

    pub fn from_name(name: &str) -> Option<SamplerKind> {
        SamplerKind::ALL.into_iter().find(|k| k.name() == name)
    }

    pub fn is_shadow(self) -> bool {
        matches!(self, SamplerKind::Sampler2DShadow | SamplerKind::Sampler2DArrayShadow | SamplerKind::SamplerCubeShadow)
    }

    pub fn is_array(self) -> bool {
        matches!(self, SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow)
    }

    pub fn dim(self) -> naga::ImageDimension {
        match self {
            SamplerKind::Sampler3D => naga::ImageDimension::D3,
            SamplerKind::SamplerCube | SamplerKind::SamplerCubeShadow => naga::ImageDimension::Cube,
            _ => naga::ImageDimension::D2,
        }
    }

    /// The naga image class of the texture half.
    pub fn image_class(self) -> naga::ImageClass {
        match self {
            k if k.is_shadow() => naga::ImageClass::Depth { multi: false },
            SamplerKind::ISampler2D => naga::ImageClass::Sampled { kind: naga::ScalarKind::Sint, multi: false },
            SamplerKind::USampler2D => naga::ImageClass::Sampled { kind: naga::ScalarKind::Uint, multi: false },
            _ => naga::ImageClass::Sampled { kind: naga::ScalarKind::Float, multi: false },
        }
    }
}

/// The shape of a storage image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ImageDim {
    D2,
    D3,
    D2Array,
}

/// A storage image type: `image2D`, `iimage2D`, `uimage2D`, and the same
/// for `3D` and `2DArray`. The texel scalar is `Float`, `Int` or `Uint`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ImageKind {
    pub dim: ImageDim,
    pub scalar: Scalar,
}

impl ImageKind {
    pub fn name(self) -> String {
        let prefix = match self.scalar {
            Scalar::Int => "i",
            Scalar::Uint => "u",
            _ => "",
        };
        let dim = match self.dim {
            ImageDim::D2 => "2D",
            ImageDim::D3 => "3D",
            ImageDim::D2Array => "2DArray",
        };
        format!("{prefix}image{dim}")
    }

    pub fn from_name(name: &str) -> Option<ImageKind> {
        let (scalar, rest) = match name.as_bytes().first()? {
            b'i' if name.starts_with("iimage") => (Scalar::Int, &name[6..]),
            b'u' if name.starts_with("uimage") => (Scalar::Uint, &name[6..]),
            _ => (Scalar::Float, name.strip_prefix("image")?),
        };
        let dim = match rest {
            "2D" => ImageDim::D2,
            "3D" => ImageDim::D3,
            "2DArray" => ImageDim::D2Array,
            _ => return None,
        };
        Some(ImageKind { dim, scalar })
    }

    /// Components of a texel coordinate (`int2`, `int3`).
    pub fn coord_width(self) -> u8 {
        match self.dim {
            ImageDim::D2 => 2,
            _ => 3,
        }
    }
}

/// The texel formats of storage images every target with images has
/// (GLSL ES 3.10's list, all of which WGSL has): the DSL spelling is
/// GLSL's layout qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ImageFormat {
    Rgba8,
    Rgba8Snorm,
    Rgba8ui,
    Rgba8i,
    Rgba16f,
    Rgba16ui,
    Rgba16i,
    Rgba32f,
    Rgba32ui,
    Rgba32i,
    R32f,
    R32ui,
    R32i,
}

impl ImageFormat {
    pub const ALL: [ImageFormat; 13] = [
        ImageFormat::Rgba8,
        ImageFormat::Rgba8Snorm,
        ImageFormat::Rgba8ui,
        ImageFormat::Rgba8i,
        ImageFormat::Rgba16f,
        ImageFormat::Rgba16ui,
        ImageFormat::Rgba16i,
        ImageFormat::Rgba32f,
        ImageFormat::Rgba32ui,
        ImageFormat::Rgba32i,
        ImageFormat::R32f,
        ImageFormat::R32ui,
        ImageFormat::R32i,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ImageFormat::Rgba8 => "rgba8",
            ImageFormat::Rgba8Snorm => "rgba8_snorm",
            ImageFormat::Rgba8ui => "rgba8ui",
            ImageFormat::Rgba8i => "rgba8i",
            ImageFormat::Rgba16f => "rgba16f",
            ImageFormat::Rgba16ui => "rgba16ui",
            ImageFormat::Rgba16i => "rgba16i",
            ImageFormat::Rgba32f => "rgba32f",
            ImageFormat::Rgba32ui => "rgba32ui",
            ImageFormat::Rgba32i => "rgba32i",
            ImageFormat::R32f => "r32f",
            ImageFormat::R32ui => "r32ui",
            ImageFormat::R32i => "r32i",
        }
    }

    pub fn from_name(name: &str) -> Option<ImageFormat> {
        ImageFormat::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The scalar of the image types this format goes with.
    pub fn scalar(self) -> Scalar {
        match self {
            ImageFormat::Rgba8ui | ImageFormat::Rgba16ui | ImageFormat::Rgba32ui | ImageFormat::R32ui => Scalar::Uint,
            ImageFormat::Rgba8i | ImageFormat::Rgba16i | ImageFormat::Rgba32i | ImageFormat::R32i => Scalar::Int,
            _ => Scalar::Float,
        }
    }

    /// Read-write access (no `@readonly`/`@writeonly`) is allowed only for
    /// the single-channel 32-bit formats (GLSL ES 3.10, WGSL).
    pub fn allows_read_write(self) -> bool {
        matches!(self, ImageFormat::R32f | ImageFormat::R32ui | ImageFormat::R32i)
    }

    pub fn naga(self) -> naga::StorageFormat {
        use naga::StorageFormat as F;
        match self {
            ImageFormat::Rgba8 => F::Rgba8Unorm,
            ImageFormat::Rgba8Snorm => F::Rgba8Snorm,
            ImageFormat::Rgba8ui => F::Rgba8Uint,
            ImageFormat::Rgba8i => F::Rgba8Sint,
            ImageFormat::Rgba16f => F::Rgba16Float,
            ImageFormat::Rgba16ui => F::Rgba16Uint,
            ImageFormat::Rgba16i => F::Rgba16Sint,
            ImageFormat::Rgba32f => F::Rgba32Float,
            ImageFormat::Rgba32ui => F::Rgba32Uint,
            ImageFormat::Rgba32i => F::Rgba32Sint,
            ImageFormat::R32f => F::R32Float,
            ImageFormat::R32ui => F::R32Uint,
            ImageFormat::R32i => F::R32Sint,
        }
    }

    /// The WGSL / WebGPU name of the format (the manifest's `wgpu_format`).
    pub fn wgsl_name(self) -> &'static str {
        match self {
            ImageFormat::Rgba8 => "rgba8unorm",
            ImageFormat::Rgba8Snorm => "rgba8snorm",
            ImageFormat::Rgba8ui => "rgba8uint",
            ImageFormat::Rgba8i => "rgba8sint",
            ImageFormat::Rgba16f => "rgba16float",
            ImageFormat::Rgba16ui => "rgba16uint",
            ImageFormat::Rgba16i => "rgba16sint",
            ImageFormat::Rgba32f => "rgba32float",
            ImageFormat::Rgba32ui => "rgba32uint",
            ImageFormat::Rgba32i => "rgba32sint",
            ImageFormat::R32f => "r32float",
            ImageFormat::R32ui => "r32uint",
            ImageFormat::R32i => "r32sint",
        }
    }
}

/// How a shader may use a storage image or buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Access {
    ReadWrite,
    /// `@readonly`.
    Read,
    /// `@writeonly` (images only).
    Write,
}

impl Access {
    pub fn name(self) -> &'static str {
        match self {
            Access::ReadWrite => "read_write",
            Access::Read => "read",
            Access::Write => "write",
        }
    }

    pub fn naga(self) -> naga::StorageAccess {
        match self {
            Access::ReadWrite => naga::StorageAccess::LOAD | naga::StorageAccess::STORE,
            Access::Read => naga::StorageAccess::LOAD,
            Access::Write => naga::StorageAccess::STORE,
        }
    }
}

/// Index of a struct in `sema::Program::structs`.
pub type StructId = usize;

/// Index of an enumeration in `sema::Program::enums`.
pub type EnumId = u32;

#[derive(Debug, PartialEq, Eq, Hash)]
pub enum Ty {
    Scalar(Scalar),
    /// 2, 3 or 4 components.
    Vector(Scalar, u8),
    /// Float matrix: columns, rows.
    Matrix(u8, u8),
    Array(Box<Ty>, u32),
    Struct(StructId),
    /// An enumeration: a distinct type of named `int` (or `uint`) values,
    /// compared and used as indices, converted with `int(e)`.
    Enum(EnumId),
    Sampler(SamplerKind),
    /// A storage image (`image2D`, `uimage3D`, ...): its format and access
    /// are the global's (`GlobalKind::Image`).
    Image(ImageKind),
    /// `T[]`: the run-time-sized last member of a `@ssbo` struct; its
    /// length is the bound buffer's (`length(buf.data)`).
    RuntimeArray(Box<Ty>),
    /// The type of a call to a function without a result.
    Void,
    /// Stands in after an error so one mistake does not cascade.
    Error,
}

/// Written out so that the common case, a type without a box, is a copy
/// inlined where it happens (the derived clone is a call for every
/// expression's type).
impl Clone for Ty {
    #[inline]
    fn clone(&self) -> Ty {
        match self {
            Ty::Scalar(s) => Ty::Scalar(*s),
            Ty::Vector(s, n) => Ty::Vector(*s, *n),
            Ty::Matrix(c, r) => Ty::Matrix(*c, *r),
            Ty::Struct(id) => Ty::Struct(*id),
            Ty::Enum(id) => Ty::Enum(*id),
            Ty::Sampler(k) => Ty::Sampler(*k),
            Ty::Image(k) => Ty::Image(*k),
            Ty::Void => Ty::Void,
            Ty::Error => Ty::Error,
            Ty::Array(..) | Ty::RuntimeArray(_) => self.clone_boxed(),
        }
    }
}

impl Ty {
    #[inline(never)]
    fn clone_boxed(&self) -> Ty {
        match self {
            Ty::Array(elem, n) => Ty::Array(elem.clone(), *n),
            Ty::RuntimeArray(elem) => Ty::RuntimeArray(elem.clone()),
            _ => unreachable!("only the boxed types"),
        }
    }
}

pub const FLOAT: Ty = Ty::Scalar(Scalar::Float);
pub const INT: Ty = Ty::Scalar(Scalar::Int);
pub const UINT: Ty = Ty::Scalar(Scalar::Uint);
pub const BOOL: Ty = Ty::Scalar(Scalar::Bool);
pub const HALF: Ty = Ty::Scalar(Scalar::Half);

/// Vector type names by scalar (`Scalar` order) and size 2-4.
const VECTOR_NAMES: [[&str; 3]; 5] = [
    ["float2", "float3", "float4"],
    ["int2", "int3", "int4"],
    ["uint2", "uint3", "uint4"],
    ["bool2", "bool3", "bool4"],
    ["half2", "half3", "half4"],
];

/// Matrix type names by columns and rows 2-4.
const MATRIX_NAMES: [[&str; 3]; 3] = [
    ["float2x2", "float2x3", "float2x4"],
    ["float3x2", "float3x3", "float3x4"],
    ["float4x2", "float4x3", "float4x4"],
];

impl Ty {
    /// The spelling of a scalar, vector or matrix type, as [`TyDisplay`]
    /// writes it, without formatting (lowering spells many of them).
    pub fn builtin_name(&self) -> Option<&'static str> {
        match *self {
            Ty::Scalar(s) => Some(s.name()),
            Ty::Vector(s, n @ 2..=4) => Some(VECTOR_NAMES[s as usize][n as usize - 2]),
            Ty::Matrix(c @ 2..=4, r @ 2..=4) => Some(MATRIX_NAMES[c as usize - 2][r as usize - 2]),
            _ => None,
        }
    }

    /// A scalar or vector of `scalar` with `n` components (1 = scalar).
    pub fn vec(scalar: Scalar, n: u8) -> Ty {
        if n == 1 {
            Ty::Scalar(scalar)
        } else {
            Ty::Vector(scalar, n)
        }
    }

    /// The scalar of a scalar, vector or matrix.
    pub fn scalar(&self) -> Option<Scalar> {
        match *self {
            Ty::Scalar(s) | Ty::Vector(s, _) => Some(s),
            Ty::Matrix(..) => Some(Scalar::Float),
            _ => None,
        }
    }

    /// Component count of a scalar (1) or vector.
    pub fn width(&self) -> Option<u8> {
        match *self {
            Ty::Scalar(_) => Some(1),
            Ty::Vector(_, n) => Some(n),
            _ => None,
        }
    }

    pub fn is_error(&self) -> bool {
        matches!(self, Ty::Error)
    }

    /// Whether values of this type can be stored in variables, passed and returned.
    pub fn is_value(&self) -> bool {
        match self {
            Ty::Sampler(_) | Ty::Image(_) | Ty::RuntimeArray(_) | Ty::Void => false,
            Ty::Array(elem, _) => elem.is_value(),
            _ => true,
        }
    }

    /// A sampler or an array of samplers.
    /// Whether `half` is part of the type (a struct's fields are looked up
    /// in `structs`).
    pub fn has_half(&self, structs: &[StructDef]) -> bool {
        match self {
            Ty::Scalar(Scalar::Half) | Ty::Vector(Scalar::Half, _) => true,
            Ty::Array(elem, _) => elem.has_half(structs),
            Ty::Struct(id) => structs.get(*id).is_some_and(|s| s.fields.iter().any(|f| f.1.has_half(structs))),
            _ => false,
        }
    }

    pub fn is_sampler_like(&self) -> bool {
        match self {
            Ty::Sampler(_) => true,
            Ty::Array(elem, _) => elem.is_sampler_like(),
            _ => false,
        }
    }

    /// Parses a builtin type name (`float3`, `int`, `float4x4`, `sampler2D`).
    pub fn from_builtin_name(name: &str) -> Option<Ty> {
        if let Some(k) = SamplerKind::from_name(name) {
            return Some(Ty::Sampler(k));
        }
        if let Some(k) = ImageKind::from_name(name) {
            return Some(Ty::Image(k));
        }
        if name == "float16" {
            return Some(Ty::Scalar(Scalar::Half));
        }
        let (base, scalar) = [("float", Scalar::Float), ("int", Scalar::Int), ("uint", Scalar::Uint), ("bool", Scalar::Bool), ("half", Scalar::Half)]
            .into_iter()
            .find(|(p, _)| name.starts_with(p))?;
        let rest = &name[base.len()..];
        match rest.as_bytes() {
            [] => Some(Ty::Scalar(scalar)),
            [n @ b'2'..=b'4'] => Some(Ty::Vector(scalar, n - b'0')),
            [c @ b'2'..=b'4', b'x', r @ b'2'..=b'4'] if scalar == Scalar::Float => Some(Ty::Matrix(c - b'0', r - b'0')),
            _ => None,
        }
    }
}

/// Why a type name no target has is refused (`int8`, `byte2`, `uint64`,
/// `double`), and what to use instead; `None` for other names.
pub fn unsupported_type(name: &str) -> Option<(String, &'static str)> {
    let (base, digits) = match name.find(|c: char| c.is_ascii_digit()) {
        Some(k) => (&name[..k], &name[k..]),
        None => (name, ""),
    };
    // daslang's 8- and 16-lane forms (`byte8`, `half8`, `float8`): CPU
    // only, as its shader emitters say; `int8`/`uint8` are 8-bit scalars.
    let lanes: u32 = digits.parse().unwrap_or(0);
    let wide = match base {
        "float" | "half" | "bool" | "short" | "ushort" | "byte" | "ubyte" => lanes > 4,
        "int" | "uint" => lanes > 4 && lanes != 8 && lanes != 16 && lanes != 64,
        _ => false,
    };
    if wide {
        return Some((
            format!("`{name}`: vectors of {lanes} components are CPU-only in daslang, not a shader type"),
            "shader vectors have at most 4 components (daslang's shader emitters refuse its 8- and 16-lane forms): split it into 4-component vectors",
        ));
    }
    let bits = match (base, digits) {
        ("int" | "uint", "8" | "16" | "64") => digits,
        ("byte" | "ubyte" | "char" | "uchar", "" | "2" | "3" | "4") => "8",
        ("short" | "ushort", "" | "2" | "3" | "4") => "16",
        ("long" | "ulong", "" | "2" | "3" | "4") | ("int64" | "uint64", _) => "64",
        ("double", "" | "2" | "3" | "4") => return Some((format!("`{name}` (64-bit float) is not supported by any target (glsl330, gles300, wgsl, spirv)"), "GLSL 330, GLSL ES 3.00 and WGSL have no double precision: use `float`")),
        _ => return None,
    };
    let help = match bits {
        "8" => "GLSL 330, GLSL ES 3.00 and WGSL have no 8-bit integers: use `int`/`uint` (vectors `int2`, `uint4`, ...) and mask with `& 0xFF`, or keep four bytes in a `uint` (packUnorm4x8 / unpackUnorm4x8)",
        "16" => "GLSL 330, GLSL ES 3.00 and WGSL have no 16-bit integers: use `int`/`uint` (vectors `int2`, `uint4`, ...), or keep two halves in a `uint`",
        _ => "GLSL 330, GLSL ES 3.00 and WGSL have no 64-bit integers: use `int`/`uint`, or two `uint`s",
    };
    Some((format!("`{name}` ({bits}-bit integer) is not supported by any target (glsl330, gles300, wgsl, spirv)"), help))
}

/// Displays a type by its DSL spelling; struct names come from the program.
pub struct TyDisplay<'a> {
    pub ty: &'a Ty,
    pub struct_names: &'a [String],
    pub enum_names: &'a [String],
}

impl fmt::Display for TyDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(name) = self.ty.builtin_name() {
            return f.write_str(name);
        }
        match self.ty {
            Ty::Scalar(s) => f.write_str(s.name()),
            Ty::Vector(s, n) => write!(f, "{}{}", s.name(), n),
            Ty::Matrix(c, r) => write!(f, "float{c}x{r}"),
            Ty::Array(elem, n) => write!(f, "{}[{}]", TyDisplay { ty: elem, ..*self }, n),
            Ty::Struct(id) => f.write_str(self.struct_names.get(*id).map(|s| s.as_str()).unwrap_or("<struct>")),
            Ty::Enum(id) => f.write_str(self.enum_names.get(*id as usize).map(|s| s.as_str()).unwrap_or("<enum>")),
            Ty::Sampler(k) => f.write_str(k.name()),
            Ty::Image(k) => f.write_str(&k.name()),
            Ty::RuntimeArray(elem) => write!(f, "{}[]", TyDisplay { ty: elem, ..*self }),
            Ty::Void => f.write_str("void"),
            Ty::Error => f.write_str("{error}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_names_spell_scalar_vector_and_matrix_types() {
        for s in [Scalar::Float, Scalar::Int, Scalar::Uint, Scalar::Bool] {
            assert_eq!(Ty::Scalar(s).builtin_name(), Some(s.name()));
            for n in 2..=4u8 {
                assert_eq!(Ty::Vector(s, n).builtin_name(), Some(format!("{}{n}", s.name()).as_str()));
            }
        }
        for c in 2..=4u8 {
            for r in 2..=4u8 {
                assert_eq!(Ty::Matrix(c, r).builtin_name(), Some(format!("float{c}x{r}").as_str()));
            }
        }
        assert_eq!(Ty::Struct(0).builtin_name(), None);
    }
}

/// A struct declaration: its fields in order.
#[derive(Debug)]
pub struct StructDef {
    pub name: String,
    pub fields: Vec<(String, Ty, Span)>,
    pub span: Span,
}

/// A compile-time value of a top-level `let`.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstValue {
    Float(f64),
    Int(i64),
    Uint(u64),
    Bool(bool),
    /// Vector, matrix (columns), array or struct components.
    Composite(Vec<ConstValue>),
}
