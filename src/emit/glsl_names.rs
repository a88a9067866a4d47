//! The identifiers a GL host binds by: the source's names, renamed by one
//! rule where GLSL cannot take them.
//!
//! GLSL 330 and GLSL ES 3.00 reserve their keywords, the words reserved for
//! future use, the names of their builtin functions (a global of that name
//! would hide the function) and every name starting with `gl_`. A source
//! name that is one of those, or that naga could give to something else
//! in a GL file of the compile ([`NamerLabels`]: what its namer makes of
//! the modules' names, and the names it makes up, such as `loop_init`),
//! becomes the name followed by `_` (naga's own rule for the names it
//! makes), then `_1`, `_2` ... until it is free. The choice depends on the
//! compile, not on one file, so both stages of a program give a varying
//! the same name. [`pick_names`] names a compile's stage I/O so, also off
//! the names the fix-ups after naga write (block names `light_ubo`) and
//! off each other. The manifest records every GLSL name (`glsl_name`), so
//! a host never guesses.

/// Keywords, reserved words and builtin function names of GLSL 330 core and
/// GLSL ES 3.00 (their specifications, sections 3.6 and 8), and the builtin
/// functions of GLSL 4.30 / ES 3.10 naga writes.
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
    // Builtin functions of GLSL 4.30 / ES 3.10 (images, atomics, barriers)
    // and of the extensions naga may use, which its text can call.
    "imageLoad", "imageStore", "imageSize", "imageSamples", "imageAtomicAdd", "imageAtomicMin", "imageAtomicMax", "imageAtomicAnd",
    "imageAtomicOr", "imageAtomicXor", "imageAtomicExchange", "imageAtomicCompSwap", "atomicAdd", "atomicMin", "atomicMax", "atomicAnd",
    "atomicOr", "atomicXor", "atomicExchange", "atomicCompSwap", "atomicCounter", "atomicCounterIncrement", "atomicCounterDecrement",
    "memoryBarrierAtomicCounter", "memoryBarrierBuffer", "memoryBarrierShared", "memoryBarrierImage", "groupMemoryBarrier",
    "textureQueryLevels", "textureSamples", "textureGatherOffsets", "dFdxFine", "dFdyFine", "dFdxCoarse", "dFdyCoarse", "fwidthFine",
    "fwidthCoarse", "interpolateAtCentroid", "interpolateAtSample", "interpolateAtOffset", "packDouble2x32", "unpackDouble2x32",
    "EmitStreamVertex", "EndStreamPrimitive", "anyInvocation", "allInvocations", "allInvocationsEqual",
];

/// Whether GLSL 330 or GLSL ES 3.00 cannot take `name` as an identifier.
pub fn is_reserved(name: &str) -> bool {
    // Asked for every name of every GL module: a set, not a scan of the list.
    static SET: std::sync::OnceLock<rustc_hash::FxHashSet<&'static str>> = std::sync::OnceLock::new();
    // GLSL ES reserves every name holding `__`, and WebGL2 (ANGLE) refuses
    // them; desktop GLSL only warns.
    name.starts_with("gl_") || name.contains("__") || SET.get_or_init(|| RESERVED.iter().copied().collect()).contains(name)
}

/// The GLSL name of a source name: itself, or itself followed by `_`,
/// `_1`, `_2` ..., the first that is neither reserved nor `taken` (see the
/// module docs).
pub fn glsl_name(source: &str, taken: impl Fn(&str) -> bool) -> String {
    let base = glsl_base(source).into_owned();
    let free = |n: &str| !is_reserved(n) && !taken(n);
    if free(&base) {
        return base;
    }
    // No name tried may hold `__`: after a base ending in `_` come the
    // digits alone (`input_1`, not `input__`).
    let sep = if base.ends_with('_') { "" } else { "_" };
    if sep == "_" {
        let under = [base.as_str(), "_"].concat();
        if free(&under) {
            return under;
        }
    }
    (1u32..).map(|k| format!("{base}{sep}{k}")).find(|n| free(n)).expect("a free name")
}

/// The first name [`glsl_name`] tries for `source`, which every other it
/// tries begins with.
fn glsl_base(source: &str) -> std::borrow::Cow<'_, str> {
    // The checker keeps `gl_` names for builtins; a source name never
    // starts so, but the rule must end for any name. Every name tried for
    // a source name starting as the writer's own (`_group_0_binding_1_fs`,
    // `const_float`) is one of those: it would never end.
    let source: std::borrow::Cow<'_, str> = if source.contains("__") {
        // Runs of `_` become one: a name holding `__` is reserved.
        let mut s = String::with_capacity(source.len());
        for c in source.chars() {
            if !(c == '_' && s.ends_with('_')) {
                s.push(c);
            }
        }
        s.into()
    } else {
        source.into()
    };
    if ["gl_", "_group_", "_immediates_binding_", "const_"].iter().any(|p| source.starts_with(p)) {
        ["u", &source].concat().into()
    } else {
        source
    }
}

/// What naga's GLSL writer can call anything in a set of GL modules: what
/// its namer makes of each name the modules hold (struct members aside:
/// they live in their own namespace), with its fallbacks for unnamed
/// items, and the names the writer makes up itself. A varying's GLSL name
/// is chosen against this, the same for every module of a compile, so
/// that the stages of a program agree on it: a name naga takes in one
/// stage only (`loop_init` where a loop needs one) is given up in all.
#[derive(Default)]
pub struct NamerLabels<'a> {
    /// Each module's names as the namer keeps them (their bases: nearly
    /// always the names themselves). The namer writes a base, the base
    /// with `_` (after a final digit, or a keyword), then `_1`, `_2` ...
    /// for the repeats in one module.
    modules: Vec<Vec<std::borrow::Cow<'a, str>>>,
    /// The most loops one module has: the writer names each loop's
    /// first-iteration flag `loop_init`, numbered as any name.
    loops: u32,
    /// Where set ([`NamerLabels::for_initials`]), the first bytes of the
    /// names that will be asked about: a base starting otherwise can never
    /// be one of them, so it is not kept (a module holds hundreds of
    /// names, a compile asks about a few).
    initials: Option<Box<[bool; 256]>>,
}

impl<'a> NamerLabels<'a> {
    /// Labels that answer [`NamerLabels::taken`] only for names whose
    /// first byte is the first byte of one of `names`. Every name
    /// [`glsl_name`] asks about for a source name starts as its base does.
    pub fn for_initials<'n>(names: impl IntoIterator<Item = &'n str>) -> NamerLabels<'a> {
        let mut initials = Box::new([false; 256]);
        for n in names {
            // An empty base is tried as `_`, `_1` ...
            let b = glsl_base(n).as_bytes().first().copied().unwrap_or(b'_');
            initials[b as usize] = true;
        }
        NamerLabels { initials: Some(initials), ..Default::default() }
    }

    /// Adds the names of `module`.
    pub fn add_module(&mut self, module: &'a naga::Module) {
        self.add_module_without(module, |_| false);
    }

    /// Adds the names of `module` but those of its globals `skip` says
    /// (uniforms written under placeholders, named afterwards).
    pub fn add_module_without(&mut self, module: &'a naga::Module, skip: impl Fn(&str) -> bool) {
        let functions = || module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
        let initials = self.initials.as_deref();
        // Filtered, a module keeps a few; otherwise one per name.
        let capacity = match initials {
            Some(_) => 16,
            None => {
                NAMER_FALLBACKS.len()
                    + module.types.len()
                    + module.constants.len()
                    + module.overrides.len()
                    + module.global_variables.len()
                    + module.entry_points.len()
                    + functions().map(|f| 1 + f.arguments.len() + f.local_variables.len() + f.named_expressions.len()).sum::<usize>()
            }
        };
        let mut bases = Vec::with_capacity(capacity);
        let mut add = |n: &'a str| {
            // A name starting with a letter keeps it as the first byte of
            // its base (`gl_` gains `gen_`, also a `g`): such a name is
            // passed over without working its base out.
            let first = n.as_bytes().first().copied().unwrap_or(0);
            if first.is_ascii_alphabetic() && initials.is_some_and(|i| !i[first as usize]) {
                return;
            }
            let base = namer_base(n);
            if initials.is_none_or(|i| base.as_bytes().first().is_some_and(|&b| i[b as usize])) {
                bases.push(base);
            }
        };
        NAMER_FALLBACKS.iter().for_each(|n| add(n));
        module.types.iter().filter_map(|(_, t)| t.name.as_deref()).for_each(&mut add);
        module.constants.iter().filter_map(|(_, c)| c.name.as_deref()).for_each(&mut add);
        module.overrides.iter().filter_map(|(_, o)| o.name.as_deref()).for_each(&mut add);
        module.global_variables.iter().filter_map(|(_, g)| g.name.as_deref()).filter(|n| !skip(n)).for_each(&mut add);
        module.entry_points.iter().for_each(|e| add(&e.name));
        let mut loops = 0;
        for f in functions() {
            f.name.as_deref().into_iter().for_each(&mut add);
            f.arguments.iter().filter_map(|a| a.name.as_deref()).for_each(&mut add);
            f.local_variables.iter().filter_map(|(_, l)| l.name.as_deref()).for_each(&mut add);
            f.named_expressions.values().for_each(|n| add(n));
            loops += count_loops(&f.body);
        }
        self.modules.push(bases);
        self.loops = self.loops.max(loops);
    }

    /// How many names of one module at most have namer base `base`.
    fn count(&self, base: &str) -> u32 {
        let loops = if base == "loop_init" { self.loops } else { 0 };
        let named = self.modules.iter().map(|m| m.iter().filter(|b| *b == base).count() as u32).max().unwrap_or(0);
        loops + named
    }

    /// Whether naga's GLSL text for some module added could hold the
    /// identifier `name` outside struct members (keywords and builtins are
    /// [`is_reserved`]'s). The set is finite, so [`glsl_name`] ends.
    pub fn taken(&self, name: &str) -> bool {
        debug_assert!(
            self.initials.as_ref().is_none_or(|i| name.as_bytes().first().is_none_or(|&b| i[b as usize])),
            "`{name}` was not among the initials asked for"
        );
        if made_up(name) || self.count(name) > 0 || name.strip_suffix('_').is_some_and(|b| self.count(b) > 0) {
            return true;
        }
        // `BASE_N`, N from 1 to the repeats (the namer's numbering).
        let Some(at) = name.rfind('_') else { return false };
        let digits = &name[at + 1..];
        let repeat = (!digits.is_empty() && !digits.starts_with('0') && digits.bytes().all(|b| b.is_ascii_digit())).then(|| digits.parse::<u32>().ok()).flatten();
        repeat.is_some_and(|n| n < self.count(&name[..at]))
    }
}

/// The GLSL names of a compile's attributes, varyings and colour outputs:
/// for each of `wanted` (one source name per thing named, in order), the
/// [`glsl_name`] free of everything the GL text of `modules` can hold
/// outside struct members: what naga can write ([`NamerLabels`]), the
/// names the fix-ups after it write ([`fixup_names`]), `also_taken` (names
/// chosen elsewhere for the compile) and the names given to the wanted
/// before it. The names the labels are asked about are derived from
/// `wanted` here, so no caller can leave a family of them out.
pub fn pick_names(modules: &[&naga::Module], also_taken: &[&str], wanted: &[&str]) -> Vec<String> {
    let mut labels = NamerLabels::for_initials(wanted.iter().copied());
    for m in modules {
        labels.add_module(m);
    }
    // Every name asked about starts with one of the initials: the fixed
    // names that cannot are not kept (a module holds many, a compile asks
    // about a few).
    let asked = |n: &str| labels.initials.as_deref().is_none_or(|i| n.as_bytes().first().is_none_or(|&b| i[b as usize]));
    // (name, suffix) pairs: nothing is formatted for a name never asked about.
    let mut fixed: Vec<(&str, &str)> = also_taken.iter().filter(|n| asked(n)).map(|&n| (n, "")).collect();
    for m in modules {
        fixup_names(m, |n, suffix| {
            if asked(n) {
                fixed.push((n, suffix));
            }
        });
    }
    let is_fixed = |n: &str| fixed.iter().any(|&(f, suffix)| n.len() == f.len() + suffix.len() && n.starts_with(f) && n.ends_with(suffix));
    let mut chosen: Vec<String> = Vec::with_capacity(wanted.len());
    for source in wanted {
        let name = glsl_name(source, |n| labels.taken(n) || is_fixed(n) || chosen.iter().any(|c| c == n));
        chosen.push(name);
    }
    chosen
}

/// The names the GL fix-ups give the globals of `module` besides naga's,
/// each as a global's name and a suffix: the name itself (a uniform,
/// sampler or image given its source name back), and the block name of a
/// uniform or storage buffer ([`block_name`], [`storage_block_name`]).
pub fn fixup_names<'m>(module: &'m naga::Module, mut each: impl FnMut(&'m str, &'static str)) {
    for (_, g) in module.global_variables.iter() {
        let Some(name) = g.name.as_deref() else { continue };
        match g.space {
            naga::AddressSpace::Uniform => each(name, UBO),
            naga::AddressSpace::Storage { .. } => each(name, SSBO),
            _ => {}
        }
        each(name, "");
    }
}

const UBO: &str = "_ubo";
const SSBO: &str = "_ssbo";

/// The GLSL block name of uniform buffer `name` (the struct uniform's, or
/// the loose buffer's): `<name>_ubo`.
pub fn block_name(name: &str) -> String {
    [name, UBO].concat()
}

/// The GLSL block name of storage buffer `name`: `<name>_ssbo`.
pub fn storage_block_name(name: &str) -> String {
    [name, SSBO].concat()
}

/// Every name of `module` naga's namer names something by (struct
/// members aside), repeats included.
pub fn module_names<'m>(module: &'m naga::Module, mut each: impl FnMut(&'m str)) {
    module.types.iter().filter_map(|(_, t)| t.name.as_deref()).for_each(&mut each);
    module.constants.iter().filter_map(|(_, c)| c.name.as_deref()).for_each(&mut each);
    module.overrides.iter().filter_map(|(_, o)| o.name.as_deref()).for_each(&mut each);
    module.global_variables.iter().filter_map(|(_, g)| g.name.as_deref()).for_each(&mut each);
    module.entry_points.iter().for_each(|e| each(&e.name));
    for f in module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function)) {
        f.name.as_deref().into_iter().for_each(&mut each);
        f.arguments.iter().filter_map(|a| a.name.as_deref()).for_each(&mut each);
        f.local_variables.iter().filter_map(|(_, l)| l.name.as_deref()).for_each(&mut each);
        f.named_expressions.values().for_each(|n| each(n));
    }
}

/// For each of `globals` (names of globals of `module`), whether naga's
/// GLSL writer writes it under that very name: the namer keeps it
/// (nothing to drop or escape, a letter last so no `_` is added, not
/// reserved) and no other name of the module has the same base. Only
/// names whose base is one of those globals' are counted (the globals
/// are a few, the module's names many: no map of every base).
pub fn namer_keeps(module: &naga::Module, globals: &[&str]) -> Vec<bool> {
    let mut keeps: Vec<bool> = globals.iter().map(|&n| namer_base(n) == n && n.as_bytes().last().is_some_and(|c| c.is_ascii_alphabetic()) && !is_reserved(n)).collect();
    if keeps.iter().any(|&k| k) {
        let mut counts = vec![0u32; globals.len()];
        module_names(module, |n| {
            let base = namer_base(n);
            for (i, g) in globals.iter().enumerate() {
                if keeps[i] && base == *g {
                    counts[i] += 1;
                }
            }
        });
        for (k, c) in keeps.iter_mut().zip(counts) {
            *k &= c == 1;
        }
    }
    keeps
}

/// The loops in `block`, however nested.
fn count_loops(block: &naga::Block) -> u32 {
    use naga::Statement as S;
    block
        .iter()
        .map(|s| match s {
            S::Block(b) => count_loops(b),
            S::If { accept, reject, .. } => count_loops(accept) + count_loops(reject),
            S::Switch { cases, .. } => cases.iter().map(|c| count_loops(&c.body)).sum(),
            S::Loop { body, continuing, .. } => 1 + count_loops(body) + count_loops(continuing),
            _ => 0,
        })
        .sum()
}

/// What naga's namer keeps of a name: leading digits and trailing `_`
/// dropped, `:<>,` made `_`, any other character not a letter, digit or
/// `_` written `uXXXX_`, runs of `_` made one, `unnamed` for nothing left,
/// and `gen_` before a prefix GLSL reserves (`gl_`, `_group`,
/// `_immediates_binding_`).
pub fn namer_base(name: &str) -> std::borrow::Cow<'_, str> {
    use std::borrow::Cow;
    // Nearly every name is kept as it is: one pass over its bytes says so.
    let b = name.as_bytes();
    let mut kept = !b.is_empty() && !b[0].is_ascii_digit() && b[b.len() - 1] != b'_' && !name.starts_with("gl_") && !name.starts_with("_group") && !name.starts_with("_immediates_binding_");
    let mut after_underscore = false;
    for &c in b {
        if !kept {
            break;
        }
        kept = c.is_ascii_alphanumeric() || (c == b'_' && !after_underscore);
        after_underscore = c == b'_';
    }
    if kept {
        return Cow::Borrowed(name);
    }
    let trimmed = name.trim_start_matches(|c: char| c.is_numeric()).trim_end_matches('_');
    let plain = !trimmed.is_empty() && !trimmed.contains("__") && trimmed.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
    let base: Cow<'_, str> = if plain {
        Cow::Borrowed(trimmed)
    } else {
        let mut out = String::new();
        for c in trimmed.chars() {
            let c = if matches!(c, ':' | '<' | '>' | ',') { '_' } else { c };
            let after_underscore = out.ends_with('_');
            if c == '_' && after_underscore {
                continue;
            }
            if c.is_ascii_alphanumeric() || c == '_' {
                out.push(c);
            } else {
                if !out.is_empty() && !after_underscore {
                    out.push('_');
                }
                out.push_str(&format!("u{:04x}_", c as u32));
            }
        }
        let len = out.trim_end_matches('_').len();
        out.truncate(len);
        if out.is_empty() {
            out.push_str("unnamed");
        }
        Cow::Owned(out)
    };
    if ["gl_", "_group", "_immediates_binding_"].iter().any(|p| base.starts_with(p)) {
        return Cow::Owned(["gen_", &base].concat());
    }
    base
}

/// What naga's namer calls an unnamed type, function, argument, local,
/// global or entry point result.
const NAMER_FALLBACKS: &[&str] = &["type", "VertexOutput", "FragmentOutput", "ComputeOutput", "function", "param", "local", "global", "member"];

/// The identifiers naga's GLSL writer makes up outside its namer: `_e12`
/// (an expression's value, `_e12_clamped_lod` its clamped level),
/// `_tmp_return`, `_group_0_binding_1_fs`, `_vs2fs_location0` and the other
/// interface names, `naga_modf` / `naga_frexp`, `const_...` (an unnamed
/// constant) and uniform blocks `<type>_block_<N><stage>`.
fn made_up(name: &str) -> bool {
    // (No identifier is empty.)
    if name.is_empty() {
        return true;
    }
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if let Some(rest) = name.strip_prefix("_e") {
        return digits(rest.strip_suffix("_clamped_lod").unwrap_or(rest));
    }
    if ["_p2vs_location", "_vs2fs_location", "_fs2p_location"].iter().any(|p| name.strip_prefix(p).is_some_and(digits)) {
        return true;
    }
    if name == "_tmp_return" || name.starts_with("_group_") || name.starts_with("_immediates_binding_") || name.starts_with("const_") || name == "naga_modf" || name == "naga_frexp" {
        return true;
    }
    // `<type>_block_<N><stage>`.
    name.rfind("_block_").is_some_and(|at| {
        let rest = &name[at + "_block_".len()..];
        let stage = ["Vertex", "Fragment", "Compute"].iter().find_map(|s| rest.strip_suffix(s));
        stage.is_some_and(digits)
    })
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
        // `__` is reserved in GLSL ES (WebGL2 refuses it): never made, and
        // a source name holding it is given one without.
        assert!(is_reserved("a__b"));
        assert_eq!(glsl_name("input_", |n| n == "input_"), "input_1");
        assert_eq!(glsl_name("my__u", |_| false), "my_u");
        assert_eq!(glsl_name("a___b_", |n| n == "a_b_"), "a_b_1");
    }

    #[test]
    fn names_naga_could_write_are_taken() {
        let mut module = naga::Module::default();
        let f32 = module.types.insert(naga::Type { name: None, inner: naga::TypeInner::Scalar(naga::Scalar::F32) }, naga::Span::UNDEFINED);
        for n in ["v", "in_a_pos", "lit1", "world", "world", "step_", "gl_Position", "a::b"] {
            let init = module.global_expressions.append(naga::Expression::Literal(naga::Literal::F32(0.0)), naga::Span::UNDEFINED);
            module.constants.append(naga::Constant { name: Some(n.to_string()), ty: f32, init }, naga::Span::UNDEFINED);
        }
        let mut l = NamerLabels::default();
        l.add_module(&module);
        // What the namer makes of a name: its base, with `_`, with `_N` for a repeat.
        for taken in ["world", "world_", "world_1", "lit1", "lit1_", "step", "step_", "gen_gl_Position", "a_b", "function", "local_"] {
            assert!(l.taken(taken), "{taken}");
        }
        // Other names, and numbers beyond the repeats: what `glsl_name` falls back to.
        for free in ["v_world_pos", "worlds", "world_x", "world_2", "world_01", "a_pos", "Position", "gl_Position_", "loop_init", "step_1"] {
            assert!(!l.taken(free), "{free}");
        }
        // naga's own names, exactly.
        for made in ["_e12", "_e3_clamped_lod", "_tmp_return", "_vs2fs_location1", "_group_0_binding_1_fs", "naga_modf", "Uniforms_block_0Vertex", "const_float"] {
            assert!(l.taken(made), "{made}");
        }
        for not_made in ["_e", "_ex", "_e1_", "_tmp_return_", "_vs2fs_location", "u_block_ubo", "Uniforms_block_0Vertex_"] {
            assert!(!l.taken(not_made), "{not_made}");
        }
        // Labels kept only for some initials answer as the full ones for
        // every name starting so.
        let mut some = NamerLabels::for_initials(["world", "step", "a_pos", "gl_x", "loop"]);
        some.add_module(&module);
        for name in ["world", "world_", "world_1", "world_2", "worlds", "step", "step_", "step_1", "a_b", "a_pos", "ul", "uv", "local_", "lit1"] {
            if ["w", "s", "a", "u", "l"].iter().any(|i| name.starts_with(i)) {
                assert_eq!(some.taken(name), l.taken(name), "{name}");
            }
        }
        // So do the names tried for an empty source name.
        let mut empty = NamerLabels::for_initials([""]);
        empty.add_module(&module);
        assert_eq!(glsl_name("", |n| empty.taken(n)), glsl_name("", |n| l.taken(n)));
        // A loop's flag, once there is a loop.
        let body = naga::Block::from_vec(vec![naga::Statement::Loop { body: naga::Block::new(), continuing: naga::Block::new(), break_if: None }]);
        module.functions.append(naga::Function { body, ..Default::default() }, naga::Span::UNDEFINED);
        let mut l = NamerLabels::default();
        l.add_module(&module);
        assert!(l.taken("loop_init") && l.taken("loop_init_") && !l.taken("loop_init_1"));
        // `glsl_name` ends: every taken set is finite.
        assert_eq!(glsl_name("loop_init", |n| l.taken(n)), "loop_init_1");
        assert_eq!(glsl_name("world", |n| l.taken(n)), "world_2");
        // Names starting as the writer's own, every numbering of which it
        // makes up too, end as well.
        for (source, got) in [("_group_x", "u_group_x"), ("_group_0_binding_1_fs", "u_group_0_binding_1_fs"), ("const_a", "uconst_a"), ("_immediates_binding_a", "u_immediates_binding_a")] {
            assert_eq!(glsl_name(source, |n| l.taken(n)), got);
        }
        assert_eq!(namer_base("3x__y:z"), "x_y_z");
    }

    #[test]
    fn picked_names_keep_off_fixups_and_each_other() {
        let mut module = naga::Module::default();
        let f32 = module.types.insert(naga::Type { name: None, inner: naga::TypeInner::Scalar(naga::Scalar::F32) }, naga::Span::UNDEFINED);
        for (name, space) in [("light", naga::AddressSpace::Uniform), ("data", naga::AddressSpace::Storage { access: naga::StorageAccess::LOAD }), ("tint", naga::AddressSpace::Private)] {
            module.global_variables.append(naga::GlobalVariable { name: Some(name.into()), space, binding: None, ty: f32, init: None, memory_decorations: Default::default() }, naga::Span::UNDEFINED);
        }
        // The block names the fix-ups give, names chosen elsewhere, and
        // the names picked before; the rest as `glsl_name` has them.
        let wanted = ["light_ubo", "data_ssbo", "taken", "input", "input_", "vk_location1", "vk_location1", "a_pos", "tint"];
        let picked = pick_names(&[&module], &["taken"], &wanted);
        assert_eq!(picked, ["light_ubo_", "data_ssbo_", "taken_", "input_", "input_1", "vk_location1", "vk_location1_", "a_pos", "tint_1"]);
    }
}
