//! Emission: validated naga modules to target text, and the reflection manifest.

pub mod reflect_types;

use crate::diag::Diagnostic;
use crate::lower::Lowered;
use crate::{Artifact, Reflection, Target};

/// Emits every requested target plus the reflection manifest.
pub fn emit(_lowered: &Lowered, _stem: &str, _source_name: &str, _targets: &[Target]) -> Result<(Vec<Artifact>, Reflection), Diagnostic> {
    Err(Diagnostic::bug("emitter not written yet", None))
}
