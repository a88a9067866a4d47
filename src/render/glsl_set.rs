//! A program's GLSL outputs (330 core or ES 3.00), one source text per
//! entry point, with the reflection that binds them. The GL consumer
//! ([`super::gl`]) and the WebGL2 consumer ([`super::webgl`]) both take one.

use std::collections::BTreeMap;

use crate::emit::reflect_types::Reflection;
use crate::Target;

/// The GLSL sources of one program for one GL profile.
#[derive(Clone, Debug)]
pub struct GlslSet {
    /// Names the program in messages.
    pub label: String,
    /// [`Target::Glsl330`] or [`Target::Gles300`].
    pub target: Target,
    /// Source text by file name (`main_vs.300es.vert`, ...), as the
    /// reflection's `files` map names them.
    pub files: BTreeMap<String, String>,
    pub reflection: Reflection,
}

impl GlslSet {
    /// The GLSL files of `target` from a compilation that produced them.
    pub fn from_compiled(label: impl Into<String>, compiled: &crate::Compiled, target: Target) -> Result<GlslSet, String> {
        let label = label.into();
        if !matches!(target, Target::Glsl330 | Target::Gles300) {
            return Err(format!("{label}: {} is not a GLSL target", target.name()));
        }
        let mut files = BTreeMap::new();
        for e in &compiled.reflection.entry_points {
            let file = e
                .files
                .get(target.name())
                .ok_or_else(|| format!("{label}: entry point `{}` has no {} output in the reflection", e.name, target.name()))?;
            let a = compiled
                .artifact(file)
                .ok_or_else(|| format!("{label}: the reflection names `{file}` but the compiler did not produce it"))?;
            files.insert(file.clone(), a.text().into_owned());
        }
        Ok(GlslSet { label, target, files, reflection: compiled.reflection.clone() })
    }

    /// The file name and source text of an entry point.
    pub fn entry(&self, entry: &str) -> Result<(&str, &str), String> {
        let e = self
            .reflection
            .entry_points
            .iter()
            .find(|e| e.name == entry)
            .ok_or_else(|| format!("{}: no entry point `{entry}`", self.label))?;
        let file = e
            .files
            .get(self.target.name())
            .ok_or_else(|| format!("{}: entry point `{entry}` has no {} file", self.label, self.target.name()))?;
        let text = self.files.get(file).ok_or_else(|| format!("{}: `{file}` is missing", self.label))?;
        Ok((file.as_str(), text.as_str()))
    }

    /// Applies `edit` to every source text (tests use it to break a
    /// program on purpose).
    pub fn map_sources(mut self, mut edit: impl FnMut(&str) -> String) -> GlslSet {
        for text in self.files.values_mut() {
            *text = edit(text);
        }
        self
    }
}
