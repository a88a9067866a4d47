//! The identifiers a GL host binds by: the source's names, renamed by one
//! rule where GLSL cannot take them.
//!
//! GLSL 330 and GLSL ES 3.00 reserve their keywords, the words reserved for
//! future use, the names of their builtin functions (a global of that name
//! would hide the function) and every name starting with `gl_`. A source
//! name that is one of those, or that another identifier of the file
//! already uses, becomes the name followed by `_` (naga's own rule for the
//! names it makes), then `_1`, `_2` ... until it is free. The manifest
//! records every GLSL name (`glsl_name`), so a host never guesses.

/// Keywords, reserved words and builtin function names of GLSL 330 core and
/// GLSL ES 3.00 (their specifications, sections 3.6 and 8).
const RESERVED: &[&str] = &[
    // Keywords.
    "attribute", "const", "uniform", "varying", "layout", "centroid", "flat", "smooth", "noperspective", "break", "continue", "do", "for", "while",
    "switch", "case", "default", "if", "else", "in", "out", "inout", "float", "int", "void", "bool", "true", "false", "invariant", "discard", "return",
    "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2", "vec3", "vec4", "ivec2",
    "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "uint", "uvec2", "uvec3", "uvec4", "lowp", "mediump", "highp", "precision", "struct",
    "sampler1D", "sampler2D", "sampler3D", "samplerCube", "sampler1DShadow", "sampler2DShadow", "samplerCubeShadow", "sampler1DArray",
    "sampler2DArray", "sampler1DArrayShadow", "sampler2DArrayShadow", "isampler1D", "isampler2D", "isampler3D", "isamplerCube", "isampler1DArray",
    "isampler2DArray", "usampler1D", "usampler2D", "usampler3D", "usamplerCube", "usampler1DArray", "usampler2DArray", "sampler2DRect",
    "sampler2DRectShadow", "isampler2DRect", "usampler2DRect", "samplerBuffer", "isamplerBuffer", "usamplerBuffer", "sampler2DMS",
    "isampler2DMS", "usampler2DMS", "sampler2DMSArray", "isampler2DMSArray", "usampler2DMSArray",
    // Reserved for future use.
    "coherent", "volatile", "restrict", "readonly", "writeonly", "resource", "atomic_uint", "patch", "sample", "subroutine", "common",
    "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "goto", "inline", "noinline", "public", "static",
    "extern", "external", "interface", "long", "short", "double", "half", "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3",
    "hvec4", "dvec2", "dvec3", "dvec4", "fvec2", "fvec3", "fvec4", "sampler3DRect", "filter", "image1D", "image2D", "image3D", "imageCube",
    "iimage1D", "iimage2D", "iimage3D", "iimageCube", "uimage1D", "uimage2D", "uimage3D", "uimageCube", "image1DArray", "image2DArray",
    "iimage1DArray", "iimage2DArray", "uimage1DArray", "uimage2DArray", "imageBuffer", "iimageBuffer", "uimageBuffer", "sizeof", "cast",
    "namespace", "using", "dmat2", "dmat3", "dmat4", "precise", "buffer", "shared",
    // Builtin functions.
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "pow", "exp", "log",
    "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "trunc", "round", "roundEven", "ceil", "fract", "mod", "modf", "min", "max",
    "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat", "fma",
    "frexp", "ldexp", "packSnorm2x16", "unpackSnorm2x16", "packUnorm2x16", "unpackUnorm2x16", "packHalf2x16", "unpackHalf2x16", "packUnorm4x8",
    "packSnorm4x8", "unpackUnorm4x8", "unpackSnorm4x8", "length", "distance", "dot", "cross", "normalize", "faceforward", "reflect", "refract",
    "matrixCompMult", "outerProduct", "transpose", "determinant", "inverse", "lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual",
    "equal", "notEqual", "any", "all", "not", "textureSize", "texture", "textureProj", "textureLod", "textureOffset", "texelFetch",
    "texelFetchOffset", "textureProjOffset", "textureLodOffset", "textureProjLod", "textureProjLodOffset", "textureGrad", "textureGradOffset",
    "textureProjGrad", "textureProjGradOffset", "textureGather", "textureGatherOffset", "textureQueryLod", "dFdx", "dFdy", "fwidth", "noise1",
    "noise2", "noise3", "noise4", "EmitVertex", "EndPrimitive", "texture1D", "texture1DProj", "texture1DLod", "texture2D", "texture2DProj",
    "texture2DLod", "texture3D", "texture3DProj", "texture3DLod", "textureCube", "textureCubeLod", "shadow1D", "shadow2D", "shadow1DProj",
    "shadow2DProj", "shadow1DLod", "shadow2DLod", "bitfieldExtract", "bitfieldInsert", "bitfieldReverse", "bitCount", "findLSB", "findMSB",
    "uaddCarry", "usubBorrow", "umulExtended", "imulExtended", "barrier", "memoryBarrier", "average", "main",
];

/// Whether GLSL 330 or GLSL ES 3.00 cannot take `name` as an identifier.
pub fn is_reserved(name: &str) -> bool {
    // Asked for every name of every GL module: a set, not a scan of the list.
    static SET: std::sync::OnceLock<rustc_hash::FxHashSet<&'static str>> = std::sync::OnceLock::new();
    name.starts_with("gl_") || SET.get_or_init(|| RESERVED.iter().copied().collect()).contains(name)
}

/// The GLSL name of a source name: itself, or itself followed by `_`,
/// `_1`, `_2` ..., the first that is neither reserved nor `taken` (see the
/// module docs).
pub fn glsl_name(source: &str, taken: impl Fn(&str) -> bool) -> String {
    // The checker keeps `gl_` names for builtins; a source name never
    // starts so, but the rule must end for any name.
    let base = if source.starts_with("gl_") { ["u", source].concat() } else { source.to_string() };
    let free = |n: &str| !is_reserved(n) && !taken(n);
    if free(&base) {
        return base;
    }
    let under = [base.as_str(), "_"].concat();
    if free(&under) {
        return under;
    }
    (1u32..).map(|k| format!("{base}_{k}")).find(|n| free(n)).expect("a free name")
}

/// The GLSL spelling of a type of a module (`mat3x2`, `bvec2`, `float[9]`,
/// `Light[4]`), as a host reads it to choose a `glUniform*` call.
pub fn glsl_type(module: &naga::Module, ty: naga::Handle<naga::Type>) -> String {
    use naga::{ScalarKind as K, TypeInner as T};
    let t = &module.types[ty];
    let prefix = |k: K| match k {
        K::Sint => "i",
        K::Uint => "u",
        K::Bool => "b",
        _ => "",
    };
    match t.inner {
        T::Scalar(s) => match s.kind {
            K::Sint => "int",
            K::Uint => "uint",
            K::Bool => "bool",
            _ => "float",
        }
        .to_string(),
        T::Vector { size, scalar } => [prefix(scalar.kind), "vec", digit(size)].concat(),
        T::Matrix { columns, rows, .. } if columns == rows => ["mat", digit(columns)].concat(),
        T::Matrix { columns, rows, .. } => ["mat", digit(columns), "x", digit(rows)].concat(),
        T::Array { base, size: naga::ArraySize::Constant(n), .. } => {
            // `float[2][3]` in the DSL is `float[3][2]` in GLSL's order.
            let inner = glsl_type(module, base);
            match inner.find('[') {
                Some(at) => format!("{}[{n}]{}", &inner[..at], &inner[at..]),
                None => format!("{inner}[{n}]"),
            }
        }
        _ => t.name.clone().unwrap_or_default(),
    }
}

/// `2`, `3` or `4`: type names are spelled for every uniform, attribute
/// and varying of every compile, without the formatting machinery.
pub fn digit(size: naga::VectorSize) -> &'static str {
    match size {
        naga::VectorSize::Bi => "2",
        naga::VectorSize::Tri => "3",
        naga::VectorSize::Quad => "4",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reserved_names_take_an_underscore_until_free() {
        assert_eq!(glsl_name("a_pos", |_| false), "a_pos");
        assert_eq!(glsl_name("input", |_| false), "input_");
        assert_eq!(glsl_name("texture", |n| n == "texture_"), "texture_1");
        assert_eq!(glsl_name("sample", |_| false), "sample_");
        assert_eq!(glsl_name("gl_x", |_| false), "ugl_x");
        assert!(is_reserved("gl_Thing") && !is_reserved("a_b"));
    }
}
