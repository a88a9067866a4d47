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

/// The names naga's namer is given when it writes a module (struct
/// members aside: they live in their own namespace), as the namer keeps
/// them: every identifier of naga's text that is no keyword, builtin or
/// name of naga's own comes from one of these.
pub struct NamerLabels<'a> {
    /// Each label without leading digits and trailing `_` (the namer drops
    /// them), the namer's fallbacks for unnamed items among them.
    bases: Vec<&'a str>,
    /// Some label is one the namer rewrites further (a character other than
    /// a letter, digit or `_`, or `__`): any name may be taken then.
    rewritten: bool,
}

impl<'a> NamerLabels<'a> {
    pub fn of(module: &'a naga::Module) -> NamerLabels<'a> {
        let functions = || module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
        let count = NAMER_FALLBACKS.len()
            + module.types.len()
            + module.constants.len()
            + module.overrides.len()
            + module.global_variables.len()
            + 2 * module.entry_points.len()
            + functions().map(|f| 1 + f.arguments.len() + f.local_variables.len() + f.named_expressions.len()).sum::<usize>();
        let mut labels = NamerLabels { bases: Vec::with_capacity(count), rewritten: false };
        labels.bases.extend_from_slice(NAMER_FALLBACKS);
        let mut add = |n: Option<&'a str>| {
            let Some(n) = n else { return };
            let base = n.trim_start_matches(|c: char| c.is_ascii_digit()).trim_end_matches('_');
            let b = base.as_bytes();
            if b.is_empty() || !b.iter().all(|&c| c.is_ascii_alphanumeric() || c == b'_') || b.windows(2).any(|w| w == b"__") {
                labels.rewritten = true;
            }
            labels.bases.push(base);
        };
        module.types.iter().for_each(|(_, t)| add(t.name.as_deref()));
        module.constants.iter().for_each(|(_, c)| add(c.name.as_deref()));
        module.overrides.iter().for_each(|(_, o)| add(o.name.as_deref()));
        module.global_variables.iter().for_each(|(_, g)| add(g.name.as_deref()));
        module.entry_points.iter().for_each(|e| add(Some(&e.name)));
        for f in functions() {
            add(f.name.as_deref());
            f.arguments.iter().for_each(|a| add(a.name.as_deref()));
            f.local_variables.iter().for_each(|(_, l)| add(l.name.as_deref()));
            f.named_expressions.values().for_each(|n| add(Some(n)));
        }
        labels
    }

    /// Whether naga's GLSL text could hold the identifier `name` outside
    /// struct members: a name naga makes up, a uniform block
    /// (`<type>_block_<N><stage>`), or what its namer makes of a label (its
    /// base, the base and `_` after a final digit or a keyword, or the
    /// base, `_` and a number for a repeat; a reserved prefix, `gl_` or
    /// `_group`, makes it `gen_...`). When this is false the text need not
    /// be searched for `name`; when it is true the text says.
    pub fn may_be_taken(&self, name: &str) -> bool {
        let Some(&first) = name.as_bytes().first() else { return true };
        // (`windows`, not `contains`: a substring search builds a searcher first.)
        if self.rewritten || MADE_UP_PREFIXES.iter().any(|p| p.as_bytes()[0] == first && name.starts_with(p)) || name.as_bytes().windows(7).any(|w| w == b"_block_") {
            return true;
        }
        // The bases the namer could have made `name` from.
        let bare = name.strip_suffix('_');
        let numbered = name.rfind('_').filter(|&at| at + 1 < name.len() && name[at + 1..].bytes().all(|b| b.is_ascii_digit())).map(|at| &name[..at]);
        self.bases.iter().any(|&l| l == name || Some(l) == bare || Some(l) == numbered)
    }
}

/// What naga's namer calls an unnamed type, function, argument, local,
/// global or entry point result (an unnamed constant is `const_...`).
const NAMER_FALLBACKS: &[&str] = &["type", "VertexOutput", "FragmentOutput", "ComputeOutput", "function", "param", "local", "global"];

/// Prefixes of the identifiers naga's GLSL writer makes up (`_e12`,
/// `_group_0_binding_1_fs`, `_vs2fs_location0`, `loop_init`, `naga_modf`,
/// `gen_gl_Position`, `const_float`) and of GLSL builtin function families
/// beyond 330 / ES 3.00 that `RESERVED` leaves out (extensions, GLSL 4.x).
const MADE_UP_PREFIXES: &[&str] = &[
    "_", "gl_", "gen_", "naga_", "const_", "loop_init", "image", "atomic", "memoryBarrier", "groupMemoryBarrier", "subgroup", "interpolateAt",
    "textureQuery", "textureSamples", "textureGatherOffsets", "dFd", "fwidth", "anyInvocation", "allInvocation", "packDouble", "unpackDouble",
    "EmitStream", "EndStream", "bitfield", "find", "uadd", "usub", "umul", "imul", "bitCount",
];

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

    #[test]
    fn names_the_namer_could_write_are_looked_for() {
        let labels = |names: &[&str]| {
            let mut module = naga::Module::default();
            for n in names {
                module.constants.append(naga::Constant { name: Some(n.to_string()), ty: module.types.insert(naga::Type { name: None, inner: naga::TypeInner::Scalar(naga::Scalar::F32) }, naga::Span::UNDEFINED), init: module.global_expressions.append(naga::Expression::Literal(naga::Literal::F32(0.0)), naga::Span::UNDEFINED) }, naga::Span::UNDEFINED);
            }
            module
        };
        let module = labels(&["v", "in_a_pos", "lit1", "world", "step_", "gl_Position"]);
        let l = NamerLabels::of(&module);
        // What the namer makes of a label: its base, with `_`, with `_N`.
        assert!(l.may_be_taken("world") && l.may_be_taken("world_") && l.may_be_taken("world_2") && l.may_be_taken("lit1_"));
        assert!(l.may_be_taken("step") && l.may_be_taken("step_"), "a final `_` is dropped, then added back for a keyword");
        assert!(l.may_be_taken("function") && l.may_be_taken("local_1"), "the namer's fallbacks for unnamed items");
        // Not from `v`, `world` or `gl_Position` (which becomes `gen_gl_Position`): other names.
        for free in ["v_world_pos", "worlds", "world_x", "world_2x", "a_pos", "Position"] {
            assert!(!l.may_be_taken(free), "{free}");
        }
        // naga's own names and builtins beyond GLSL 330 / ES 3.00.
        for made_up in ["_e12", "loop_init_1", "gen_gl_Position", "naga_modf", "Uniforms_block_0Vertex", "imageLoad", "atomicAdd", "dFdxFine", "const_float", ""] {
            assert!(l.may_be_taken(made_up), "{made_up}");
        }
        // A label the namer rewrites further makes every name one to look for.
        for rewritten in ["u__x", "a-b"] {
            let module = labels(&[rewritten]);
            assert!(NamerLabels::of(&module).may_be_taken("anything"), "{rewritten}");
        }
    }
}
