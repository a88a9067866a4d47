//! GLSL 330 core and GLSL ES 3.00, one file per entry point.
//!
//! naga's GLSL writer runs on the GL modules (`Lowered::gl`), whose resource globals carry no
//! binding, so its namer gives samplers and uniform instances their source
//! names. Two things are then fixed up in the text:
//! - uniform blocks: naga names them `<type>_block_<N><Stage>`, which differs
//!   between the stages of one program and is meaningless to a host. Each is
//!   renamed to `<instance>_block` (`u_model_block`), identical in every
//!   stage; a rename that would collide with another identifier is refused.
//! - ES 3.00: after naga's `precision highp float; precision highp int;`,
//!   a `precision highp T;` line for every sampler type the shader uses that
//!   ES 3.00 gives no default precision (`sampler2DShadow`, ...).
//!
//! Each file is written from the entry point's own GL module
//! (`Lowered::gl[i]`), which holds only what that entry point reaches, so it
//! declares only the structs, functions, constants and globals it uses, not
//! the other stages' output structs.
//!
//! Writer flags are empty: the default (`ADJUST_COORDINATE_SPACE`) would flip
//! y and rewrite z, but the DSL already is GL-convention code.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::ops::Range;
use std::sync::LazyLock;

use memchr::memmem::Finder;

use naga::back::glsl::{Options, PipelineOptions, Version, WriterFlags};
use naga::proc::{BoundsCheckPolicies, BoundsCheckPolicy};

use super::{guard, text};
use crate::diag::Diagnostic;
use crate::lower::{EntryInterface, Lowered};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    Desktop330,
    Es300,
}

impl Profile {
    fn version(self) -> Version {
        match self {
            Profile::Desktop330 => Version::Desktop(330),
            // `is_webgl` only changes multiview (unused: the DSL has none)
            // and drops `invariant gl_FragCoord`, which WebGL2 rejects and
            // native ES does not need; so one ES file serves both WebGL2 and
            // native GLES 3.x.
            Profile::Es300 => Version::Embedded { version: 300, is_webgl: true },
        }
    }

    fn label(self) -> &'static str {
        match self {
            Profile::Desktop330 => "GLSL 330",
            Profile::Es300 => "GLSL ES 3.00",
        }
    }

    fn infix(self) -> &'static str {
        match self {
            Profile::Desktop330 => "330",
            Profile::Es300 => "300es",
        }
    }
}

/// `main_vs.330.vert`, `main_fs.300es.frag`.
pub fn file_name(entry: &str, stage: naga::ShaderStage, profile: Profile) -> String {
    let ext = match stage {
        naga::ShaderStage::Fragment => "frag",
        _ => "vert",
    };
    format!("{entry}.{}.{ext}", profile.infix())
}

/// The identifiers one GLSL entry point uses for what a host binds.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EntryNames {
    /// Uniform global (handle index) -> uniform block name.
    pub blocks: BTreeMap<usize, String>,
    /// Texture global (handle index) -> `uniform sampler*` name.
    pub samplers: BTreeMap<usize, String>,
    /// Location -> name of each `in` (vertex attributes or varyings).
    pub inputs: BTreeMap<u32, String>,
    /// Location -> name of each `out` (varyings or colour outputs).
    pub outputs: BTreeMap<u32, String>,
}

/// ES 3.00 types that have no default precision (GLSL ES 3.00 §4.5.4) and
/// that naga can write. `sampler2D` and `samplerCube` have one.
const ES_NO_DEFAULT_PRECISION: &[&str] = &[
    "sampler3D",
    "sampler2DShadow",
    "samplerCubeShadow",
    "sampler2DArray",
    "sampler2DArrayShadow",
    "isampler2D",
    "isampler3D",
    "isamplerCube",
    "isampler2DArray",
    "usampler2D",
    "usampler3D",
    "usamplerCube",
    "usampler2DArray",
];

/// Bounds checks for GLSL. Indexing arrays, vectors and matrices (also in
/// uniform blocks) is clamped (`Restrict`): an out-of-range index in GLSL is
/// undefined behaviour, and clamping is cheap and matches what WebGPU
/// guarantees, so every target reads the same element. Image loads stay
/// unchecked: the checked forms need `textureQueryLevels`, which ES 3.00
/// lacks.
fn policies() -> BoundsCheckPolicies {
    BoundsCheckPolicies {
        index: BoundsCheckPolicy::Restrict,
        buffer: BoundsCheckPolicy::Restrict,
        image_load: BoundsCheckPolicy::Unchecked,
        binding_array: BoundsCheckPolicy::Unchecked,
    }
}

/// Writes one entry point's GL module and fixes up its names.
pub fn write_entry(lowered: &Lowered, ep: &EntryInterface, profile: Profile) -> Result<(String, EntryNames), Diagnostic> {
    write_entry_from(lowered, &EntryModule::new(lowered, ep)?, ep, profile)
}

/// The GL module of one entry point and the map from its globals to the
/// GPU module's: made once and written in both GLSL profiles.
pub struct EntryModule<'a> {
    module: &'a naga::Module,
    info: &'a naga::valid::ModuleInfo,
    /// For each global of `module` (by handle index), the index of the GPU
    /// module's global of the same name, where exactly one matches.
    to_original: Vec<Option<usize>>,
}

impl<'a> EntryModule<'a> {
    pub fn new(lowered: &'a Lowered, ep: &EntryInterface) -> Result<EntryModule<'a>, Diagnostic> {
        let gl = lowered.gl.get(ep.index).ok_or_else(|| Diagnostic::bug(format!("entry point `{}` has no GL module", ep.name), None))?;
        let to_original = global_map(&gl.module, &lowered.gpu);
        Ok(EntryModule { module: &gl.module, info: &gl.info, to_original })
    }

    /// The GPU module's global index for a global of the GL module.
    fn original(&self, h: naga::Handle<naga::GlobalVariable>, ep: &EntryInterface) -> Result<usize, Diagnostic> {
        self.to_original.get(h.index()).copied().flatten().ok_or_else(|| {
            Diagnostic::bug(format!("a global of entry point `{}` has no unique name to match it with the GPU module", ep.name), None)
        })
    }
}

// Finders for the fixed needles, built once (building one costs about as
// much as searching a whole GLSL file).
static BLOCK: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new("_block"));
static LOCATION: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new("_location"));
static SAMPLER: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new("sampler"));
static PRECISION_INT: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new(PRECISION_INT_LINE));
const PRECISION_INT_LINE: &str = "precision highp int;\n";

/// [`write_entry`] from an [`EntryModule`] made for `ep`.
///
/// The fix-ups edit naga's text in place, and find the names they check
/// with one search per kind of name (every block name contains `_block`,
/// every attribute or varying name `_location`), not one per name.
pub fn write_entry_from(lowered: &Lowered, em: &EntryModule, ep: &EntryInterface, profile: Profile) -> Result<(String, EntryNames), Diagnostic> {
    let (module, module_info) = (em.module, em.info);
    let (mut out, info) = guard(format_args!("the {} writer for entry point `{}`", profile.label(), ep.name), || {
        let options = Options {
            version: profile.version(),
            writer_flags: WriterFlags::empty(),
            binding_map: Default::default(),
            zero_initialize_workgroup_memory: false,
        };
        let pipeline = PipelineOptions { shader_stage: ep.stage, entry_point: ep.name.clone(), multiview: None };
        let mut out = String::new();
        let mut writer = naga::back::glsl::Writer::new(&mut out, module, module_info, &options, &pipeline, policies())
            .map_err(|e| e.to_string())?;
        let info = writer.write().map_err(|e| e.to_string())?;
        drop(writer);
        Ok((out, info))
    })?;
    let bug = |msg: String| Diagnostic::bug(format!("{} output of entry point `{}`: {msg}", profile.label(), ep.name), None);

    let mut names = EntryNames::default();

    // Uniform blocks, in handle order so the result is deterministic.
    // naga names each `<type>_block_<N><Stage>` (declared once, never used
    // elsewhere); the new name `<instance>_block` must be free.
    let mut uniforms: Vec<_> = info.uniforms.iter().collect();
    uniforms.sort_by_key(|(h, _)| h.index());
    let mut renames: Vec<(Range<usize>, String)> = Vec::new();
    if !uniforms.is_empty() {
        let idents = text::idents_containing(&out, &BLOCK);
        for (handle, naga_block) in uniforms {
            let at = idents.iter().filter(|(_, id)| *id == naga_block.as_str()).map(|&(i, _)| i..i + naga_block.len());
            let instance = at
                .clone()
                .next()
                .and_then(|first| block_instance(&out[first.end..]))
                .ok_or_else(|| bug(format!("cannot find uniform block `{naga_block}`")))?;
            let new = [instance.trim_end_matches('_'), "_block"].concat();
            if idents.iter().any(|(_, id)| *id == new) {
                return Err(bug(format!("renaming uniform block `{naga_block}` to `{new}` would collide with an identifier of the same name")));
            }
            if renames.iter().any(|(_, n)| *n == new) {
                return Err(bug(format!("two uniform blocks would both be named `{new}`")));
            }
            renames.extend(at.map(|r| (r, new.clone())));
            names.blocks.insert(em.original(*handle, ep)?, new);
        }
    }
    text::apply_edits(&mut out, renames);

    for (name, mapping) in &info.texture_mapping {
        if !text::contains_ident(&out, name) {
            return Err(bug(format!("sampler `{name}` reported by naga is not in the text")));
        }
        let original = em.original(mapping.texture, ep)?;
        // naga's namer appends `_` to names ending in a digit (`layers_0`,
        // an element of a sampler array, becomes `layers_0_`); give the
        // sampler back its own name where nothing else uses it.
        let source = lowered.gpu.global_variables.iter().nth(original).and_then(|(_, g)| g.name.as_deref());
        let mut final_name = name.clone();
        if let Some(src) = source {
            if name.strip_suffix('_') == Some(src) && src.ends_with(|c: char| c.is_ascii_digit()) && !text::contains_ident(&out, src) {
                text::replace_idents(&mut out, &[(name, src)]);
                final_name = src.to_string();
            }
        }
        names.samplers.insert(original, final_name);
    }

    // Attributes, varyings and colour outputs are named by location
    // (`_p2vs_location0`, `_vs2fs_location1`, `_fs2p_location0`): naga
    // reports only those it wrote without `layout(location)`, so the names
    // are formed here and checked against the text.
    let (in_prefix, out_prefix) = match ep.stage {
        naga::ShaderStage::Vertex => ("_p2vs_location", "_vs2fs_location"),
        _ => ("_vs2fs_location", "_fs2p_location"),
    };
    let declared = if ep.inputs.is_empty() && ep.outputs.is_empty() { Vec::new() } else { text::idents_containing(&out, &LOCATION) };
    for (vars, prefix, map) in [(&ep.inputs, in_prefix, &mut names.inputs), (&ep.outputs, out_prefix, &mut names.outputs)] {
        for var in vars {
            let name = format!("{prefix}{}", var.location);
            if !declared.iter().any(|(_, id)| *id == name) {
                return Err(bug(format!("`{}` (location {}) is not declared as `{name}`", var.name, var.location)));
            }
            if let Some(loc) = info.varying.get(&name) {
                if loc.location != var.location {
                    return Err(bug(format!("`{name}` has location {}, expected {}", loc.location, var.location)));
                }
            }
            map.insert(var.location, name);
        }
    }

    if profile == Profile::Es300 {
        add_es_precision(&mut out).ok_or_else(|| bug("no `precision highp int;` line to extend".into()))?;
    }
    Ok((out, names))
}

/// Maps the globals of an entry point's GL module to the GPU module's
/// global indices (by name: the lowering makes global names unique, and the
/// modules' handles differ).
fn global_map(gl: &naga::Module, gpu: &naga::Module) -> Vec<Option<usize>> {
    gl.global_variables
        .iter()
        .map(|(_, g)| {
            let mut same = gpu.global_variables.iter().filter(|(_, o)| o.name.is_some() && o.name == g.name && o.space == g.space);
            match (same.next(), same.next()) {
                (Some((h, _)), None) => Some(h.index()),
                _ => None,
            }
        })
        .collect()
}

/// The instance name declared inside `uniform BLOCK { T name; };`, from
/// the text that follows `BLOCK`.
fn block_instance(rest: &str) -> Option<&str> {
    let open = rest.find('{')?;
    let body = &rest[open + 1..];
    let decl = &body[..body.find(';')?];
    let decl = decl.split('[').next()?;
    let name = decl.split_whitespace().last()?;
    Some(name)
}

/// Adds `precision highp T;` for every no-default-precision type the text
/// uses, right after naga's `precision highp int;`.
fn add_es_precision(src: &mut String) -> Option<()> {
    let at = PRECISION_INT.find(src.as_bytes())? + PRECISION_INT_LINE.len();
    // Every such type name contains `sampler`: look only at those words.
    let used = text::idents_containing(src, &SAMPLER);
    let mut lines = String::new();
    for ty in ES_NO_DEFAULT_PRECISION {
        if used.iter().any(|(_, id)| id == ty) {
            let _ = writeln!(lines, "precision highp {ty};");
        }
    }
    src.insert_str(at, &lines);
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_block_instances() {
        assert_eq!(block_instance(" { highp mat4 u_model; };\nuniform X_block_1Vertex { vec4 arr[4]; };"), Some("u_model"));
        assert_eq!(block_instance(" { vec4 arr[4]; };"), Some("arr"));
        assert_eq!(block_instance(" {"), None);
    }

    #[test]
    fn es_precision_goes_after_int() {
        let s = "#version 300 es\n\nprecision highp float;\nprecision highp int;\n\nuniform highp sampler2DShadow s;\nuniform highp isampler2D t;\n";
        let mut out = s.to_string();
        add_es_precision(&mut out).unwrap();
        assert!(out.contains("precision highp int;\nprecision highp sampler2DShadow;\nprecision highp isampler2D;\n\nuniform"));
    }
}
