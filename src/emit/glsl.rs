//! GLSL 330 core, GLSL ES 3.00, GLSL 430 core and GLSL ES 3.10, one file
//! per entry point.
//!
//! naga's GLSL writer runs on the GL modules (`Lowered::gl`), whose resource globals carry no
//! binding, so its namer gives samplers and uniform instances their source
//! names (where naga appends `_`, to a name ending in a digit, the source
//! name is given back: `glsl_names`). Then the text is fixed up:
//! - uniform blocks: naga names them `<type>_block_<N><Stage>`, which differs
//!   between the stages of one program and is meaningless to a host. Each is
//!   renamed to `<name>_ubo` (`u_cam_ubo`, as daslang's generator names
//!   it), identical in every stage; a rename that would collide with another
//!   identifier is refused. naga declares the struct as the block's one
//!   member (`{ Camera u_cam; }`); a uniform block is given the struct's
//!   members and an instance name instead (`{ mat4 model; ... } u_cam;`),
//!   as daslang's generator declares it, so that a stage links with the
//!   generator's other stage (the GL lowering reads a whole struct member
//!   by member, as an instance is no value).
//! - varyings: naga's `smooth` is dropped (GLSL's default for floats;
//!   daslang's generator writes none, and Mesa refuses a qualifier on one
//!   side only); `flat` stays.
//! - plain uniforms: the GL module holds a loose uniform as a private global
//!   (`GlEntry::uniforms`), which naga declares `T name = zero;`; that line
//!   becomes `uniform T name;`.
//! - attributes, varyings and colour outputs take their source names, and a
//!   `layout(location = N)` only where the source gives one.
//! - ES 3.00: after naga's `precision highp float; precision highp int;`,
//!   a `precision highp T;` line for every sampler type the shader uses that
//!   ES 3.00 gives no default precision (`sampler2DShadow`, ...).
//!
//! - GLSL 430 / ES 3.10 (compute, storage buffers, images): the GL
//!   module is written with bindings on its storage buffers and textures
//!   (GLES 3.1 has no `glShaderStorageBlockBinding` and cannot set an
//!   image's unit from the host), so each declares `layout(binding = N)`:
//!   a storage buffer its GL binding point, a storage image its image
//!   unit, a sampler its texture unit. Storage blocks are `<name>_ssbo`.
//!   Workgroup memory is zeroed at the start of each workgroup, as WGSL
//!   and SPIR-V (naga's polyfill) do.
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

use super::{glsl_names, guard, text};
// The block names are the name picker's to know (it keeps varyings off them).
pub use glsl_names::{block_name, storage_block_name};
use crate::diag::Diagnostic;
use crate::lower::{EntryInterface, Lowered};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    Desktop330,
    Es300,
    Desktop430,
    Es310,
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
            Profile::Desktop430 => Version::Desktop(430),
            Profile::Es310 => Version::Embedded { version: 310, is_webgl: false },
        }
    }

    /// Resources carry `layout(binding = N)` (GLSL 430, ES 3.10).
    fn binds_in_shader(self) -> bool {
        matches!(self, Profile::Desktop430 | Profile::Es310)
    }

    fn is_es(self) -> bool {
        matches!(self, Profile::Es300 | Profile::Es310)
    }

    fn label(self) -> &'static str {
        match self {
            Profile::Desktop330 => "GLSL 330",
            Profile::Es300 => "GLSL ES 3.00",
            Profile::Desktop430 => "GLSL 430",
            Profile::Es310 => "GLSL ES 3.10",
        }
    }

    fn infix(self) -> &'static str {
        match self {
            Profile::Desktop330 => "330",
            Profile::Es300 => "300es",
            Profile::Desktop430 => "430",
            Profile::Es310 => "310es",
        }
    }
}

/// `main_vs.330.vert`, `main_fs.300es.frag`, `fill.430.comp`.
pub fn file_name(entry: &str, stage: naga::ShaderStage, profile: Profile) -> String {
    let ext = match stage {
        naga::ShaderStage::Fragment => "frag",
        naga::ShaderStage::Compute => "comp",
        _ => "vert",
    };
    // Made for every file of every compile: no formatting machinery.
    [entry, ".", profile.infix(), ".", ext].concat()
}

/// The identifiers one GLSL entry point uses for what a host binds.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EntryNames {
    /// Uniform global (handle index) -> uniform block name.
    pub blocks: BTreeMap<usize, String>,
    /// Source name -> GLSL name of each plain uniform.
    pub uniforms: BTreeMap<String, String>,
    /// `(is an output, location)` of each `in`/`out` declared with
    /// `layout(location = N)`.
    pub located: std::collections::BTreeSet<(bool, u32)>,
    /// Texture global (handle index) -> `uniform sampler*` name.
    pub samplers: BTreeMap<usize, String>,
    /// Location -> name of each `in` (vertex attributes or varyings).
    pub inputs: BTreeMap<u32, String>,
    /// Location -> name of each `out` (varyings or colour outputs).
    pub outputs: BTreeMap<u32, String>,
    /// Source name -> GLSL name of each storage image (GLSL 430 / ES 3.10).
    pub images: BTreeMap<String, String>,
    /// Uniform global (handle index) -> the GLSL names of its block's
    /// members, in order (`u_cam_ubo.model` is what a host queries).
    pub block_members: BTreeMap<usize, Vec<String>>,
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
    let varyings = VaryingNames::of(lowered);
    write_entry_from(lowered, &EntryModule::new(lowered, ep, &varyings)?, ep, profile)
}

/// The GLSL name of the Vulkan-dialect varying at `location` (before
/// `glsl_names` renames it where the program already has that name).
pub fn vulkan_varying_name(location: u32) -> String {
    format!("vk_location{location}")
}

/// The GLSL name of each attribute, varying and colour output of a
/// compile, by source name: chosen once ([`glsl_names::pick_names`])
/// against everything the GL texts that have them can hold, so that both
/// stages of a program, and every profile, agree.
pub struct VaryingNames<'a> {
    names: Vec<(&'a str, String)>,
    /// The plain uniforms naga's namer would rename in some GL module
    /// (`a_`, `in_a` beside the input holder `in_a`), with the name every
    /// stage gives them. Nearly always empty.
    uniforms: Vec<(&'a str, String)>,
}

impl<'a> VaryingNames<'a> {
    pub fn of(lowered: &'a Lowered) -> VaryingNames<'a> {
        let with_io = || lowered.interface.entry_points.iter().filter(|ep| !ep.inputs.is_empty() || !ep.outputs.is_empty());
        // What is named, in order, each once: by source name, and for the
        // Vulkan dialect's varyings, which link by location under two
        // source names, by location: GL links by name, so both sides take
        // one made of the location (`vk_location1`), which either side can
        // derive.
        let mut named: Vec<(&str, usize)> = Vec::new();
        let mut wanted: Vec<std::borrow::Cow<'_, str>> = Vec::new();
        let mut locations: Vec<u32> = Vec::new();
        for ep in with_io().filter(|ep| ep.dialect == crate::syntax::ast::Dialect::Vulkan) {
            let varyings = match ep.stage {
                naga::ShaderStage::Vertex => &ep.outputs,
                naga::ShaderStage::Fragment => &ep.inputs,
                _ => continue,
            };
            for var in varyings {
                if named.iter().any(|(n, _)| *n == var.name) {
                    continue;
                }
                let at = locations.iter().position(|&l| l == var.location).unwrap_or_else(|| {
                    locations.push(var.location);
                    wanted.push(vulkan_varying_name(var.location).into());
                    wanted.len() - 1
                });
                named.push((&var.name, at));
            }
        }
        for var in with_io().flat_map(|ep| ep.inputs.iter().chain(&ep.outputs)) {
            if !named.iter().any(|(n, _)| *n == var.name) {
                named.push((&var.name, wanted.len()));
                wanted.push(var.name.as_str().into());
            }
        }
        let uniforms = renamed_uniforms(lowered);
        let modules: Vec<&naga::Module> = with_io().filter_map(|ep| lowered.gl.get(ep.index)).map(|gl| &gl.module).collect();
        let taken: Vec<&str> = uniforms.iter().map(|(_, n)| n.as_str()).collect();
        let wanted: Vec<&str> = wanted.iter().map(|w| w.as_ref()).collect();
        let picked = glsl_names::pick_names(&modules, &taken, &wanted);
        // (Two source names of one location share its name.)
        let names = named.into_iter().map(|(n, at)| (n, picked[at].clone())).collect();
        VaryingNames { names, uniforms }
    }

    /// The compile's GLSL name of plain uniform `source`, where naga would
    /// rename it.
    fn uniform(&self, source: &str) -> Option<&str> {
        self.uniforms.iter().find(|(n, _)| *n == source).map(|(_, g)| g.as_str())
    }

    /// For the plain uniforms of `module` that [`VaryingNames::uniform`]
    /// names, a placeholder naga keeps: unique in the module, a letter last.
    fn placeholders(&self, module: &naga::Module, uniforms: &[(naga::Handle<naga::GlobalVariable>, String)]) -> Vec<(naga::Handle<naga::GlobalVariable>, String)> {
        let mine: Vec<_> = uniforms.iter().filter(|(_, s)| self.uniform(s).is_some()).collect();
        if mine.is_empty() {
            return Vec::new();
        }
        let mut names = rustc_hash::FxHashSet::default();
        glsl_names::module_names(module, |n| {
            names.insert(n.to_string());
        });
        mine.into_iter()
            .map(|(h, _)| {
                let mut p = format!("umbrac_uniform_{}_x", h.index());
                while names.contains(&p) {
                    p.push('x');
                }
                (*h, p)
            })
            .collect()
    }

    fn get(&self, source: &str) -> Option<&str> {
        self.names.iter().find(|(n, _)| *n == source).map(|(_, g)| g.as_str())
    }
}

/// The GL module of one entry point and the map from its globals to the
/// GPU module's: made once and written in both GLSL profiles.
pub struct EntryModule<'a> {
    module: &'a naga::Module,
    info: &'a naga::valid::ModuleInfo,
    /// For each global of `module` (by handle index), the index of the GPU
    /// module's global of the same name, where exactly one matches.
    to_original: Vec<Option<usize>>,
    /// [`crate::lower::GlEntry::uniforms`].
    uniforms: &'a [(naga::Handle<naga::GlobalVariable>, String)],
    /// The GLSL name of every attribute, varying and colour output of the
    /// compile: the same in every stage and profile.
    varyings: &'a VaryingNames<'a>,
}

impl<'a> EntryModule<'a> {
    /// `varyings`: [`VaryingNames::of`] the compile.
    pub fn new(lowered: &'a Lowered, ep: &EntryInterface, varyings: &'a VaryingNames<'a>) -> Result<EntryModule<'a>, Diagnostic> {
        let gl = lowered.gl.get(ep.index).ok_or_else(|| Diagnostic::bug(format!("entry point `{}` has no GL module", ep.name), None))?;
        let to_original = global_map(&gl.module, &lowered.gpu);
        Ok(EntryModule { module: &gl.module, info: &gl.info, to_original, uniforms: &gl.uniforms, varyings })
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
static STRUCT: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new("\nstruct "));
static STRUCT_END: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new("\n};"));
static PRECISION_INT: LazyLock<Finder<'static>> = LazyLock::new(|| Finder::new(PRECISION_INT_LINE));
const PRECISION_INT_LINE: &str = "precision highp int;\n";

/// [`write_entry`] from an [`EntryModule`] made for `ep`.
///
/// The fix-ups edit naga's text in place, and find the names they check
/// with one search per kind of name (every block name contains `_block`,
/// every attribute or varying name `_location`), not one per name.
pub fn write_entry_from(lowered: &Lowered, em: &EntryModule, ep: &EntryInterface, profile: Profile) -> Result<(String, EntryNames), Diagnostic> {
    let bound;
    let (module, binding_map, renamed) = if profile.binds_in_shader() {
        let (m, map, renamed) = with_gl_bindings(lowered, em, ep)?;
        bound = m;
        (&bound, map, renamed)
    } else {
        (em.module, Default::default(), Vec::new())
    };
    // Plain uniforms whose names naga's namer could change are written
    // under placeholders it keeps, then given their compile's names below.
    let placeholders = em.varyings.placeholders(em.module, em.uniforms);
    let placed;
    let module = if placeholders.is_empty() {
        module
    } else {
        let mut m = module.clone();
        for (h, p) in &placeholders {
            m.global_variables[*h].name = Some(p.clone());
        }
        placed = m;
        &placed
    };
    let module_info = em.info;
    let (mut out, info) = guard(format_args!("the {} writer for entry point `{}`", profile.label(), ep.name), || {
        let options = Options {
            version: profile.version(),
            writer_flags: WriterFlags::empty(),
            binding_map,
            zero_initialize_workgroup_memory: true,
        };
        let pipeline = PipelineOptions { shader_stage: ep.stage, entry_point: ep.name.clone(), multiview: None };
        let mut out = String::with_capacity(super::output_capacity(module));
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
    // elsewhere); the new name `<name>_ubo` must be free.
    let mut uniforms: Vec<_> = info.uniforms.iter().collect();
    uniforms.sort_by_key(|(h, _)| h.index());
    let mut renames: Vec<(Range<usize>, String)> = Vec::new();
    // (naga's instance name, source name, global, block name, a uniform
    // block of a struct)
    let mut instances: Vec<(String, String, usize, String, bool)> = Vec::new();
    if !uniforms.is_empty() {
        let idents = text::idents_containing(&out, &BLOCK);
        for (handle, naga_block) in uniforms {
            let at = idents.iter().filter(|(_, id)| *id == naga_block.as_str()).map(|&(i, _)| i..i + naga_block.len());
            let instance = at
                .clone()
                .next()
                .and_then(|first| trailing_instance(&out[first.end..]).or_else(|| block_instance(&out[first.end..])))
                .ok_or_else(|| bug(format!("cannot find uniform block `{naga_block}`")))?;
            let original = em.original(*handle, ep)?;
            let source = lowered.gpu.global_variables.iter().nth(original).and_then(|(_, g)| g.name.clone()).unwrap_or_else(|| instance.to_string());
            let storage = matches!(em.module.global_variables[*handle].space, naga::AddressSpace::Storage { .. });
            let new = if storage { storage_block_name(&source) } else { block_name(&source) };
            if idents.iter().any(|(_, id)| *id == new) || text::contains_ident(&out, &new) {
                return Err(bug(format!("renaming uniform block `{naga_block}` to `{new}` would collide with an identifier of the same name")));
            }
            if renames.iter().any(|(_, n)| *n == new) {
                return Err(bug(format!("two uniform blocks would both be named `{new}`")));
            }
            // Only a struct has members to declare (a test's WGSL module may
            // hold a lone matrix in a uniform buffer).
            let is_struct = matches!(em.module.types[em.module.global_variables[*handle].ty].inner, naga::TypeInner::Struct { .. });
            instances.push((instance.to_string(), source, original, new.clone(), !storage && is_struct));
            renames.extend(at.map(|r| (r, new.clone())));
            names.blocks.insert(original, new);
        }
    }
    text::apply_edits(&mut out, renames);
    for (naga_name, source, original, block, uniform) in &instances {
        let name = restore_source_name(&mut out, naga_name, source);
        // A uniform block declares its struct's members, with an instance
        // name, as daslang's generator does: stages of both link.
        if *uniform {
            let members = inline_block_members(&mut out, block, &name).ok_or_else(|| bug(format!("cannot declare the members of uniform block `{block}`")))?;
            names.block_members.insert(*original, members);
        }
    }

    // Plain uniforms: `T name = zero;` becomes `uniform T name;`.
    for (handle, source) in em.uniforms {
        let placeholder = placeholders.iter().find(|(h, _)| h == handle).map(|(_, p)| p.as_str());
        let naga_name = placeholder.or(em.module.global_variables[*handle].name.as_deref()).unwrap_or(source);
        if let (Some(p), Some(name)) = (placeholder, em.varyings.uniform(source)) {
            // Named for the whole compile, so every stage agrees.
            let (line, at) = global_declaration(&out, p).ok_or_else(|| bug(format!("cannot find the declaration of uniform `{source}`")))?;
            let decl = &out[line.clone()];
            let at = at - line.start;
            let after = &decl[at + p.len()..];
            let dims = &after[..after.find([' ', ';']).unwrap_or(after.len())];
            let new = ["uniform ", &decl[..at], p, dims, ";"].concat();
            out.replace_range(line, &new);
            text::replace_idents(&mut out, &[(p, name)]);
            names.uniforms.insert(source.clone(), name.to_string());
            continue;
        }
        // Declared under its name, or with naga's `_` after a final digit.
        let underscored;
        let found = match global_declaration(&out, naga_name) {
            Some(found) => Some((naga_name, found)),
            None => {
                underscored = [naga_name, "_"].concat();
                global_declaration(&out, &underscored).map(|found| (underscored.as_str(), found))
            }
        };
        let Some((naga_name, found)) = found else {
            return Err(bug(format!("cannot find the declaration of uniform `{source}`")));
        };
        let name = restore_source_name(&mut out, naga_name, source);
        // Found again only if renaming moved the text.
        let found = if name == naga_name { Some(found) } else { global_declaration(&out, &name) };
        let (line, at) = found.ok_or_else(|| bug(format!("cannot find the declaration of uniform `{name}`")))?;
        let decl = &out[line.clone()];
        let at = at - line.start;
        let after = &decl[at + name.len()..];
        let dims = &after[..after.find([' ', ';']).unwrap_or(after.len())];
        let new = ["uniform ", &decl[..at], &name, dims, ";"].concat();
        out.replace_range(line, &new);
        names.uniforms.insert(source.clone(), name);
    }

    for (name, mapping) in &info.texture_mapping {
        // Storage images are named below.
        if renamed.iter().any(|(n, _)| n == name) {
            continue;
        }
        if !text::contains_ident(&out, name) {
            return Err(bug(format!("sampler `{name}` reported by naga is not in the text")));
        }
        let original = em.original(mapping.texture, ep)?;
        // naga's namer appends `_` to names ending in a digit (`layers_0`,
        // an element of a sampler array, becomes `layers_0_`); give the
        // sampler back its own name where nothing else uses it.
        let source = lowered.gpu.global_variables.iter().nth(original).and_then(|(_, g)| g.name.as_deref());
        let final_name = match source {
            Some(src) => restore_source_name(&mut out, name, src),
            None => name.clone(),
        };
        names.samplers.insert(original, final_name);
    }

    // Storage images, which naga names by binding here.
    for (naga_name, source) in &renamed {
        if !text::contains_ident(&out, naga_name) {
            return Err(bug(format!("storage image `{source}` is not declared as `{naga_name}`")));
        }
        let name = restore_source_name(&mut out, naga_name, source);
        names.images.insert(source.clone(), name);
    }

    // Attributes, varyings and colour outputs: naga names them by location
    // (`_p2vs_location0`, `_vs2fs_location1`, `_fs2p_location0`); each is
    // renamed to its source name (`glsl_names`: reserved or taken names
    // get `_`), so that a host binds it by name and the stages of a
    // program link by name. `layout(location = N)` stays only where the
    // source gives the location, and on the outputs of a fragment shader
    // with several (ES 3.00 requires it there).
    let (in_prefix, out_prefix) = match ep.stage {
        naga::ShaderStage::Vertex => ("_p2vs_location", "_vs2fs_location"),
        _ => ("_vs2fs_location", "_fs2p_location"),
    };
    let declared = if ep.inputs.is_empty() && ep.outputs.is_empty() { Vec::new() } else { text::idents_containing(&out, &LOCATION) };
    // ES 3.00 requires a location on each of several colour outputs; both
    // profiles keep them there, so that one manifest describes both.
    let mrt = ep.stage == naga::ShaderStage::Fragment && ep.outputs.len() > 1;
    let mut renames: Vec<(String, String)> = Vec::new();
    let mut unlocated: Vec<String> = Vec::new();
    for (vars, prefix, map, attribute_or_output) in [
        (&ep.inputs, in_prefix, &mut names.inputs, ep.stage == naga::ShaderStage::Vertex),
        (&ep.outputs, out_prefix, &mut names.outputs, ep.stage == naga::ShaderStage::Fragment),
    ] {
        for var in vars {
            let Some(&(_, name)) = declared.iter().find(|(_, id)| is_location_name(id, prefix, var.location)) else {
                return Err(bug(format!("`{}` (location {}) is not declared as `{prefix}{}`", var.name, var.location, var.location)));
            };
            let name = name.to_string();
            if let Some(loc) = info.varying.get(&name) {
                if loc.location != var.location {
                    return Err(bug(format!("`{name}` has location {}, expected {}", loc.location, var.location)));
                }
            }
            // The same in every stage of a program (`VaryingNames`): the
            // lowering names what holds inputs and outputs inside the
            // function apart (`in_`, `out_`), and the checker keeps
            // top-level names unique and locals off them, so only reserved
            // words and names naga makes up are renamed.
            let glsl = em.varyings.get(&var.name).ok_or_else(|| bug(format!("`{}` has no GLSL name", var.name)))?.to_string();
            debug_assert!(!names_a_variable(&out, &struct_bodies(&out), &glsl), "`{glsl}` is a variable of the GLSL text but not a name naga could have written");
            // naga writes varyings without a location (they link by name).
            if attribute_or_output && !var.explicit_location && !mrt {
                unlocated.push(glsl.clone());
            } else if attribute_or_output {
                names.located.insert((std::ptr::eq(vars, &ep.outputs), var.location));
            }
            renames.push((name, glsl.clone()));
            map.insert(var.location, glsl);
        }
    }
    // Renamed where `declared` found them: the text has not changed since.
    let edits: Vec<(Range<usize>, &str)> = declared
        .iter()
        .filter_map(|&(at, id)| renames.iter().find(|(from, _)| from == id).map(|(from, to)| (at..at + from.len(), to.as_str())))
        .collect();
    text::apply_edits(&mut out, edits);
    for name in &unlocated {
        drop_location_qualifier(&mut out, name).ok_or_else(|| bug(format!("no `layout(location = N)` declaration of `{name}` to drop")))?;
    }

    drop_smooth_qualifiers(&mut out);
    if profile.is_es() {
        add_es_precision(&mut out).ok_or_else(|| bug("no `precision highp int;` line to extend".into()))?;
    }
    Ok((out, names))
}

/// Whether `id` is naga's name for location `location` with `prefix`
/// (`_vs2fs_location` and 1: `_vs2fs_location1`), without formatting it.
fn is_location_name(id: &str, prefix: &str, location: u32) -> bool {
    id.strip_prefix(prefix).is_some_and(|n| n.bytes().all(|b| b.is_ascii_digit()) && (n == "0" || !n.starts_with('0')) && n.parse() == Ok(location))
}

/// Whether `name` is a variable (or function, or type) of the text: an
/// identifier there that is not a struct member (declared in one of the
/// `struct_bodies`, or read after a `.`). Debug builds check every name
/// given against the text with it.
fn names_a_variable(src: &str, struct_bodies: &[Range<usize>], name: &str) -> bool {
    text::find_ident(src, name).any(|at| !src[..at].ends_with('.') && !struct_bodies.iter().any(|body| body.contains(&at)))
}

/// The byte ranges of the struct definitions of the text, from `struct`
/// to the `};` that closes it (naga writes both at the start of a line).
fn struct_bodies(src: &str) -> Vec<Range<usize>> {
    let b = src.as_bytes();
    let starts = src.starts_with("struct ").then_some(0).into_iter().chain(STRUCT.find_iter(b).map(|at| at + 1));
    starts.filter_map(|open| STRUCT_END.find(&b[open..]).map(|end| open..open + end + STRUCT_END.needle().len())).collect()
}


/// [`with_gl_bindings`]' module, binding map and renamed images.
type GlBound = (naga::Module, naga::back::glsl::BindingMap, Vec<(String, String)>);

/// A copy of the entry point's GL module whose storage buffers and
/// textures have bindings, the map from those to GL binding points
/// (storage buffers), image units (storage images) and texture units
/// (samplers), and the names naga then gives the storage images, with
/// their source names.
fn with_gl_bindings(lowered: &Lowered, em: &EntryModule, ep: &EntryInterface) -> Result<GlBound, Diagnostic> {
    let mut module = em.module.clone();
    let mut map = naga::back::glsl::BindingMap::default();
    let mut renamed = Vec::new();
    let stage = match ep.stage {
        naga::ShaderStage::Compute => "cs",
        naga::ShaderStage::Fragment => "fs",
        _ => "vs",
    };
    for (h, g) in module.global_variables.iter_mut() {
        let storage = matches!(g.space, naga::AddressSpace::Storage { .. });
        let image = g.space == naga::AddressSpace::Handle && matches!(em.module.types[g.ty].inner, naga::TypeInner::Image { .. });
        if !storage && !image {
            continue;
        }
        let original = em.original(h, ep)?;
        let Some(r) = lowered.interface.resources.iter().find(|r| r.global.index() == original) else {
            return Err(Diagnostic::bug(format!("entry point `{}` uses a resource the interface does not describe", ep.name), None));
        };
        let unit = r.texture_unit.unwrap_or(0);
        let binding = naga::ResourceBinding { group: 0, binding: h.index() as u32 };
        g.binding = Some(binding);
        map.insert(binding, u8::try_from(unit).map_err(|_| Diagnostic::bug(format!("unit {unit} of `{}` does not fit GLSL's binding", r.name), None))?);
        if matches!(r.kind, crate::lower::ResourceKind::Image { .. }) {
            renamed.push((format!("_group_0_binding_{}_{stage}", h.index()), r.name.clone()));
        }
    }
    Ok((module, map, renamed))
}

/// The plain uniforms of a compile whose names naga's namer would change
/// in some GL module, each with a name that no GL text of the compile can
/// hold otherwise (chosen against every module's names but theirs, so the
/// stages agree), nor another of them.
fn renamed_uniforms(lowered: &Lowered) -> Vec<(&str, String)> {
    let gls = || lowered.interface.entry_points.iter().filter_map(|ep| lowered.gl.get(ep.index)).filter(|gl| !gl.uniforms.is_empty());
    let mut renamed: Vec<&str> = Vec::new();
    for gl in gls() {
        let names: Vec<&str> = gl.uniforms.iter().map(|(h, source)| gl.module.global_variables[*h].name.as_deref().unwrap_or(source)).collect();
        for ((_, source), kept) in gl.uniforms.iter().zip(glsl_names::namer_keeps(&gl.module, &names)) {
            if !kept && !renamed.contains(&source.as_str()) {
                renamed.push(source);
            }
        }
    }
    if renamed.is_empty() {
        return Vec::new();
    }
    let mut labels = glsl_names::NamerLabels::default();
    for gl in gls() {
        labels.add_module_without(&gl.module, |n| renamed.contains(&n));
    }
    let mut chosen: Vec<(&str, String)> = Vec::new();
    for source in renamed {
        let name = glsl_names::glsl_name(source, |n| labels.taken(n) || chosen.iter().any(|(_, c)| c == n));
        chosen.push((source, name));
    }
    chosen
}


/// Gives a global its source name back where naga's namer changed it (it
/// appends `_` to names ending in a digit, `layers_0` becoming
/// `layers_0_`): the name `glsl_names` gives the source name, unless
/// something else in the text has it. Returns the name the text uses.
fn restore_source_name(out: &mut String, naga_name: &str, source: &str) -> String {
    if naga_name == source {
        return naga_name.to_string();
    }
    let name = glsl_names::glsl_name(source, |n| n != naga_name && text::contains_ident(out, n));
    if name != naga_name {
        text::replace_idents(out, &[(naga_name, &name)]);
    }
    name
}

/// The line range (without its newline) of the global declaration of
/// `name`, and where in the text the name is: at the start of a line
/// (struct members are indented), the name followed by an initialiser, an
/// array size or `;`.
fn global_declaration(src: &str, name: &str) -> Option<(Range<usize>, usize)> {
    text::find_ident(src, name).find_map(|at| {
        let line_start = src[..at].rfind('\n').map_or(0, |k| k + 1);
        let line_end = src[at..].find('\n').map_or(src.len(), |k| at + k);
        let head = &src[line_start..at];
        let rest = &src[at + name.len()..line_end];
        let starts_decl = !head.is_empty() && !head.starts_with([' ', '\t']) && head.ends_with(' ') && !head.trim_end().contains([' ', '(', '=']);
        (starts_decl && (rest.starts_with(" = ") || rest.starts_with('[') || rest.starts_with(';'))).then_some((line_start..line_end, at))
    })
}

/// Removes `layout(location = N) ` from the `in`/`out` declaration of
/// `name` (a host binds it by name then).
fn drop_location_qualifier(src: &mut String, name: &str) -> Option<()> {
    // The global declaration, not a struct member of the same name.
    let at = text::find_ident(src, name).find(|&at| {
        let line_start = src[..at].rfind('\n').map_or(0, |k| k + 1);
        let line = &src[line_start..at];
        src[at + name.len()..].starts_with(';') && (line.starts_with("layout(location = ") || line.starts_with("in ") || line.starts_with("out ") || line.starts_with("flat ") || line.starts_with("smooth "))
    })?;
    let line_start = src[..at].rfind('\n').map_or(0, |k| k + 1);
    let line = &src[line_start..at];
    if !line.starts_with("layout(location = ") {
        return Some(()); // written without one already
    }
    let close = line.find(") ")?;
    src.replace_range(line_start..line_start + close + 2, "");
    Some(())
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

/// The instance name of a block written `BLOCK { members } name;` (naga
/// writes a storage buffer whose struct ends in a run-time-sized array
/// with its members in the block), from the text that follows `BLOCK`.
fn trailing_instance(rest: &str) -> Option<&str> {
    let close = rest.find("\n}")?;
    let after = rest[close + 2..].strip_prefix(' ')?;
    let name = &after[..after.find(';')?];
    (!name.is_empty() && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')).then_some(name)
}

/// Rewrites naga's `uniform BLOCK { T instance; };` as `uniform BLOCK {
/// <T's members> } instance;`, and returns the members' names. The
/// members are copied from naga's `struct T` (which stays: other code may
/// use the type), so they have the names naga reads them by; the body
/// still reads `instance.member`.
fn inline_block_members(src: &mut String, block: &str, instance: &str) -> Option<Vec<String>> {
    let at = text::find_ident(src, block).find(|&at| src[..at].ends_with("uniform ") && src[at + block.len()..].starts_with(" { "))?;
    let open = at + block.len() + 1;
    let close = open + src[open..].find("; };")?;
    let decl = &src[open + 2..close];
    let (ty, name) = decl.split_once(' ')?;
    if name != instance {
        return None;
    }
    let head = ["struct ", ty, " {\n"].concat();
    let body_start = memchr::memmem::find_iter(src.as_bytes(), head.as_bytes()).find(|&k| k == 0 || src.as_bytes()[k - 1] == b'\n')? + head.len();
    let body_end = body_start + src[body_start..].find("\n};")? + 1;
    let body = src[body_start..body_end].to_string();
    let members = body.lines().filter_map(|l| l.trim().trim_end_matches(';').split('[').next()?.split_whitespace().last().map(str::to_string)).collect();
    src.replace_range(open..close + "; };".len(), &["{\n", &body, "} ", instance, ";"].concat());
    Some(members)
}

/// Drops naga's `smooth` from varying declarations: it is GLSL's default
/// for float varyings, and daslang's generator writes none, so a stage
/// of either links with a stage of the other (the presence of
/// interpolation qualifiers must match). `flat` stays (integers need it).
fn drop_smooth_qualifiers(src: &mut String) {
    const SMOOTH: &str = "smooth ";
    let edits: Vec<(Range<usize>, &str)> = memchr::memmem::find_iter(src.as_bytes(), SMOOTH.as_bytes())
        .filter(|&k| {
            // A global declaration: at the start of a line, or after its
            // `layout(location = N) ` (GLSL 430 / ES 3.10).
            let line = &src[src[..k].rfind('\n').map_or(0, |n| n + 1)..k];
            let rest = &src[k + SMOOTH.len()..];
            (line.is_empty() || (line.starts_with("layout(") && line.ends_with(") "))) && (rest.starts_with("in ") || rest.starts_with("out "))
        })
        .map(|k| (k..k + SMOOTH.len(), ""))
        .collect();
    text::apply_edits(src, edits);
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
    fn location_names_match_their_number_only() {
        assert!(is_location_name("_vs2fs_location1", "_vs2fs_location", 1));
        assert!(is_location_name("_vs2fs_location0", "_vs2fs_location", 0));
        assert!(is_location_name("_fs2p_location12", "_fs2p_location", 12));
        assert!(!is_location_name("_vs2fs_location10", "_vs2fs_location", 1));
        assert!(!is_location_name("_vs2fs_location01", "_vs2fs_location", 1));
        assert!(!is_location_name("_vs2fs_location1_", "_vs2fs_location", 1));
        assert!(!is_location_name("_p2vs_location1", "_vs2fs_location", 1));
        assert!(!is_location_name("_vs2fs_location", "_vs2fs_location", 0));
    }

    #[test]
    fn smooth_goes_flat_stays() {
        let mut s = "smooth out vec3 a;\nlayout(location = 1) smooth in vec2 b;\nflat out int c;\n    float smoothed = 0.0;\nvoid f() { smooth_x(); }\n".to_string();
        drop_smooth_qualifiers(&mut s);
        assert_eq!(s, "out vec3 a;\nlayout(location = 1) in vec2 b;\nflat out int c;\n    float smoothed = 0.0;\nvoid f() { smooth_x(); }\n");
    }

    #[test]
    fn blocks_get_their_structs_members() {
        let mut s = "struct Cam {\n    mat4x4 view;\n    vec4 lights[2];\n};\nlayout(std140) uniform cam_ubo { Cam cam; };\n\nvoid main() { vec4 x = cam.lights[0]; }\n".to_string();
        let members = inline_block_members(&mut s, "cam_ubo", "cam").unwrap();
        assert_eq!(members, ["view", "lights"]);
        assert!(s.contains("layout(std140) uniform cam_ubo {\n    mat4x4 view;\n    vec4 lights[2];\n} cam;\n\nvoid main()"), "{s}");
        assert!(s.starts_with("struct Cam {\n"), "the struct stays: {s}");
        assert_eq!(inline_block_members(&mut "uniform b_ubo { Cam other; };\n".to_string(), "b_ubo", "cam"), None);
    }

    #[test]
    fn es_precision_goes_after_int() {
        let s = "#version 300 es\n\nprecision highp float;\nprecision highp int;\n\nuniform highp sampler2DShadow s;\nuniform highp isampler2D t;\n";
        let mut out = s.to_string();
        add_es_precision(&mut out).unwrap();
        assert!(out.contains("precision highp int;\nprecision highp sampler2DShadow;\nprecision highp isampler2D;\n\nuniform"));
    }
}
