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
    // naga's writer appends the module to the directives (as
    // `naga::back::wgsl::write_string` does to an empty string): no copy of
    // the whole text to put them in front.
    let mut out = diagnostic_directives(&lowered.gpu);
    if !out.is_empty() {
        out.push('\n');
    }
    out.reserve(super::output_capacity(&lowered.gpu));
    guard("the WGSL writer", || {
        let mut writer = naga::back::wgsl::Writer::new(out, naga::back::wgsl::WriterFlags::empty());
        writer.write(&lowered.gpu, &lowered.gpu_info).map_err(|e| e.to_string())?;
        Ok(writer.finish())
    })
}

/// `diagnostic(SEVERITY, RULE);` for each module-level filter, outermost
/// first; where a rule appears more than once, the innermost (the one naga
/// applies) wins.
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
