//! Writing outputs to disk atomically.

use std::path::Path;

use crate::Artifact;

/// Writes every artifact into `dir`.
pub fn write_artifacts(dir: &Path, artifacts: &[Artifact]) -> Result<(), String> {
    for a in artifacts {
        std::fs::write(dir.join(&a.file_name), &a.contents).map_err(|e| format!("cannot write {}: {e}", a.file_name))?;
    }
    Ok(())
}
