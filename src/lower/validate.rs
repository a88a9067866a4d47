//! naga's validator, with the flags and capabilities of each flavour of
//! module; a rejection is an internal compiler error.

use std::cell::Cell;

use naga::valid::Validator;
use naga::Module;

use super::interface::Flavor;
use crate::diag::Diagnostic;
use crate::source::Span;

/// The validator for modules of `flavor`.
fn validator(flavor: Flavor) -> Validator {
    use naga::valid::{Capabilities, ValidationFlags};
    let (flags, caps) = match flavor {
        Flavor::Gl => (ValidationFlags::all() - ValidationFlags::BINDINGS, naga::back::glsl::supported_capabilities()),
        // `packHalf2x16` needs SHADER_FLOAT16_IN_FLOAT32 (WebGPU has it
        // everywhere), `half` needs SHADER_FLOAT16 (WebGPU's `shader-f16`).
        // Subgroups, `gl_DrawID` and `gl_PrimitiveID`: sema refuses them
        // for the targets that lack them.
        Flavor::Gpu(_) => (
            ValidationFlags::all(),
            Capabilities::default()
                | Capabilities::SHADER_FLOAT16_IN_FLOAT32
                | Capabilities::SHADER_FLOAT16
                | Capabilities::SUBGROUP
                | Capabilities::SUBGROUP_BARRIER
                | Capabilities::PRIMITIVE_INDEX
                | Capabilities::DRAW_INDEX
                // Vulkan-dialect descriptor arrays (SPIR-V only, by sema).
                | Capabilities::TEXTURE_AND_SAMPLER_BINDING_ARRAY
                | Capabilities::TEXTURE_AND_SAMPLER_BINDING_ARRAY_NON_UNIFORM_INDEXING
                // Mesh and task entry points (SPIR-V only, by sema).
                | Capabilities::MESH_SHADER,
        ),
    };
    Validator::new(flags, caps)
}

thread_local! {
    /// This thread's validators, GL's and the GPU modules', kept between
    /// modules and compilations: naga resets a validator per module and
    /// keeps its tables' memory, so a thread that compiles many variants
    /// builds them once.
    static GL_VALIDATOR: Cell<Option<Validator>> = const { Cell::new(None) };
    static GPU_VALIDATOR: Cell<Option<Validator>> = const { Cell::new(None) };
}

/// Validates a finished module with this thread's validator for `flavor`;
/// a failure is an internal compiler error located at the span naga reports.
pub fn validate(module: &Module, flavor: Flavor) -> Result<naga::valid::ModuleInfo, Diagnostic> {
    let kept = match flavor {
        Flavor::Gl => &GL_VALIDATOR,
        Flavor::Gpu(_) => &GPU_VALIDATOR,
    };
    // Taken out while it runs: a panic in naga drops it instead of leaving
    // one in an unknown state for the next module.
    let mut validator = kept.take().unwrap_or_else(|| validator(flavor));
    let result = validator.validate(module);
    kept.set(Some(validator));
    result.map_err(|e| {
        let span = e.spans().next().map(|(s, _)| Span::from(*s)).filter(|s| !s.is_empty());
        let mut msg = e.as_inner().to_string();
        let mut src: Option<&dyn std::error::Error> = std::error::Error::source(e.as_inner());
        while let Some(s) = src {
            msg.push_str(&format!(": {s}"));
            src = s.source();
        }
        let which = match flavor {
            Flavor::Gl => "GLSL",
            Flavor::Gpu(_) => "WGSL/SPIR-V",
        };
        let mut d = Diagnostic::bug(format!("naga rejected the IR built for the {which} targets: {msg}"), span);
        for (_, label) in e.spans().skip(1).take(3) {
            if !label.is_empty() {
                d = d.with_note(label.clone());
            }
        }
        d.with_note("this is a bug in umbrac; no output was written")
    })
}
