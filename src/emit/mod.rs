//! Emission: validated naga modules to target text, and the reflection manifest.
//!
//! - [`glsl`]: GLSL 330 core and GLSL ES 3.00, one file per entry point, from
//!   its module in `Lowered::gl`, with stable uniform block names and the ES sampler
//!   precision preamble.
//! - [`wgsl`]: one WGSL module from `Lowered::gpu`, keeping the module's
//!   diagnostic filters (naga's WGSL writer drops them).
//! - [`spirv`]: one SPIR-V module from `Lowered::gpu`, every entry point.
//! - [`reflect`]: the JSON manifest (`STEM.reflect.json`), with uniform block
//!   layouts checked against GLSL's std140 rules (a consistency check of the
//!   lowering: the checker has already refused the DSL types whose layouts
//!   differ).
//!
//! Either every requested artifact is produced or none is. Emission reports
//! only internal errors (ARCHITECTURE.md, "Errors"): any backend failure or
//! inconsistency of the lowered modules is a [`Diagnostic::bug`] naming
//! what failed.

pub mod glsl;
pub mod glsl_names;
pub mod limits;
pub mod reflect;
pub mod reflect_types;
pub mod spirv;
pub mod spirv_spec;
pub mod wgsl;

use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::diag::Diagnostic;
use crate::lower::Lowered;
use reflect_types::Reflection;
use crate::target::{Artifact, Target};

/// Emits every requested target plus the reflection manifest.
///
/// `stem` names the per-module outputs (`STEM.wgsl`, `STEM.spv`,
/// `STEM.reflect.json`); `source_name` is recorded in the manifest. An empty
/// `targets` means every target that can run the program (`Target::defaults`).
pub fn emit(lowered: &Lowered, stem: &str, source_name: &str, targets: &[Target]) -> Result<(Vec<Artifact>, Reflection), Diagnostic> {
    // A program with compute, storage buffers, images or subgroups takes
    // its GLSL names from GLSL 430, which has them.
    let needs_430 = lowered.interface.entry_points.iter().any(|e| e.stage == naga::ShaderStage::Compute)
        || lowered.interface.resources.iter().any(|r| matches!(r.kind, crate::lower::ResourceKind::Storage { .. } | crate::lower::ResourceKind::Image { .. }))
        || wgsl::uses_subgroups(&lowered.gpu);
    let mut targets: Vec<Target> = if targets.is_empty() { Target::defaults(needs_430).to_vec() } else { targets.to_vec() };
    targets.sort();
    targets.dedup();

    check_consistency(lowered)?;

    // Layouts first, checked against std140 whatever the targets: the
    // manifest promises one layout for every target, and the checker has
    // refused every type whose layouts differ, so a difference here is a
    // lowering bug.
    let layouts = reflect::uniform_layouts(lowered)?;

    // Two GLSL files per entry point, WGSL, SPIR-V and the manifest.
    let mut artifacts = Vec::with_capacity(2 * lowered.interface.entry_points.len() + 3);

    // GLSL: the names a GL host needs come from the GLSL writer itself, so
    // it runs (for GLSL 330) even when no GLSL target is requested.
    let mut glsl_names: Vec<glsl::EntryNames> = Vec::with_capacity(lowered.interface.entry_points.len());
    let varyings = glsl::VaryingNames::of(lowered);
    for ep in &lowered.interface.entry_points {
        // No GLSL stage: nothing to name (sema refuses the GLSL targets).
        if matches!(ep.stage, naga::ShaderStage::Mesh | naga::ShaderStage::Task) {
            glsl_names.push(glsl::EntryNames::default());
            continue;
        }
        let entry_module = glsl::EntryModule::new(lowered, ep, &varyings)?;
        let naming = if needs_430 { glsl::Profile::Desktop430 } else { glsl::Profile::Desktop330 };
        let (text, names) = glsl::write_entry_from(lowered, &entry_module, ep, naming)?;
        for (target, profile) in [(Target::Glsl430, glsl::Profile::Desktop430), (Target::Gles310, glsl::Profile::Es310)] {
            if !targets.contains(&target) {
                continue;
            }
            let (text, other) = if profile == naming { (text.clone(), names.clone()) } else { glsl::write_entry_from(lowered, &entry_module, ep, profile)? };
            if other.blocks != names.blocks || other.samplers != names.samplers || other.inputs != names.inputs || other.outputs != names.outputs || other.images != names.images {
                return Err(Diagnostic::bug(format!("the GLSL outputs of entry point `{}` disagree on identifier names", ep.name), None));
            }
            artifacts.push(Artifact { file_name: glsl::file_name(&ep.name, ep.stage, profile), target: Some(target), entry: Some(ep.name.clone()), contents: text.into_bytes() });
        }
        if needs_430 {
            glsl_names.push(names);
            continue;
        }
        if targets.contains(&Target::Glsl330) {
            artifacts.push(Artifact {
                file_name: glsl::file_name(&ep.name, ep.stage, glsl::Profile::Desktop330),
                target: Some(Target::Glsl330),
                entry: Some(ep.name.clone()),
                contents: text.into_bytes(),
            });
        }
        if targets.contains(&Target::Gles300) {
            let (text, es_names) = glsl::write_entry_from(lowered, &entry_module, ep, glsl::Profile::Es300)?;
            if es_names != names {
                return Err(Diagnostic::bug(
                    format!("GLSL 330 and GLSL ES 3.00 outputs of entry point `{}` disagree on identifier names", ep.name),
                    None,
                ));
            }
            artifacts.push(Artifact {
                file_name: glsl::file_name(&ep.name, ep.stage, glsl::Profile::Es300),
                target: Some(Target::Gles300),
                entry: Some(ep.name.clone()),
                contents: text.into_bytes(),
            });
        }
        glsl_names.push(names);
    }
    // GL links a program's varyings by name: both ends of each must use
    // one (compared per varying: two programs that share none may hold
    // different ones at a location).
    let eps = &lowered.interface.entry_points;
    for &(v, f) in &lowered.interface.links {
        let (Some(vs), Some(fs), Some(ve), Some(fe)) = (glsl_names.get(v), glsl_names.get(f), eps.get(v), eps.get(f)) else { continue };
        for out in &ve.outputs {
            let Some(input) = fe.inputs.iter().find(|i| i.name == out.name) else { continue };
            let (a, b) = (vs.outputs.get(&out.location), fs.inputs.get(&input.location));
            if a != b {
                return Err(Diagnostic::bug(format!("varying `{}` is {a:?} in the vertex GLSL and {b:?} in the fragment GLSL", out.name), None));
            }
        }
    }

    if targets.contains(&Target::Wgsl) {
        let text = wgsl::write(lowered)?;
        artifacts.push(Artifact { file_name: [stem, ".wgsl"].concat(), target: Some(Target::Wgsl), entry: None, contents: text.into_bytes() });
    }
    if targets.contains(&Target::Spirv) {
        let words = spirv::write(lowered)?;
        // One copy of the words' bytes, into a buffer of the final size
        // (pushing them a word at a time checks the capacity every time).
        let mut contents = vec![0u8; 4 * words.len()];
        for (bytes, w) in contents.chunks_exact_mut(4).zip(&words) {
            bytes.copy_from_slice(&w.to_le_bytes());
        }
        artifacts.push(Artifact { file_name: [stem, ".spv"].concat(), target: Some(Target::Spirv), entry: None, contents });
    }

    let reflection = reflect::build(lowered, stem, source_name, &targets, &glsl_names, &layouts)?;
    // The manifest grows with the interface: about 1 KB per entry point
    // and per resource (7 KB for the tutorial's 4 and 3).
    let interface = &lowered.interface;
    let mut json = Vec::with_capacity(1024 * (2 + interface.entry_points.len() + interface.resources.len()));
    serde_json::to_writer_pretty(&mut json, &reflection)
        .map_err(|e| Diagnostic::bug(format!("cannot serialise the reflection manifest: {e}"), None))?;
    json.push(b'\n');
    artifacts.push(Artifact { file_name: reflect::file_name(stem), target: None, entry: None, contents: json });

    Ok((artifacts, reflection))
}

/// The modules and the interface must describe the same entry points;
/// anything else is a lowering bug that would make the outputs disagree.
fn check_consistency(lowered: &Lowered) -> Result<(), Diagnostic> {
    let gpu = &lowered.gpu;
    let eps = &lowered.interface.entry_points;
    if lowered.gl.len() != gpu.entry_points.len() || eps.len() != gpu.entry_points.len() {
        return Err(Diagnostic::bug("the GL modules, the GPU module and the interface have different entry points", None));
    }
    for (i, ep) in eps.iter().enumerate() {
        let same = |m: &naga::EntryPoint| m.name == ep.name && m.stage == ep.stage;
        let gl = &lowered.gl[i].module.entry_points;
        // A mesh or task entry point has an empty GL module (no GLSL stage).
        let gl_ok = match ep.stage {
            naga::ShaderStage::Mesh | naga::ShaderStage::Task => gl.is_empty(),
            _ => gl.len() == 1 && same(&gl[0]),
        };
        if ep.index != i || !gpu.entry_points.get(i).is_some_and(same) || !gl_ok {
            return Err(Diagnostic::bug(format!("entry point `{}` (index {}) does not match the lowered modules", ep.name, ep.index), None));
        }
        if !matches!(ep.stage, naga::ShaderStage::Vertex | naga::ShaderStage::Fragment | naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task) {
            return Err(Diagnostic::bug(format!("entry point `{}` has unsupported stage {:?}", ep.name, ep.stage), None));
        }
    }
    for &(v, f) in &lowered.interface.links {
        let stage = |i: usize| eps.get(i).map(|e| e.stage);
        if stage(v) != Some(naga::ShaderStage::Vertex) || stage(f) != Some(naga::ShaderStage::Fragment) {
            return Err(Diagnostic::bug(format!("program ({v}, {f}) does not link a vertex and a fragment entry point"), None));
        }
    }
    for r in &lowered.interface.resources {
        let ok = |h: naga::Handle<naga::GlobalVariable>| gpu.global_variables.try_get(h).is_ok();
        if !ok(r.global) || r.sampler_global.is_some_and(|s| !ok(s)) {
            return Err(Diagnostic::bug(format!("resource `{}` refers to a global that does not exist", r.name), Some(r.span)));
        }
    }
    Ok(())
}

/// Bytes to reserve for a backend's output of `module`: naga's writers
/// append to what they are given, and from empty the text of the
/// tutorial's fragment shader regrew about ten times, each a copy. Outputs
/// of the tutorials take 15-60 bytes per expression, the short files the
/// most (their declarations are most of them).
pub(crate) fn output_capacity(module: &naga::Module) -> usize {
    let functions = module.functions.iter().map(|(_, f)| &f.expressions).chain(module.entry_points.iter().map(|e| &e.function.expressions));
    512 + 40 * functions.map(|e| e.len()).sum::<usize>()
}

/// Runs a naga backend, turning a panic inside it into a bug diagnostic.
/// naga documents that its writers may panic on IR they do not support;
/// that must never take the compiler (or a build script) down.
/// `what` is only formatted on failure (callers pass `format_args!`).
pub(crate) fn guard<T>(what: impl std::fmt::Display, f: impl FnOnce() -> Result<T, String>) -> Result<T, Diagnostic> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(Diagnostic::bug(format!("{what} failed: {e}"), None)),
        Err(payload) => Err(Diagnostic::bug(format!("{what} panicked: {}", crate::diag::panic_message(&*payload)), None)),
    }
}

/// Identifier-level text helpers for post-processing generated code.
///
/// Each looks for one name (or a part that several names share) with a
/// substring search and checks the characters around a hit, instead of
/// tokenising the whole text: the names fixed up are few, and a full
/// identifier scan (with a hash per token) of every GLSL file used to cost
/// more than naga's writer itself. Edits are made in place.
pub(crate) mod text {
    use std::ops::Range;

    use memchr::memmem::Finder;

    fn is_ident_char(c: u8) -> bool {
        c.is_ascii_alphanumeric() || c == b'_'
    }

    /// Start offsets of `name` (a non-empty identifier) where it occurs in
    /// `s` as a whole identifier.
    pub fn find_ident<'a>(s: &'a str, name: &'a str) -> impl Iterator<Item = usize> + 'a {
        let b = s.as_bytes();
        memchr::memmem::find_iter(b, name.as_bytes()).filter(move |&i| {
            let end = i + name.len();
            (i == 0 || !is_ident_char(b[i - 1])) && (end == b.len() || !is_ident_char(b[end]))
        })
    }

    pub fn contains_ident(s: &str, name: &str) -> bool {
        find_ident(s, name).next().is_some()
    }

    /// The byte range of the whole identifier around byte `at` of `s`.
    fn ident_span(s: &str, at: usize) -> std::ops::Range<usize> {
        let b = s.as_bytes();
        let mut start = at;
        while start > 0 && is_ident_char(b[start - 1]) {
            start -= 1;
        }
        let mut end = at;
        while end < b.len() && is_ident_char(b[end]) {
            end += 1;
        }
        start..end
    }

    /// Every whole identifier of `s` that contains the needle of `part`,
    /// with its start offset, in text order (each occurrence once). One
    /// search serves all the names that share a part.
    pub fn idents_containing<'a>(s: &'a str, part: &Finder) -> Vec<(usize, &'a str)> {
        let mut out: Vec<(usize, &str)> = Vec::new();
        for i in part.find_iter(s.as_bytes()) {
            let span = ident_span(s, i);
            // A part found twice in one identifier.
            if out.last().is_some_and(|&(start, _)| start == span.start) {
                continue;
            }
            out.push((span.start, &s[span]));
        }
        out
    }

    /// Replaces each range of `s` with its text. Ranges must not overlap
    /// (of two that do, the later one is skipped). A few edits are made in
    /// place, each moving the text after it, which is cheaper than a copy
    /// for the one per uniform block usual here; beyond [`IN_PLACE_EDITS`]
    /// (a sampler renamed in a long program) the text is rebuilt once, so
    /// the cost stays linear in its size.
    pub fn apply_edits<T: AsRef<str>>(s: &mut String, mut edits: Vec<(Range<usize>, T)>) {
        edits.sort_unstable_by_key(|(r, _)| r.start);
        // Whole identifiers never overlap; skip defensively, one rule for both ways.
        let mut end = 0;
        edits.retain(|(r, _)| {
            let keep = r.start >= end;
            if keep {
                end = r.end;
            }
            keep
        });
        if edits.len() <= IN_PLACE_EDITS {
            // Back to front, so that the ranges still to do keep their offsets.
            for (r, to) in edits.iter().rev() {
                s.replace_range(r.clone(), to.as_ref());
            }
            return;
        }
        let mut out = String::with_capacity(s.len() + edits.iter().map(|(_, t)| t.as_ref().len()).sum::<usize>());
        let mut last = 0;
        for (r, to) in &edits {
            out.push_str(&s[last..r.start]);
            out.push_str(to.as_ref());
            last = r.end;
        }
        out.push_str(&s[last..]);
        *s = out;
    }

    /// Above this many edits [`apply_edits`] rebuilds the text instead.
    const IN_PLACE_EDITS: usize = 8;

    /// Replaces every whole identifier `from` with `to`, for each pair.
    pub fn replace_idents(s: &mut String, renames: &[(&str, &str)]) {
        let mut edits = Vec::new();
        for &(from, to) in renames {
            edits.extend(find_ident(s, from).map(|at| (at..at + from.len(), to)));
        }
        apply_edits(s, edits);
    }
}

#[cfg(test)]
mod tests {
    use memchr::memmem::Finder;

    use super::text::*;

    /// naga's writers may panic on IR they do not support: the panic's
    /// message must reach the user as a bug diagnostic, whichever payload
    /// type `panic!` gave it, and an `Err` from the writer likewise.
    #[test]
    fn a_failing_or_panicking_backend_becomes_a_bug_diagnostic() {
        use crate::diag::Severity;
        // A runtime argument, so the payload is a `String` (literal ones
        // are folded into the format string, which gives a `&str`).
        let at = std::hint::black_box(7);
        let formatted = super::guard("the test writer", || -> Result<(), String> { panic!("bad IR at {at}") }).unwrap_err();
        assert!(matches!(formatted.severity, Severity::Bug));
        assert_eq!(formatted.message, "the test writer panicked: bad IR at 7");
        let literal = super::guard(format_args!("the {} writer", "GLSL"), || -> Result<(), String> { panic!("unsupported") }).unwrap_err();
        assert_eq!(literal.message, "the GLSL writer panicked: unsupported");
        let failed = super::guard("the test writer", || -> Result<(), String> { Err("no entry point".into()) }).unwrap_err();
        assert_eq!(failed.message, "the test writer failed: no entry point");
        assert_eq!(super::guard("the test writer", || Ok(3)).unwrap(), 3);
    }

    #[test]
    fn whole_identifier_replacement() {
        let s = "uniform a_block_0Vertex { mat4 a; }; x = a_block_0Vertex1 + a_block_0Vertex; 1.0e_block_0Vertex";
        let mut r = s.to_string();
        replace_idents(&mut r, &[("a_block_0Vertex", "a_block")]);
        assert_eq!(r, "uniform a_block { mat4 a; }; x = a_block_0Vertex1 + a_block; 1.0e_block_0Vertex");
        assert!(contains_ident(s, "a"));
        assert!(!contains_ident(s, "mat"));
        assert!(!contains_ident("x1.0e_block", "e_block"), "inside a number is not an identifier");
        let mut two = "A_b0 + B_b1 * A_b0".to_string();
        replace_idents(&mut two, &[("A_b0", "a"), ("B_b1", "b")]);
        assert_eq!(two, "a + b * a");
        let s = "x_block + a_block_0V; a_blocky_block";
        let found = idents_containing(s, &Finder::new("_block"));
        assert_eq!(found, [(0, "x_block"), (10, "a_block_0V"), (22, "a_blocky_block")]);
        assert_eq!(idents_containing("uniform highp sampler2DShadow s;", &Finder::new("sampler")), [(14, "sampler2DShadow")]);
    }

    #[test]
    fn many_edits_rebuild_the_text_with_the_same_result() {
        let s: String = (0..40).map(|i| format!("s_tex{} + t_s_tex * s_tex;\n", i % 3)).collect();
        let mut r = s.clone();
        replace_idents(&mut r, &[("s_tex", "shadow_map")]);
        assert_eq!(r, s.replace("t_s_tex", "KEEP").replace("s_tex", "shadow_map").replace("KEEP", "t_s_tex").replace("shadow_map0", "s_tex0").replace("shadow_map1", "s_tex1").replace("shadow_map2", "s_tex2"));
        let mut few = "s_tex + s_tex".to_string();
        replace_idents(&mut few, &[("s_tex", "m")]);
        assert_eq!(few, "m + m");
    }

    #[test]
    fn overlapping_edits_keep_the_first_in_place_and_rebuilt() {
        let mut few = "abcdef".to_string();
        apply_edits(&mut few, vec![(2..5, "Y"), (0..3, "X")]);
        assert_eq!(few, "Xdef");
        let text = "abcdef".repeat(10);
        let mut many = text.clone();
        let mut edits: Vec<(std::ops::Range<usize>, &str)> = (0..10).map(|k| (6 * k..6 * k + 3, "X")).collect();
        edits.push((2..5, "Y"));
        apply_edits(&mut many, edits);
        assert_eq!(many, "Xdef".repeat(10));
    }
}
