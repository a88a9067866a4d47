//! Constructs only some targets have: refused where a requested target
//! lacks them, at their first use, naming those targets; accepted when
//! only targets that have them are requested.

use super::*;
use crate::target::Target;

impl<'a, 'd> Checker<'a, 'd> {
    /// `half` (a type, a constructor or a `1.5h` literal) at `span`:
    /// WGSL (`enable f16`) and SPIR-V (Float16) have it, GLSL 330 and
    /// GLSL ES 3.00 do not.
    pub(super) fn half_used(&mut self, span: Span) {
        if self.half_refused {
            return;
        }
        let lacking: Vec<&str> = self.targets.iter().filter(|t| matches!(t, Target::Glsl330 | Target::Gles300)).map(|t| t.name()).collect();
        if lacking.is_empty() {
            return;
        }
        self.half_refused = true;
        let (which, s) = if lacking.len() == 1 { (lacking[0].to_string(), "") } else { (lacking.join(" and "), "s") };
        let d = Diagnostic::error(format!("`half` is not supported by the {which} target{s}"), span)
            .with_label("a 16-bit float")
            .with_note("GLSL 330 and GLSL ES 3.00 have no 16-bit float type (`mediump` is a precision hint, not a type); WGSL has `f16` (`enable f16`) and SPIR-V the Float16 capability")
            .with_note("help: compile this file for `--target wgsl --target spirv` only, or use `float`");
        self.diags.push(d);
    }
}
