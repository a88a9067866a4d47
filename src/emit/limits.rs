//! The limits of each target's devices, and what each entry point (and
//! program) uses of them, counted before anything is written. Two numbers
//! per limit: the specification's guaranteed minimum, and, where the
//! devices still in use report more, the least they report (`Reported`,
//! each with its source in docs/targets.md, "Device limits"). Over what
//! devices report, a program fails to link or to make a pipeline: an error
//! naming the resource, the count and the limit. Over the guarantee only, a
//! warning naming the guarantee and who cannot run it; `--strict-limits`
//! (`Options::strict_limits`) makes it an error. `--limit NAME=N` compiles
//! for a stated limit instead of both.
//!
//! Guaranteed minimums (the GL 3.3 core and GLES 3.0 specifications'
//! implementation dependent values; WebGL2 guarantees GLES 3.0's; wgpu's
//! `Limits::default()`, WebGPU's defaults, which a device created with
//! defaults enforces, so they are errors):
//!
//! | resource (`--limit` name)        | GL 3.3 | GLES 3.0 / WebGL2 | wgpu |
//! |----------------------------------|--------|-------------------|------|
//! | `vertex-attributes`              | 16     | 16                | 16   |
//! | `varyings` (vectors)             | 15     | 15                | 16   |
//! | `uniform-vectors` vertex         | 256 (1024 reported) | 256  | -    |
//! | `uniform-vectors` fragment       | 256 (1024 reported) | 224  | -    |
//! | `uniform-blocks` per stage       | 12     | 12                | -    |
//! | `combined-uniform-blocks`        | 24     | 24                | -    |
//! | `uniform-block-size` (bytes)     | 16384  | 16384             | -    |
//! | `texture-units` per stage        | 16     | 16                | -    |
//! | `combined-texture-units`         | 48     | 32                | -    |
//! | `color-outputs`                  | 8      | 4                 | 8    |
//! | `uniform-buffers` per stage      | -      | -                 | 12   |
//! | `uniform-buffer-size` (bytes)    | -      | -                 | 65536|
//! | `sampled-textures` per stage     | -      | -                 | 16   |
//! | `samplers` per stage             | -      | -                 | 16   |
//! | `bind-groups`                    | -      | -                 | 4    |
//!
//! Compute, storage buffers and images (GL 4.3 core and GLES 3.1
//! specifications' minimums; `-`: no such limit on that family):
//!
//! | resource (`--limit` name)        | GL 4.3 | GLES 3.1 | wgpu |
//! |----------------------------------|--------|----------|------|
//! | `workgroup-size-x`               | 1024   | 128      | 256  |
//! | `workgroup-size-y`               | 1024   | 128      | 256  |
//! | `workgroup-size-z`               | 64     | 64       | 64   |
//! | `workgroup-invocations`          | 1024   | 128      | 256  |
//! | `workgroup-storage` (bytes)      | 32768  | 16384    | 16384|
//! | `storage-buffers` compute        | 8      | 4        | 8    |
//! | `storage-buffers` fragment       | 8      | 0        | 8    |
//! | `storage-buffers` vertex         | 0      | 0        | 8    |
//! | `storage-images` compute         | 8      | 4        | 4    |
//! | `storage-images` fragment        | 8      | 0        | 4    |
//! | `storage-images` vertex          | 0      | 0        | 4    |
//!
//! GL 4.3 and GLES 3.1 also run the vertex and fragment programs within
//! the GL 3.3 / GLES 3.0 rows above (their minimums are no lower).
//!
//! GL 3.3 states uniforms and varyings in components (1024 per stage, 60
//! varying components); they are counted here as GLES 3.0 does, in
//! 4-component vectors (each scalar, vector, matrix column and array
//! element taking one), which is how drivers allocate them at worst.

use crate::diag::Diagnostic;
use crate::lower::{EntryInterface, GlUniforms, Lowered, ResourceKind};
use crate::source::Span;
use crate::target::Target;

/// A resource whose use is limited, by its `--limit` name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Limit {
    VertexAttributes,
    Varyings,
    UniformVectors,
    UniformBlocks,
    CombinedUniformBlocks,
    UniformBlockSize,
    TextureUnits,
    CombinedTextureUnits,
    ColorOutputs,
    UniformBuffers,
    UniformBufferSize,
    SampledTextures,
    Samplers,
    BindGroups,
    WorkgroupSizeX,
    WorkgroupSizeY,
    WorkgroupSizeZ,
    WorkgroupInvocations,
    WorkgroupStorage,
    StorageBuffers,
    StorageImages,
}

impl Limit {
    pub const ALL: [Limit; 21] = [
        Limit::WorkgroupSizeX,
        Limit::WorkgroupSizeY,
        Limit::WorkgroupSizeZ,
        Limit::WorkgroupInvocations,
        Limit::WorkgroupStorage,
        Limit::StorageBuffers,
        Limit::StorageImages,
        Limit::VertexAttributes,
        Limit::Varyings,
        Limit::UniformVectors,
        Limit::UniformBlocks,
        Limit::CombinedUniformBlocks,
        Limit::UniformBlockSize,
        Limit::TextureUnits,
        Limit::CombinedTextureUnits,
        Limit::ColorOutputs,
        Limit::UniformBuffers,
        Limit::UniformBufferSize,
        Limit::SampledTextures,
        Limit::Samplers,
        Limit::BindGroups,
    ];

    /// The `--limit` name.
    pub fn name(self) -> &'static str {
        match self {
            Limit::VertexAttributes => "vertex-attributes",
            Limit::Varyings => "varyings",
            Limit::UniformVectors => "uniform-vectors",
            Limit::UniformBlocks => "uniform-blocks",
            Limit::CombinedUniformBlocks => "combined-uniform-blocks",
            Limit::UniformBlockSize => "uniform-block-size",
            Limit::TextureUnits => "texture-units",
            Limit::CombinedTextureUnits => "combined-texture-units",
            Limit::ColorOutputs => "color-outputs",
            Limit::UniformBuffers => "uniform-buffers",
            Limit::UniformBufferSize => "uniform-buffer-size",
            Limit::SampledTextures => "sampled-textures",
            Limit::Samplers => "samplers",
            Limit::BindGroups => "bind-groups",
            Limit::WorkgroupSizeX => "workgroup-size-x",
            Limit::WorkgroupSizeY => "workgroup-size-y",
            Limit::WorkgroupSizeZ => "workgroup-size-z",
            Limit::WorkgroupInvocations => "workgroup-invocations",
            Limit::WorkgroupStorage => "workgroup-storage",
            Limit::StorageBuffers => "storage-buffers",
            Limit::StorageImages => "storage-images",
        }
    }

    pub fn from_name(name: &str) -> Option<Limit> {
        Limit::ALL.into_iter().find(|l| l.name() == name)
    }

    /// What is counted, for messages.
    fn what(self) -> &'static str {
        match self {
            Limit::VertexAttributes => "vertex attribute locations",
            Limit::Varyings => "varying vectors",
            Limit::UniformVectors => "uniform vectors",
            Limit::UniformBlocks => "uniform blocks",
            Limit::CombinedUniformBlocks => "uniform blocks in its two stages",
            Limit::UniformBlockSize => "bytes in one uniform block",
            Limit::TextureUnits => "texture units",
            Limit::CombinedTextureUnits => "texture units in its two stages",
            Limit::ColorOutputs => "colour outputs",
            Limit::UniformBuffers => "uniform buffers",
            Limit::UniformBufferSize => "bytes in one uniform buffer",
            Limit::SampledTextures => "sampled textures",
            Limit::Samplers => "samplers",
            Limit::BindGroups => "bind groups",
            Limit::WorkgroupSizeX => "invocations along x in a workgroup",
            Limit::WorkgroupSizeY => "invocations along y in a workgroup",
            Limit::WorkgroupSizeZ => "invocations along z in a workgroup",
            Limit::WorkgroupInvocations => "invocations in a workgroup",
            Limit::WorkgroupStorage => "bytes of workgroup memory",
            Limit::StorageBuffers => "storage buffers",
            Limit::StorageImages => "storage images",
        }
    }
}

/// Which devices a count is held against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    Gl330,
    Es300,
    Gl430,
    Es310,
    Wgpu,
}

impl Family {
    /// Who guarantees the minimums, as a sentence's subject and verb.
    fn promise(self) -> &'static str {
        match self {
            Family::Gl330 => "GL 3.3 core guarantees",
            Family::Es300 => "GLES 3.0 and WebGL2 guarantee",
            Family::Gl430 => "GL 4.3 core guarantees",
            Family::Es310 => "GLES 3.1 guarantees",
            Family::Wgpu => "wgpu's default limits (WebGPU's) allow",
        }
    }

    fn target(self) -> &'static str {
        match self {
            Family::Gl330 => "GLSL 330",
            Family::Es300 => "GLSL ES 3.00",
            Family::Gl430 => "GLSL 430",
            Family::Es310 => "GLSL ES 3.10",
            Family::Wgpu => "WGSL/SPIR-V",
        }
    }

    /// The guaranteed minimum, and the name the API gives it; `None` where
    /// the family has no such limit.
    fn minimum(self, limit: Limit, stage: naga::ShaderStage) -> Option<(u64, &'static str)> {
        use Family::*;
        use Limit::*;
        let fragment = stage == naga::ShaderStage::Fragment;
        let compute = stage == naga::ShaderStage::Compute;
        // GL 4.3 / GLES 3.1 run vertex and fragment programs within the
        // GL 3.3 / GLES 3.0 minimums.
        let classic = match self {
            Gl430 => Gl330,
            Es310 => Es300,
            f => f,
        };
        Some(match (self, limit) {
            (Gl430, WorkgroupSizeX) => (1024, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[0]"),
            (Gl430, WorkgroupSizeY) => (1024, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[1]"),
            (Gl430 | Es310, WorkgroupSizeZ) => (64, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[2]"),
            (Gl430, WorkgroupInvocations) => (1024, "GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS"),
            (Gl430, WorkgroupStorage) => (32768, "GL_MAX_COMPUTE_SHARED_MEMORY_SIZE"),
            (Es310, WorkgroupSizeX) => (128, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[0]"),
            (Es310, WorkgroupSizeY) => (128, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[1]"),
            (Es310, WorkgroupInvocations) => (128, "GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS"),
            (Es310, WorkgroupStorage) => (16384, "GL_MAX_COMPUTE_SHARED_MEMORY_SIZE"),
            (Wgpu, WorkgroupSizeX) => (256, "max_compute_workgroup_size_x"),
            (Wgpu, WorkgroupSizeY) => (256, "max_compute_workgroup_size_y"),
            (Wgpu, WorkgroupSizeZ) => (64, "max_compute_workgroup_size_z"),
            (Wgpu, WorkgroupInvocations) => (256, "max_compute_invocations_per_workgroup"),
            (Wgpu, WorkgroupStorage) => (16384, "max_compute_workgroup_storage_size"),
            (Gl430, StorageBuffers) if compute => (8, "GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS"),
            (Gl430, StorageBuffers) if fragment => (8, "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS"),
            (Gl430, StorageBuffers) => (0, "GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS"),
            (Es310, StorageBuffers) if compute => (4, "GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS"),
            (Es310, StorageBuffers) if fragment => (0, "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS"),
            (Es310, StorageBuffers) => (0, "GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS"),
            (Wgpu, StorageBuffers) => (8, "max_storage_buffers_per_shader_stage"),
            (Gl430, StorageImages) if compute => (8, "GL_MAX_COMPUTE_IMAGE_UNIFORMS"),
            (Gl430, StorageImages) if fragment => (8, "GL_MAX_FRAGMENT_IMAGE_UNIFORMS"),
            (Gl430, StorageImages) => (0, "GL_MAX_VERTEX_IMAGE_UNIFORMS"),
            (Es310, StorageImages) if compute => (4, "GL_MAX_COMPUTE_IMAGE_UNIFORMS"),
            (Es310, StorageImages) if fragment => (0, "GL_MAX_FRAGMENT_IMAGE_UNIFORMS"),
            (Es310, StorageImages) => (0, "GL_MAX_VERTEX_IMAGE_UNIFORMS"),
            (Wgpu, StorageImages) => (4, "max_storage_textures_per_shader_stage"),
            (Gl430 | Es310, _) => return classic.minimum(limit, stage),
            (Gl330 | Es300, VertexAttributes) => (16, "GL_MAX_VERTEX_ATTRIBS"),
            (Wgpu, VertexAttributes) => (16, "max_vertex_attributes"),
            (Gl330, Varyings) => (15, "GL_MAX_VARYING_COMPONENTS / 4"),
            (Es300, Varyings) => (15, "GL_MAX_VARYING_VECTORS"),
            (Wgpu, Varyings) => (16, "max_inter_stage_shader_variables"),
            (Gl330, UniformVectors) if fragment => (256, "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS / 4"),
            (Gl330, UniformVectors) => (256, "GL_MAX_VERTEX_UNIFORM_COMPONENTS / 4"),
            (Es300, UniformVectors) if fragment => (224, "GL_MAX_FRAGMENT_UNIFORM_VECTORS"),
            (Es300, UniformVectors) => (256, "GL_MAX_VERTEX_UNIFORM_VECTORS"),
            (Gl330 | Es300, UniformBlocks) if fragment => (12, "GL_MAX_FRAGMENT_UNIFORM_BLOCKS"),
            (Gl330 | Es300, UniformBlocks) => (12, "GL_MAX_VERTEX_UNIFORM_BLOCKS"),
            (Gl330 | Es300, CombinedUniformBlocks) => (24, "GL_MAX_COMBINED_UNIFORM_BLOCKS"),
            (Gl330 | Es300, UniformBlockSize) => (16384, "GL_MAX_UNIFORM_BLOCK_SIZE"),
            (Gl330 | Es300, TextureUnits) if fragment => (16, "GL_MAX_TEXTURE_IMAGE_UNITS"),
            (Gl330 | Es300, TextureUnits) => (16, "GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS"),
            (Gl330, CombinedTextureUnits) => (48, "GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS"),
            (Es300, CombinedTextureUnits) => (32, "GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS"),
            (Gl330, ColorOutputs) => (8, "GL_MAX_DRAW_BUFFERS"),
            (Es300, ColorOutputs) => (4, "GL_MAX_DRAW_BUFFERS"),
            (Wgpu, ColorOutputs) => (8, "max_color_attachments"),
            (Wgpu, UniformBuffers) => (12, "max_uniform_buffers_per_shader_stage"),
            (Wgpu, UniformBufferSize) => (65536, "max_uniform_buffer_binding_size"),
            (Wgpu, SampledTextures) => (16, "max_sampled_textures_per_shader_stage"),
            (Wgpu, Samplers) => (16, "max_samplers_per_shader_stage"),
            (Wgpu, BindGroups) => (4, "max_bind_groups"),
            _ => return None,
        })
    }
}

/// Where the devices of a family still in use all report more than the
/// guarantee: the least they report, and who, for messages (sources in
/// docs/targets.md, "Device limits").
#[derive(Clone, Copy)]
struct Reported {
    n: u64,
    /// "the N that ..." in an error over it.
    who: &'static str,
    /// What a warning over the guarantee says of the devices it excludes.
    excluded: &'static str,
}

impl Family {
    /// What the devices in use report, where it is more than the guarantee
    /// (`None`: the guarantee is what some device in use has).
    fn reported(self, limit: Limit, stage: naga::ShaderStage) -> Option<Reported> {
        match (self, limit, stage) {
            // NVIDIA (down to its 340 legacy driver) and Apple's macOS driver
            // report 4096 components a stage, Mesa 16384; none reports 1024.
            (Family::Gl330 | Family::Gl430, Limit::UniformVectors, naga::ShaderStage::Vertex | naga::ShaderStage::Fragment) => Some(Reported {
                n: 1024,
                who: "GL 3.3 drivers in use report (4096 components on NVIDIA and Apple's macOS driver, 16384 on Mesa)",
                excluded: "only a GL driver that reports the bare minimum of 1024 components cannot run it; NVIDIA and Apple's macOS driver report 4096, Mesa 16384",
            }),
            _ => None,
        }
    }

    /// Why a guarantee is also the error, where a device in use has only it.
    fn hard_note(self, limit: Limit, stage: naga::ShaderStage) -> Option<&'static str> {
        match (self, limit, stage) {
            (Family::Es300 | Family::Es310, Limit::UniformVectors, naga::ShaderStage::Vertex) => {
                Some("Qualcomm Adreno GPUs report exactly 256 (GLES and WebGL2 on Android): the program fails to link there")
            }
            (Family::Wgpu, ..) => Some("a WebGPU device created with default limits refuses the pipeline; compiled with `--limit`, the manifest's `required_limits` says what the host must request"),
            _ => None,
        }
    }
}

/// What one entry point (or program) uses of a resource: the count, and
/// (when `items` is kept) the declaration of what it uses, in order, with
/// the running count: the item past the limit is where the error points.
/// Items are only kept when counting again for an error: every compile
/// counts, and almost none goes over.
#[derive(Default)]
struct Use<'a> {
    /// What is needed: the sum of what is added, or for locations, the
    /// highest location used + 1 where that is more.
    count: u64,
    sum: u64,
    items: Option<Vec<(u64, Span, &'a str)>>,
}

impl<'a> Use<'a> {
    fn new(keep_items: bool) -> Use<'a> {
        Use { count: 0, sum: 0, items: keep_items.then(Vec::new) }
    }

    fn add(&mut self, n: u64, span: Span, name: &'a str) {
        self.sum += n;
        self.count = self.count.max(self.sum);
        if let Some(items) = &mut self.items {
            items.push((self.count, span, name));
        }
    }

    /// Adds `n` locations from `location` on: a location past the limit
    /// does not exist on a device with the minimum, however few are used
    /// (`@location = 16` is the 17th vertex attribute location).
    fn add_at(&mut self, n: u64, location: u32, span: Span, name: &'a str) {
        self.count = self.count.max(location as u64 + n);
        self.add(n, span, name);
    }
}

/// Checks every entry point and program of `lowered` against the limits
/// of each requested target (or the stated `raised` ones), pushing an
/// error for each limit gone over that devices report, and a warning (an
/// error if `strict`) for each guarantee gone over within that.
pub fn check<'a>(lowered: &'a Lowered, targets: &[Target], raised: &[(Limit, u64)], strict: bool, diags: &mut Vec<Diagnostic>) {
    let mut families = Vec::new();
    for t in targets {
        let f = match t {
            Target::Glsl330 => Family::Gl330,
            Target::Gles300 => Family::Es300,
            Target::Glsl430 => Family::Gl430,
            Target::Gles310 => Family::Es310,
            Target::Wgsl | Target::Spirv => Family::Wgpu,
        };
        if !families.contains(&f) {
            families.push(f);
        }
    }
    let iface = &lowered.interface;
    let (mut gl_uses, mut wgpu_uses): (Option<Vec<Vec<(Limit, Use)>>>, Option<Vec<Vec<(Limit, Use)>>>) = (None, None);
    for family in families {
        // `whose` names the entry point or program; it is only formatted
        // for an error (this runs for every compile).
        // `itemised` counts again, keeping the items, for the error.
        let mut report = |limit: Limit, stage: naga::ShaderStage, whose: &dyn Fn() -> String, used: &Use, itemised: &dyn Fn() -> Use<'a>| {
            let Some((minimum, api)) = family.minimum(limit, stage) else { return };
            let stated = raised.iter().rev().find(|(l, _)| *l == limit).map(|&(_, n)| n);
            // A stated limit replaces both numbers; strict keeps the guarantee.
            let reported = family.reported(limit, stage).filter(|r| stated.is_none() && !strict && r.n > minimum);
            let guaranteed = stated.unwrap_or(minimum);
            if used.count <= guaranteed {
                return;
            }
            let error = reported.is_none_or(|r| used.count > r.n);
            let allowed = match reported {
                Some(r) if error => r.n,
                _ => guaranteed,
            };
            let used = itemised();
            let Some(&(_, span, name)) = used.items.iter().flatten().find(|(total, ..)| *total > allowed) else { return };
            let over = match (stated, reported) {
                (Some(n), _) => format!("the stated limit of {n}"),
                (None, Some(r)) if error => format!("the {} that {}", r.n, r.who),
                _ => format!("the {minimum} that {} ({api})", family.promise()),
            };
            let message = format!("{} uses {} {} in {}, over {over}", whose(), used.count, limit.what(), family.target());
            let mut d = match error {
                true => Diagnostic::error(message, span).with_label(format!("`{name}` goes over the limit")),
                false => Diagnostic::warning(message, span).with_label(format!("`{name}` goes past the guarantee")),
            };
            if used.count > used.sum {
                // Fewer are used than the limit: a location is past it.
                d = d.with_note(format!("locations count from 0: with {allowed}, the last is {}", allowed.saturating_sub(1)));
            }
            if let Some(r) = reported.filter(|_| !error) {
                d = d.with_note(r.excluded).with_note("`--strict-limits` makes this an error");
            } else if let Some(r) = family.reported(limit, stage).filter(|_| strict && stated.is_none()) {
                d = d.with_note(format!("an error because of `--strict-limits`: without it, a warning up to the {} that {}", r.n, r.who));
            } else if let Some(why) = family.hard_note(limit, stage).filter(|_| stated.is_none()) {
                d = d.with_note(why);
            }
            diags.push(d.with_note(format!("to compile for devices with more, state their limit: `--limit {}=N`", limit.name())));
        };
        // What an entry point uses depends only on whether the family is
        // GL's: counted once for GLSL 330 and ES 3.00 together.
        let gl = family != Family::Wgpu;
        let counted = if gl { &mut gl_uses } else { &mut wgpu_uses };
        let per_entry: &Vec<Vec<(Limit, Use)>> = counted.get_or_insert_with(|| iface.entry_points.iter().map(|ep| entry_uses(lowered, ep, family, false)).collect());
        let itemised = |ep: &'a EntryInterface, limit: Limit| {
            entry_uses(lowered, ep, family, true).into_iter().find(|(l, _)| *l == limit).map(|(_, u)| u).unwrap_or_default()
        };
        for (ep, uses) in iface.entry_points.iter().zip(per_entry) {
            let whose = || format!("{} entry point `{}`", stage_name(ep.stage), ep.name);
            for (limit, used) in uses {
                report(*limit, ep.stage, &whose, used, &|| itemised(ep, *limit));
            }
        }
        for &(v, f) in &iface.links {
            let (ve, fe) = (&iface.entry_points[v], &iface.entry_points[f]);
            let whose = || format!("the program of `{}` and `{}`", ve.name, fe.name);
            for (limit, single) in [(Limit::CombinedUniformBlocks, Limit::UniformBlocks), (Limit::CombinedTextureUnits, Limit::TextureUnits)] {
                // Each of the stage's blocks or units counts one.
                let count = |i: usize| per_entry[i].iter().find(|(l, _)| *l == single).map_or(0, |(_, u)| u.count);
                let used = Use { count: count(v) + count(f), ..Use::default() };
                let both = || {
                    let mut used = Use::new(true);
                    for ep in [ve, fe] {
                        for (_, span, name) in itemised(ep, single).items.into_iter().flatten() {
                            used.add(1, span, name);
                        }
                    }
                    used
                };
                report(limit, naga::ShaderStage::Vertex, &whose, &used, &both);
            }
        }
    }
}

/// What the WGSL/SPIR-V program needs above WebGPU's default limits, by
/// their `requiredLimits` names (`maxUniformBuffersPerShaderStage`), the
/// most any entry point needs; `None` when the defaults hold it. Only a
/// program compiled with `--limit` gets here needing more: the manifest
/// says what a host must request, as a default device refuses it.
pub fn webgpu_requirements(lowered: &Lowered) -> Option<std::collections::BTreeMap<String, u64>> {
    let mut needs = std::collections::BTreeMap::new();
    for ep in &lowered.interface.entry_points {
        for (limit, used) in entry_uses(lowered, ep, Family::Wgpu, false) {
            let Some((minimum, api)) = Family::Wgpu.minimum(limit, ep.stage) else { continue };
            if used.count > minimum {
                let n = needs.entry(camel_case(api)).or_insert(0);
                *n = used.count.max(*n);
            }
        }
    }
    (!needs.is_empty()).then_some(needs)
}

/// wgpu's `Limits` field name as WebGPU spells it: `max_bind_groups` ->
/// `maxBindGroups`.
fn camel_case(snake: &str) -> String {
    let mut out = String::with_capacity(snake.len());
    let mut upper = false;
    for c in snake.chars() {
        match c {
            '_' => upper = true,
            c if upper => {
                out.push(c.to_ascii_uppercase());
                upper = false;
            }
            c => out.push(c),
        }
    }
    out
}

fn stage_name(stage: naga::ShaderStage) -> &'static str {
    match stage {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Mesh => "mesh",
        naga::ShaderStage::Task => "task",
        _ => "compute",
    }
}

/// Locations (or vectors) a value of type `ty` of the GPU module takes:
/// one per scalar, vector, matrix column and array element.
fn vectors(module: &naga::Module, ty: naga::Handle<naga::Type>) -> u64 {
    match &module.types[ty].inner {
        naga::TypeInner::Matrix { columns, .. } => *columns as u64,
        naga::TypeInner::Array { base, size: naga::ArraySize::Constant(n), .. } => n.get() as u64 * vectors(module, *base),
        naga::TypeInner::Struct { members, .. } => members.iter().map(|m| vectors(module, m.ty)).sum(),
        _ => 1,
    }
}

/// What entry point `ep` uses of each limited resource on `family`.
fn entry_uses<'a>(lowered: &'a Lowered, ep: &'a EntryInterface, family: Family, keep_items: bool) -> Vec<(Limit, Use<'a>)> {
    let iface = &lowered.interface;
    let module = &lowered.gpu;
    let vertex = ep.stage == naga::ShaderStage::Vertex;
    // At most 13 limits apply to an entry point.
    let mut out = Vec::with_capacity(13);
    let new = || Use::new(keep_items);
    let gl = family != Family::Wgpu;
    // A location is a limit where it is declared: vertex attributes and
    // colour outputs everywhere, varyings in WGSL/SPIR-V (GL matches
    // them by name). One assigned is never past the count.
    let io = |vars: &'a [crate::lower::IoVar], located: bool| {
        let mut u = new();
        for v in vars {
            match located && (v.explicit_location || !gl) {
                true => u.add_at(vectors(module, v.ty), v.location, v.span, &v.name),
                false => u.add(vectors(module, v.ty), v.span, &v.name),
            }
        }
        u
    };
    if vertex {
        out.push((Limit::VertexAttributes, io(&ep.inputs, true)));
        out.push((Limit::Varyings, io(&ep.outputs, !gl)));
    } else {
        out.push((Limit::Varyings, io(&ep.inputs, !gl)));
        out.push((Limit::ColorOutputs, io(&ep.outputs, true)));
    }
    let blocks_in_gl = iface.gl_uniforms == GlUniforms::Blocks;
    let (mut blocks, mut block_size, mut buffers, mut buffer_size) = (new(), new(), new(), new());
    let (mut textures, mut samplers, mut groups) = (new(), new(), new());
    let (mut storage_buffers, mut storage_images) = (new(), new());
    let mut max_group: Option<u32> = None;
    for &ri in &ep.resources {
        let Some(r) = iface.resources.get(ri) else { continue };
        if max_group.is_none_or(|g| r.group > g) {
            max_group = Some(r.group);
            groups = new();
            groups.add(r.group as u64 + 1, r.span, &r.name);
        }
        match &r.kind {
            ResourceKind::Uniform { ty, loose, .. } => {
                let size = buffer_bytes(module, *ty);
                if gl && (!*loose || blocks_in_gl) {
                    blocks.add(1, r.span, &r.name);
                    if size > block_size.count {
                        block_size = new();
                        block_size.add(size, r.span, &r.name);
                    }
                } else if !gl {
                    buffers.add(1, r.span, &r.name);
                    if size > buffer_size.count {
                        buffer_size = new();
                        buffer_size.add(size, r.span, &r.name);
                    }
                }
            }
            ResourceKind::Sampler(_) => {
                let n = u64::from(r.count.unwrap_or(1));
                textures.add(n, r.span, &r.name);
                samplers.add(n, r.span, &r.name);
            }
            ResourceKind::Storage { .. } => storage_buffers.add(1, r.span, &r.name),
            ResourceKind::Image { .. } => storage_images.add(1, r.span, &r.name),
        }
    }
    out.push((Limit::StorageBuffers, storage_buffers));
    out.push((Limit::StorageImages, storage_images));
    if ep.stage == naga::ShaderStage::Compute {
        let [x, y, z] = ep.workgroup_size;
        for (limit, n) in [(Limit::WorkgroupSizeX, x), (Limit::WorkgroupSizeY, y), (Limit::WorkgroupSizeZ, z)] {
            let mut u = new();
            u.add(n as u64, ep.span, &ep.name);
            out.push((limit, u));
        }
        let mut u = new();
        u.add(x as u64 * y as u64 * z as u64, ep.span, &ep.name);
        out.push((Limit::WorkgroupInvocations, u));
        let mut layouter = naga::proc::Layouter::default();
        let mut shared = new();
        if layouter.update(module.to_ctx()).is_ok() {
            for (name, span) in &ep.workgroup {
                if let Some((_, g)) = module.global_variables.iter().find(|(_, g)| g.space == naga::AddressSpace::WorkGroup && g.name.as_deref() == Some(name)) {
                    shared.add(layouter[g.ty].size as u64, *span, name);
                }
            }
        }
        out.push((Limit::WorkgroupStorage, shared));
    }
    if gl {
        let mut vectors_used = new();
        if !blocks_in_gl {
            for &u in &ep.loose {
                if let Some(l) = iface.loose.get(u) {
                    vectors_used.add(vectors(module, l.value_ty), l.span, &l.name);
                }
            }
        }
        out.push((Limit::UniformVectors, vectors_used));
        out.push((Limit::UniformBlocks, blocks));
        out.push((Limit::UniformBlockSize, block_size));
        out.push((Limit::TextureUnits, textures));
    } else {
        out.push((Limit::UniformBuffers, buffers));
        out.push((Limit::UniformBufferSize, buffer_size));
        out.push((Limit::SampledTextures, textures));
        out.push((Limit::Samplers, samplers));
        out.push((Limit::BindGroups, groups));
    }
    out
}

/// The size of a uniform buffer's struct, rounded up to 16.
fn buffer_bytes(module: &naga::Module, ty: naga::Handle<naga::Type>) -> u64 {
    let size = match &module.types[ty].inner {
        naga::TypeInner::Struct { span, .. } => *span as u64,
        _ => 16,
    };
    size.div_ceil(16) * 16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn webgpu_names() {
        assert_eq!(camel_case("max_uniform_buffers_per_shader_stage"), "maxUniformBuffersPerShaderStage");
        assert_eq!(camel_case("max_compute_workgroup_size_x"), "maxComputeWorkgroupSizeX");
    }

    #[test]
    fn limit_names_round_trip() {
        for l in Limit::ALL {
            assert_eq!(Limit::from_name(l.name()), Some(l));
        }
        assert_eq!(Limit::from_name("uniform-blocks"), Some(Limit::UniformBlocks));
        assert_eq!(Limit::from_name("nope"), None);
    }
}
