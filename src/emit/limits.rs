//! The minimum limits every device of a target guarantees, and what each
//! entry point (and program) uses of them, counted before anything is
//! written: a program that goes over one fails to link, or to make a
//! pipeline, on some device, so it is a compile error that names the
//! resource, the count and the limit. `--limit NAME=N` compiles for a
//! stated higher limit.
//!
//! Minimums (the GL 3.3 core and GLES 3.0 specifications' implementation
//! dependent values; WebGL2 guarantees GLES 3.0's; wgpu's `Limits::default()`,
//! WebGPU's defaults):
//!
//! | resource (`--limit` name)        | GL 3.3 | GLES 3.0 / WebGL2 | wgpu |
//! |----------------------------------|--------|-------------------|------|
//! | `vertex-attributes`              | 16     | 16                | 16   |
//! | `varyings` (vectors)             | 15     | 15                | 16   |
//! | `uniform-vectors` vertex         | 256    | 256               | -    |
//! | `uniform-vectors` fragment       | 256    | 224               | -    |
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
}

impl Limit {
    pub const ALL: [Limit; 14] = [
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
        }
    }
}

/// Which devices a count is held against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    Gl330,
    Es300,
    Wgpu,
}

impl Family {
    /// Who guarantees the minimums, as a sentence's subject and verb.
    fn promise(self) -> &'static str {
        match self {
            Family::Gl330 => "GL 3.3 core guarantees",
            Family::Es300 => "GLES 3.0 and WebGL2 guarantee",
            Family::Wgpu => "wgpu's default limits (WebGPU's) allow",
        }
    }

    fn target(self) -> &'static str {
        match self {
            Family::Gl330 => "GLSL 330",
            Family::Es300 => "GLSL ES 3.00",
            Family::Wgpu => "WGSL/SPIR-V",
        }
    }

    /// The guaranteed minimum, and the name the API gives it; `None` where
    /// the family has no such limit.
    fn minimum(self, limit: Limit, stage: naga::ShaderStage) -> Option<(u64, &'static str)> {
        use Family::*;
        use Limit::*;
        let fragment = stage == naga::ShaderStage::Fragment;
        Some(match (self, limit) {
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

/// What one entry point (or program) uses of a resource: the count, and
/// the declaration of what it uses, in order (the item past the limit is
/// where the error points).
struct Use {
    count: u64,
    items: Vec<(u64, Span, String)>,
}

impl Use {
    fn new() -> Use {
        Use { count: 0, items: Vec::new() }
    }

    fn add(&mut self, n: u64, span: Span, name: &str) {
        self.count += n;
        self.items.push((self.count, span, name.to_string()));
    }
}

/// Checks every entry point and program of `lowered` against the limits
/// of each requested target (or the stated `raised` ones), pushing an
/// error for each limit gone over.
pub fn check(lowered: &Lowered, targets: &[Target], raised: &[(Limit, u64)], diags: &mut Vec<Diagnostic>) {
    let mut families = Vec::new();
    for t in targets {
        let f = match t {
            Target::Glsl330 => Family::Gl330,
            Target::Gles300 => Family::Es300,
            Target::Wgsl | Target::Spirv => Family::Wgpu,
        };
        if !families.contains(&f) {
            families.push(f);
        }
    }
    let iface = &lowered.interface;
    for family in families {
        let mut report = |limit: Limit, stage: naga::ShaderStage, whose: &str, used: &Use| {
            let Some((minimum, api)) = family.minimum(limit, stage) else { return };
            let allowed = raised.iter().rev().find(|(l, _)| *l == limit).map_or(minimum, |&(_, n)| n);
            if used.count <= allowed {
                return;
            }
            let Some((_, span, name)) = used.items.iter().find(|(total, ..)| *total > allowed) else { return };
            let stated = if allowed == minimum { format!("the {minimum} that {} ({api})", family.promise()) } else { format!("the stated limit of {allowed}") };
            diags.push(
                Diagnostic::error(format!("{whose} uses {} {} in {}, over {stated}", used.count, limit.what(), family.target()), *span)
                    .with_label(format!("`{name}` goes over the limit"))
                    .with_note(format!("to compile for devices with more, state their limit: `--limit {}=N`", limit.name())),
            );
        };
        for ep in &iface.entry_points {
            let whose = format!("{} entry point `{}`", stage_name(ep.stage), ep.name);
            for (limit, used) in entry_uses(lowered, ep, family) {
                report(limit, ep.stage, &whose, &used);
            }
        }
        for &(v, f) in &iface.links {
            let (ve, fe) = (&iface.entry_points[v], &iface.entry_points[f]);
            let whose = format!("the program of `{}` and `{}`", ve.name, fe.name);
            for limit in [Limit::CombinedUniformBlocks, Limit::CombinedTextureUnits] {
                let mut used = Use::new();
                for ep in [ve, fe] {
                    let per = entry_uses(lowered, ep, family);
                    let single = if limit == Limit::CombinedUniformBlocks { Limit::UniformBlocks } else { Limit::TextureUnits };
                    if let Some((_, u)) = per.into_iter().find(|(l, _)| *l == single) {
                        for (_, span, name) in u.items {
                            used.add(1, span, &name);
                        }
                    }
                }
                report(limit, naga::ShaderStage::Vertex, &whose, &used);
            }
        }
    }
}

fn stage_name(stage: naga::ShaderStage) -> &'static str {
    match stage {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
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
fn entry_uses(lowered: &Lowered, ep: &EntryInterface, family: Family) -> Vec<(Limit, Use)> {
    let iface = &lowered.interface;
    let module = &lowered.gpu;
    let vertex = ep.stage == naga::ShaderStage::Vertex;
    let mut out = Vec::new();
    let io = |vars: &[crate::lower::IoVar]| {
        let mut u = Use::new();
        for v in vars {
            u.add(vectors(module, v.ty), v.span, &v.name);
        }
        u
    };
    if vertex {
        out.push((Limit::VertexAttributes, io(&ep.inputs)));
        out.push((Limit::Varyings, io(&ep.outputs)));
    } else {
        out.push((Limit::Varyings, io(&ep.inputs)));
        out.push((Limit::ColorOutputs, io(&ep.outputs)));
    }
    let gl = family != Family::Wgpu;
    let blocks_in_gl = iface.gl_uniforms == GlUniforms::Blocks;
    let (mut blocks, mut block_size, mut buffers, mut buffer_size) = (Use::new(), Use::new(), Use::new(), Use::new());
    let (mut textures, mut samplers, mut groups) = (Use::new(), Use::new(), Use::new());
    let mut max_group: Option<u32> = None;
    for &ri in &ep.resources {
        let Some(r) = iface.resources.get(ri) else { continue };
        if max_group.is_none_or(|g| r.group > g) {
            max_group = Some(r.group);
            groups = Use::new();
            groups.add(r.group as u64 + 1, r.span, &r.name);
        }
        match &r.kind {
            ResourceKind::Uniform { ty, loose, .. } => {
                let size = buffer_bytes(module, *ty);
                if gl && (!*loose || blocks_in_gl) {
                    blocks.add(1, r.span, &r.name);
                    if size > block_size.count {
                        block_size = Use::new();
                        block_size.add(size, r.span, &r.name);
                    }
                } else if !gl {
                    buffers.add(1, r.span, &r.name);
                    if size > buffer_size.count {
                        buffer_size = Use::new();
                        buffer_size.add(size, r.span, &r.name);
                    }
                }
            }
            ResourceKind::Sampler(_) => {
                textures.add(1, r.span, &r.name);
                samplers.add(1, r.span, &r.name);
            }
        }
    }
    if gl {
        let mut vectors_used = Use::new();
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
    fn limit_names_round_trip() {
        for l in Limit::ALL {
            assert_eq!(Limit::from_name(l.name()), Some(l));
        }
        assert_eq!(Limit::from_name("uniform-blocks"), Some(Limit::UniformBlocks));
        assert_eq!(Limit::from_name("nope"), None);
    }
}
