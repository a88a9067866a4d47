//! Specialization constants in the SPIR-V words naga wrote.
//!
//! naga 30's SPIR-V writer has no overrides. The SPIR-V module
//! (`Lowered::spirv`) holds each `@constant_id` constant in a module-scope
//! `Private` variable of its name, initialised with its default and never
//! written; every use is a load, which naga cannot fold. Here that
//! variable's initializer becomes a fresh `OpSpecConstant` (`True`/`False`
//! for a bool) of the same type and default, decorated `SpecId N`, so a
//! Vulkan host's `VkSpecializationInfo` sets it. The default's own
//! `OpConstant` may be shared with other values and is left alone.

const OP_NAME: u32 = 5;
const OP_TYPE_BOOL: u32 = 20;
const OP_TYPE_INT: u32 = 21;
const OP_TYPE_FLOAT: u32 = 22;
const OP_CONSTANT_TRUE: u32 = 41;
const OP_CONSTANT_FALSE: u32 = 42;
const OP_CONSTANT: u32 = 43;
const OP_CONSTANT_NULL: u32 = 46;
const OP_SPEC_CONSTANT_TRUE: u32 = 48;
const OP_SPEC_CONSTANT_FALSE: u32 = 49;
const OP_SPEC_CONSTANT: u32 = 50;
const OP_VARIABLE: u32 = 59;
const OP_DECORATE: u32 = 71;
const STORAGE_PRIVATE: u32 = 6;
const DECORATION_SPEC_ID: u32 = 1;

/// The instructions that come before the annotations (logical layout
/// sections 1-7): capabilities, extensions, imports, the memory model,
/// entry points, execution modes and debug names.
const PREAMBLE: &[u32] = &[17, 10, 11, 14, 15, 16, 331, 7, 2, 3, 4, OP_NAME, 6, 330];

/// One instruction: its first word's index and its words.
fn instructions(words: &[u32]) -> Result<Vec<(usize, &[u32])>, String> {
    if words.len() < 5 || words[0] != 0x0723_0203 {
        return Err("not a SPIR-V module".into());
    }
    let mut out = Vec::new();
    let mut at = 5;
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if count == 0 || at + count > words.len() {
            return Err(format!("a malformed instruction at word {at}"));
        }
        out.push((at, &words[at..at + count]));
        at += count;
    }
    Ok(out)
}

/// A literal string's text (NUL-terminated, little-endian bytes).
fn string(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).take_while(|&b| b != 0).collect()
}

fn string_words(text: &str) -> Vec<u32> {
    let mut bytes = text.as_bytes().to_vec();
    bytes.resize(text.len() / 4 * 4 + 4, 0);
    bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
}

fn op(opcode: u32, operands: &[u32]) -> Vec<u32> {
    let mut v = Vec::with_capacity(operands.len() + 1);
    v.push(((operands.len() as u32 + 1) << 16) | opcode);
    v.extend_from_slice(operands);
    v
}

fn name_op(id: u32, text: &str) -> Vec<u32> {
    op(OP_NAME, &[&[id][..], &string_words(text)].concat())
}

/// Makes each `(name, id)` a specialization constant (see the module
/// comment). An error is a bug: the module is not what the lowering made.
pub fn specialize(words: &[u32], constants: &[(&str, u32)]) -> Result<Vec<u32>, String> {
    let insts = instructions(words)?;
    let opcode = |i: &[u32]| i[0] & 0xffff;
    let mut bound = words[3];
    // Per instruction index: the words to put after it, and a new
    // initializer for a variable.
    let mut after: Vec<(usize, Vec<u32>)> = Vec::new();
    let mut new_init: Vec<(usize, u32)> = Vec::new();
    let mut decorations = Vec::new();
    for &(name, spec_id) in constants {
        let named: Vec<u32> = insts.iter().filter(|(_, i)| opcode(i) == OP_NAME && i.len() > 2 && string(&i[2..]) == name.as_bytes()).map(|(_, i)| i[1]).collect();
        let vars: Vec<usize> = (0..insts.len())
            .filter(|&k| {
                let i = insts[k].1;
                opcode(i) == OP_VARIABLE && i.len() == 5 && i[3] == STORAGE_PRIVATE && named.contains(&i[2])
            })
            .collect();
        let [var] = vars[..] else {
            return Err(format!("{} module-scope private variables named `{name}` with an initializer, not one", vars.len()));
        };
        let init = insts[var].1[4];
        let Some(c) = insts.iter().position(|(_, i)| matches!(opcode(i), OP_CONSTANT | OP_CONSTANT_TRUE | OP_CONSTANT_FALSE | OP_CONSTANT_NULL) && i[2] == init) else {
            return Err(format!("the initializer of `{name}` is not a constant"));
        };
        let ci = insts[c].1;
        let ty = ci[1];
        let Some(type_inst) = insts.iter().map(|(_, i)| *i).find(|i| matches!(opcode(i), OP_TYPE_BOOL | OP_TYPE_INT | OP_TYPE_FLOAT) && i[1] == ty) else {
            return Err(format!("`{name}` is not a scalar"));
        };
        let id = bound;
        bound += 1;
        let spec = match (opcode(type_inst), opcode(ci)) {
            (OP_TYPE_BOOL, OP_CONSTANT_TRUE) => op(OP_SPEC_CONSTANT_TRUE, &[ty, id]),
            (OP_TYPE_BOOL, _) => op(OP_SPEC_CONSTANT_FALSE, &[ty, id]),
            (_, _) if type_inst.get(2) != Some(&32) => return Err(format!("`{name}` is not a 32-bit scalar")),
            (_, OP_CONSTANT) if ci.len() == 4 => op(OP_SPEC_CONSTANT, &[ty, id, ci[3]]),
            (_, OP_CONSTANT_NULL) => op(OP_SPEC_CONSTANT, &[ty, id, 0]),
            _ => return Err(format!("the default of `{name}` is not one 32-bit word")),
        };
        after.push((c, spec));
        // Named too, for reflection tools (`spirv-cross --reflect`).
        let name_at = insts.iter().position(|(_, i)| opcode(i) == OP_NAME && i[1] == insts[var].1[2]).expect("the variable was found by its name");
        after.push((name_at, name_op(id, name)));
        new_init.push((var, id));
        decorations.extend(op(OP_DECORATE, &[id, DECORATION_SPEC_ID, spec_id]));
    }
    let mut out = Vec::with_capacity(words.len() + after.iter().map(|(_, w)| w.len()).sum::<usize>() + decorations.len());
    out.extend_from_slice(&words[..5]);
    out[3] = bound;
    let mut decorations = Some(decorations);
    for (k, &(_, i)) in insts.iter().enumerate() {
        if !PREAMBLE.contains(&opcode(i)) {
            if let Some(d) = decorations.take() {
                out.extend(d);
            }
        }
        let start = out.len();
        out.extend_from_slice(i);
        if let Some(&(_, id)) = new_init.iter().find(|(v, _)| *v == k) {
            out[start + 4] = id;
        }
        for (_, w) in after.iter().filter(|(at, _)| *at == k) {
            out.extend_from_slice(w);
        }
    }
    if decorations.is_some_and(|d| !d.is_empty()) {
        return Err("no types or variables after the debug names".into());
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A module with `%var = OpVariable Private %c` of the given type and
    /// constant, named `name`.
    fn module(ty: Vec<u32>, constant: Vec<u32>) -> Vec<u32> {
        let mut w = vec![0x0723_0203, 0x0001_0000, 0, 10, 0];
        w.extend(op(17, &[1])); // OpCapability Shader
        w.extend(op(14, &[0, 1])); // OpMemoryModel Logical GLSL450
        w.extend(name_op(5, "SCALE"));
        w.extend(op(OP_DECORATE, &[9, 30, 0])); // some other annotation
        w.extend(ty); // %1
        w.extend(op(32, &[2, STORAGE_PRIVATE, 1])); // %2 = OpTypePointer Private %1
        w.extend(constant); // %3
        w.extend(op(OP_VARIABLE, &[2, 5, STORAGE_PRIVATE, 3]));
        w
    }

    fn find(words: &[u32], opcode: u32) -> Vec<Vec<u32>> {
        instructions(words).unwrap().into_iter().filter(|(_, i)| i[0] & 0xffff == opcode).map(|(_, i)| i.to_vec()).collect()
    }

    #[test]
    fn a_uint_default_becomes_a_spec_constant_with_its_id() {
        let w = module(op(OP_TYPE_INT, &[1, 32, 0]), op(OP_CONSTANT, &[1, 3, 7]));
        let out = specialize(&w, &[("SCALE", 4)]).unwrap();
        assert_eq!(out[3], 11, "the id bound grows by one");
        assert_eq!(find(&out, OP_SPEC_CONSTANT), vec![op(OP_SPEC_CONSTANT, &[1, 10, 7])]);
        assert_eq!(find(&out, OP_VARIABLE), vec![op(OP_VARIABLE, &[2, 5, STORAGE_PRIVATE, 10])]);
        assert!(find(&out, OP_DECORATE).contains(&op(OP_DECORATE, &[10, DECORATION_SPEC_ID, 4])));
        assert_eq!(find(&out, OP_CONSTANT), vec![op(OP_CONSTANT, &[1, 3, 7])], "the shared constant stays");
        // The decoration goes after the names, before the other annotations
        // and types; the spec constant after its type and before the variable.
        let order: Vec<u32> = instructions(&out).unwrap().iter().map(|(_, i)| i[0] & 0xffff).collect();
        assert_eq!(order, [17, 14, OP_NAME, OP_NAME, OP_DECORATE, OP_DECORATE, OP_TYPE_INT, 32, OP_CONSTANT, OP_SPEC_CONSTANT, OP_VARIABLE]);
        assert_eq!(string(&find(&out, OP_NAME)[1][2..]), b"SCALE");
    }

    #[test]
    fn bools_take_the_true_and_false_forms() {
        let w = module(op(OP_TYPE_BOOL, &[1]), op(OP_CONSTANT_FALSE, &[1, 3]));
        assert_eq!(find(&specialize(&w, &[("SCALE", 0)]).unwrap(), OP_SPEC_CONSTANT_FALSE), vec![op(OP_SPEC_CONSTANT_FALSE, &[1, 10])]);
        let w = module(op(OP_TYPE_BOOL, &[1]), op(OP_CONSTANT_TRUE, &[1, 3]));
        assert_eq!(find(&specialize(&w, &[("SCALE", 0)]).unwrap(), OP_SPEC_CONSTANT_TRUE), vec![op(OP_SPEC_CONSTANT_TRUE, &[1, 10])]);
    }

    #[test]
    fn what_the_lowering_did_not_make_is_an_error() {
        let w = module(op(OP_TYPE_INT, &[1, 32, 0]), op(OP_CONSTANT, &[1, 3, 7]));
        assert!(specialize(&w, &[("OTHER", 0)]).unwrap_err().contains("0 module-scope private variables named `OTHER`"));
        let w = module(op(OP_TYPE_INT, &[1, 64, 0]), op(OP_CONSTANT, &[1, 3, 7, 0]));
        assert!(specialize(&w, &[("SCALE", 0)]).unwrap_err().contains("32-bit"));
        assert!(specialize(&[1, 2, 3], &[]).is_err());
    }
}
