//! A program as one consumer takes it: its code for one target (WGSL or
//! SPIR-V modules, or one GLSL file per entry point) and the manifest that
//! binds it. A GL host that binds by source names alone runs a set with no
//! manifest ([`ShaderSet::glsl_by_name`]).

use std::collections::BTreeMap;

use crate::emit::reflect_types::Reflection;
use crate::Target;

/// One module's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ShaderCode {
    Wgsl(String),
    Spirv(Vec<u32>),
    /// One entry point's GLSL (330 core or ES 3.00): its file name and text.
    Glsl { file: String, text: String },
}

impl ShaderCode {
    /// SPIR-V words from little-endian bytes.
    pub fn spirv_from_bytes(bytes: &[u8]) -> Result<ShaderCode, String> {
        if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
            return Err(format!("{} bytes is not a SPIR-V module", bytes.len()));
        }
        let words: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
        if words[0] != 0x0723_0203 {
            return Err(format!("bad SPIR-V magic number {:#010x}", words[0]));
        }
        Ok(ShaderCode::Spirv(words))
    }
}

/// A program for one target.
#[derive(Clone, Debug)]
pub struct ShaderSet {
    /// Names the program in messages.
    pub label: String,
    /// [`Target::Wgsl`], [`Target::Spirv`], [`Target::Glsl330`] or [`Target::Gles300`].
    pub target: Target,
    pub modules: Vec<ShaderCode>,
    /// Module index per entry point name; entry points not listed use
    /// module 0 (WGSL and SPIR-V; every GLSL entry point is listed).
    pub entry_module: BTreeMap<String, usize>,
    /// The manifest; `None` for a GL host that binds by source names.
    pub reflection: Option<Reflection>,
}

impl ShaderSet {
    /// One WGSL or SPIR-V module holding every entry point.
    pub fn single(label: impl Into<String>, code: ShaderCode, reflection: Reflection) -> ShaderSet {
        let target = match code {
            ShaderCode::Spirv(_) => Target::Spirv,
            _ => Target::Wgsl,
        };
        ShaderSet { label: label.into(), target, modules: vec![code], entry_module: BTreeMap::new(), reflection: Some(reflection) }
    }

    /// GLSL files by entry point name, with no manifest: a GL host binds
    /// everything by the names in the source (`glGetUniformLocation`,
    /// `glGetAttribLocation`, ...).
    pub fn glsl_by_name(label: impl Into<String>, target: Target, entries: impl IntoIterator<Item = (String, String, String)>) -> ShaderSet {
        let mut modules = Vec::new();
        let mut entry_module = BTreeMap::new();
        for (entry, file, text) in entries {
            entry_module.insert(entry, modules.len());
            modules.push(ShaderCode::Glsl { file, text });
        }
        ShaderSet { label: label.into(), target, modules, entry_module, reflection: None }
    }

    /// The program's code for `target` from a compilation that produced
    /// it, found through the manifest's per-entry-point file names.
    pub fn from_compiled(label: impl Into<String>, compiled: &crate::Compiled, target: Target) -> Result<ShaderSet, String> {
        let label = label.into();
        let key = target.name();
        let mut files: Vec<String> = Vec::new();
        let mut entry_module = BTreeMap::new();
        for e in &compiled.reflection.entry_points {
            let file = e.files.get(key).ok_or_else(|| format!("{label}: entry point `{}` has no {key} output in the reflection", e.name))?;
            let index = files.iter().position(|f| f == file).unwrap_or_else(|| {
                files.push(file.clone());
                files.len() - 1
            });
            entry_module.insert(e.name.clone(), index);
        }
        let mut modules = Vec::new();
        for file in &files {
            let a = compiled
                .artifact(file)
                .ok_or_else(|| format!("{label}: the reflection names `{file}` but the compiler did not produce it"))?;
            modules.push(match target {
                Target::Wgsl => ShaderCode::Wgsl(a.text().into_owned()),
                Target::Spirv => ShaderCode::spirv_from_bytes(&a.contents).map_err(|e| format!("{label}: {file}: {e}"))?,
                Target::Glsl330 | Target::Gles300 | Target::Glsl430 | Target::Gles310 => ShaderCode::Glsl { file: file.clone(), text: a.text().into_owned() },
            });
        }
        if modules.is_empty() {
            return Err(format!("{label}: the program has no entry points"));
        }
        Ok(ShaderSet { label, target, modules, entry_module, reflection: Some(compiled.reflection.clone()) })
    }

    pub fn module_of(&self, entry: &str) -> usize {
        self.entry_module.get(entry).copied().unwrap_or(0)
    }

    /// The GLSL file name and text of an entry point.
    pub fn glsl(&self, entry: &str) -> Result<(&str, &str), String> {
        let missing = || format!("{}: no {} file for entry point `{entry}`", self.label, self.target.name());
        let i = *self.entry_module.get(entry).ok_or_else(missing)?;
        match &self.modules[i] {
            ShaderCode::Glsl { file, text } => Ok((file, text)),
            _ => Err(missing()),
        }
    }

    /// The GLSL fragment stage of a pass: `fragment`'s file, or for a
    /// vertex-only pass an empty one in the vertex file's `#version`
    /// (GLES links no program without a fragment shader; it writes no
    /// colour, as the vertex-only pipeline it stands for).
    pub fn glsl_fragment(&self, fragment: Option<&str>, vertex_text: &str) -> Result<(String, String), String> {
        match fragment {
            Some(f) => self.glsl(f).map(|(file, text)| (file.to_string(), text.to_string())),
            None => {
                let version = vertex_text.lines().find(|l| l.starts_with("#version")).unwrap_or("#version 330 core");
                Ok(("umbrac_empty_fragment.frag".into(), format!("{version}\nvoid main() {{}}\n")))
            }
        }
    }

    /// Applies `edit` to every GLSL or WGSL text (tests use it to break a
    /// program on purpose).
    pub fn map_sources(mut self, mut edit: impl FnMut(&str) -> String) -> ShaderSet {
        for m in &mut self.modules {
            match m {
                ShaderCode::Glsl { text, .. } | ShaderCode::Wgsl(text) => *text = edit(text),
                ShaderCode::Spirv(_) => {}
            }
        }
        self
    }

    /// The manifest, or an error saying this set has none.
    pub fn manifest(&self) -> Result<&Reflection, String> {
        self.reflection.as_ref().ok_or_else(|| format!("{}: no reflection manifest (a by-name GL host runs it)", self.label))
    }
}
