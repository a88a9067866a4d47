//! WGSL: one module per input file, from `Lowered::gpu`.
//!
//! naga's WGSL writer does not write the module's diagnostic filters, so the
//! `diagnostic(...)` directives are written here, ahead of everything else.
//! The lowering relies on `diagnostic(off, derivative_uniformity)`: the DSL
//! samples textures with implicit LOD in non-uniform control flow (legal in
//! GLSL), which WGSL rejects without that directive.

use std::fmt::Write as _;

use naga::diagnostic_filter::{FilterableTriggeringRule, Severity, StandardFilterableTriggeringRule};

use super::guard;
use crate::diag::Diagnostic;
use crate::lower::Lowered;

pub fn write(lowered: &Lowered) -> Result<String, Diagnostic> {
    check_nesting(lowered)?;
    // naga's writer appends the module to the directives (as
    // `naga::back::wgsl::write_string` does to an empty string): no copy of
    // the whole text to put them in front.
    let mut out = diagnostic_directives(&lowered.gpu);
    // naga's writer writes no `enable subgroups;`, which WGSL requires
    // (naga 30's own front end does not know it: wgpu hosts drop that
    // line, docs/targets.md). Subgroup operations act on the active lanes
    // wherever they are, as in SPIR-V and GLSL, so WGSL's subgroup
    // uniformity rule is off.
    if uses_subgroups(&lowered.gpu) {
        out.insert_str(0, SUBGROUP_DIRECTIVES);
    }
    if !out.is_empty() {
        out.push('\n');
    }
    out.reserve(super::output_capacity(&lowered.gpu));
    let mut out = guard("the WGSL writer", || {
        let mut writer = naga::back::wgsl::Writer::new(out, naga::back::wgsl::WriterFlags::empty());
        writer.write(&lowered.gpu, &lowered.gpu_info).map_err(|e| e.to_string())?;
        Ok(writer.finish())
    })?;
    exact_flt_max(&mut out);
    source_entry_names(&mut out, lowered)?;
    Ok(out)
}

/// Gives each entry point its source name back where naga's namer changed
/// it (`vs1` written `vs1_`, `x__y` written `x_y`, `a_` written `a`): a
/// WebGPU host asks for the manifest's name, which the SPIR-V and the GLSL
/// file names also use. The checker refused the names WGSL cannot take
/// (its reserved words, a leading `__`, `_`); one that another item of the
/// module has is a located error.
fn source_entry_names(out: &mut String, lowered: &Lowered) -> Result<(), Diagnostic> {
    let eps = &lowered.interface.entry_points;
    // Nearly always every name is written as it is.
    if eps.iter().all(|ep| out.contains(&["\nfn ", &ep.name, "("].concat())) {
        return Ok(());
    }
    // naga writes each entry point, in module order, as a line of its
    // stage attribute then `fn NAME(`.
    let mut written = Vec::with_capacity(eps.len());
    let mut stage_line = false;
    for line in out.lines() {
        if stage_line {
            if let Some(name) = line.strip_prefix("fn ").and_then(|l| l.split('(').next()) {
                written.push(name.to_string());
            }
        }
        stage_line = ["@vertex", "@fragment", "@compute"].iter().any(|a| line.starts_with(a));
    }
    if written.len() != eps.len() {
        return Err(Diagnostic::bug(format!("the WGSL has {} entry points where the module has {}", written.len(), eps.len()), None));
    }
    let mut renames: Vec<(&str, &str)> = Vec::new();
    for (name, ep) in written.iter().zip(eps) {
        if *name == ep.name {
            continue;
        }
        if super::text::contains_ident(out, &ep.name) {
            return Err(Diagnostic::error(format!("entry point `{}` cannot keep its name in WGSL: something else there is named `{}`", ep.name, ep.name), ep.span)
                .with_note("rename the entry point or the other item: the manifest, the SPIR-V and the WGSL must name the entry point alike"));
        }
        renames.push((name, &ep.name));
    }
    super::text::replace_idents(out, &renames);
    Ok(())
}

/// naga writes an `f32` as its shortest decimal, which for FLT_MAX is
/// `340282350000000000000000000000000000000`: above FLT_MAX itself
/// (340282346638528859811704183484516925440), so outside f32's finite range,
/// which WGSL makes a shader-creation error (tint refuses it; naga rounds
/// it back). Written as the exact hexadecimal float instead. No other `f32`
/// has a shortest decimal beyond its range.
fn exact_flt_max(out: &mut String) {
    const SHORTEST: &str = "340282350000000000000000000000000000000f";
    if out.contains(SHORTEST) {
        *out = out.replace(SHORTEST, "0x1.fffffep+127f");
    }
}

/// `diagnostic(SEVERITY, RULE);` for each module-level filter, outermost
/// first; where a rule appears more than once, the innermost (the one naga
/// applies) wins.
/// What a WGSL module with subgroups starts with.
pub const SUBGROUP_DIRECTIVES: &str = "enable subgroups;\ndiagnostic(off, subgroup_uniformity);\n";

/// The WGSL text as naga 30 (wgpu 30) reads it: without `enable
/// subgroups;`, an extension its front end does not know yet (it has
/// subgroups without it).
pub fn for_naga(wgsl: &str) -> std::borrow::Cow<'_, str> {
    match wgsl.strip_prefix("enable subgroups;\n") {
        Some(rest) => rest.into(),
        None => wgsl.into(),
    }
}

/// Whether a module has a subgroup operation or reads a subgroup input
/// (WGSL's `enable subgroups`, wgpu's `Features::SUBGROUP`).
pub fn uses_subgroups(module: &naga::Module) -> bool {
    use naga::BuiltIn as B;
    let op = |f: &naga::Function| f.expressions.iter().any(|(_, e)| matches!(e, naga::Expression::SubgroupOperationResult { .. } | naga::Expression::SubgroupBallotResult));
    let input = |f: &naga::Function| {
        f.arguments.iter().any(|a| matches!(a.binding, Some(naga::Binding::BuiltIn(B::SubgroupSize | B::SubgroupInvocationId | B::NumSubgroups | B::SubgroupId))))
    };
    module.functions.iter().any(|(_, f)| op(f)) || module.entry_points.iter().any(|ep| op(&ep.function) || input(&ep.function))
}

pub fn diagnostic_directives(module: &naga::Module) -> String {
    let mut chain = Vec::new();
    let mut cur = module.diagnostic_filter_leaf;
    while let Some(h) = cur {
        let Ok(node) = module.diagnostic_filters.try_get(h) else { break };
        chain.push(&node.inner);
        cur = node.parent;
        if chain.len() > module.diagnostic_filters.len() {
            break; // a malformed (cyclic) chain; never loop forever
        }
    }
    let mut seen = Vec::new();
    let mut lines = Vec::new();
    for filter in chain {
        let rule = match &filter.triggering_rule {
            FilterableTriggeringRule::Standard(StandardFilterableTriggeringRule::DerivativeUniformity) => "derivative_uniformity".to_string(),
            FilterableTriggeringRule::Unknown(name) => name.to_string(),
            FilterableTriggeringRule::User(parts) => format!("{}.{}", parts[0], parts[1]),
        };
        if seen.contains(&rule) {
            continue;
        }
        let severity = match filter.new_severity {
            Severity::Off => "off",
            Severity::Info => "info",
            Severity::Warning => "warning",
            Severity::Error => "error",
        };
        lines.push(format!("diagnostic({severity}, {rule});"));
        seen.push(rule);
    }
    let mut out = String::new();
    for line in lines.iter().rev() {
        let _ = writeln!(out, "{line}");
    }
    out
}

/// WGSL's limit on how deeply a function's statements nest (the WGSL
/// specification, "Limits": brace-enclosed statement nesting depth 127).
pub const MAX_STATEMENT_NESTING: u32 = 127;

/// Refuses a module whose WGSL would nest statements past
/// [`MAX_STATEMENT_NESTING`], at the deepest statement. Counted as tint
/// (Chrome's WGSL compiler) counts what naga writes: the function 1, a
/// statement 1 more than what holds it, a bare block 1, an `if` (each
/// `elif`, written inside the previous `else`) or a loop 2; so 62 nested
/// `if`s, or an `if` with 61 `elif`s, are the most that fit.
fn check_nesting(lowered: &Lowered) -> Result<(), Diagnostic> {
    let gpu = &lowered.gpu;
    let bodies = gpu.functions.iter().map(|(_, f)| (&f.body, None)).chain(gpu.entry_points.iter().zip(&lowered.interface.entry_points).map(|(e, i)| (&e.function.body, Some(i.span))));
    for (body, fallback) in bodies {
        if let Some((depth, at)) = too_deep(body, 1) {
            let at = if at == naga::Span::UNDEFINED { fallback.unwrap_or_default() } else { at.into() };
            return Err(Diagnostic::error(format!("statements nest {depth} levels deep here in the WGSL output, past the {MAX_STATEMENT_NESTING} that WGSL allows"), at)
                .with_note("WGSL counts 2 levels for each `if`, `elif`, `else` and loop and 1 for each statement; GLSL and SPIR-V have no such limit (`--target` without wgsl)"));
        }
    }
    Ok(())
}

/// The first statement of `block` (at `depth`) nested past the limit.
fn too_deep(block: &naga::Block, depth: u32) -> Option<(u32, naga::Span)> {
    use naga::Statement as S;
    for (stmt, span) in block.span_iter() {
        let at = depth + 1;
        if at > MAX_STATEMENT_NESTING {
            return Some((at, *span));
        }
        let inner = match stmt {
            S::Block(b) => too_deep(b, depth + 1),
            S::If { accept, reject, .. } => too_deep(accept, depth + 2).or_else(|| too_deep(reject, depth + 2)),
            S::Loop { body, continuing, .. } => too_deep(body, depth + 2).or_else(|| too_deep(continuing, depth + 3)),
            S::Switch { cases, .. } => cases.iter().find_map(|c| too_deep(&c.body, depth + 3)),
            _ => None,
        };
        if inner.is_some() {
            return inner;
        }
    }
    None
}
