//! A frame described once, for every consumer: the render targets, the
//! passes (which program, which attachments, the fixed-function state,
//! which textures each sampler reads), the draws with their uniform values
//! by name, and the target read back. A plan says nothing about bindings,
//! offsets or locations: those come from the program's manifest (or, for a
//! by-name GL host, from the linked program) through [`super::bind`], and
//! the executors in [`super::exec`] run it.
//!
//! The scenes that build plans: [`tutorial`] (the tutorial's shadow scene),
//! [`super::techniques`] (the technique scenes) and [`checks`] (one
//! fullscreen triangle into an integer target, for self-checking programs).

pub mod checks;
pub mod compute;
pub mod meshes;
pub mod scene_file;
pub mod tutorial;
pub mod vk_shadow;
pub mod vk_tutorials;
mod value;

pub use value::{Scalar, Shape, Value, Values};

/// Index of a target in [`FramePlan::targets`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TargetId(pub usize);

/// The texel format of a render target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// 8-bit UNORM colour, not sRGB.
    Rgba8,
    /// Four 32-bit unsigned integers per texel.
    Rgba32Uint,
    Depth16,
    Depth24Plus,
    Depth32Float,
}

impl Format {
    pub fn is_depth(self) -> bool {
        matches!(self, Format::Depth16 | Format::Depth24Plus | Format::Depth32Float)
    }

    pub fn name(self) -> &'static str {
        match self {
            Format::Rgba8 => "rgba8",
            Format::Rgba32Uint => "rgba32uint",
            Format::Depth16 => "depth16",
            Format::Depth24Plus => "depth24plus",
            Format::Depth32Float => "depth32float",
        }
    }
}

/// A 2D texture the frame renders into (and may sample later).
#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    /// Names it in messages.
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub format: Format,
    /// Texels it starts with (`Rgba8` rows, top row first; layers one
    /// after another): a texture the host uploads, such as the stand-in
    /// images of [`vk_shadow`].
    pub contents: Option<Vec<u8>>,
    /// What a sampler sees of it; only an uploaded `Rgba8` texture is
    /// other than [`Dim::D2`].
    pub dim: Dim,
}

/// A texture's kind (a sampler's `dimension`), with its layer count.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Dim {
    #[default]
    D2,
    /// Six square faces: +x, -x, +y, -y, +z, -z.
    Cube,
    /// This many slices.
    D3(u32),
    /// This many layers.
    D2Array(u32),
}

impl Dim {
    /// Layers (faces, slices) its contents hold.
    pub fn layers(self) -> u32 {
        match self {
            Dim::D2 => 1,
            Dim::Cube => 6,
            Dim::D3(n) | Dim::D2Array(n) => n,
        }
    }

    /// The manifest's name of a sampler's dimension.
    pub fn name(self) -> &'static str {
        match self {
            Dim::D2 => "2d",
            Dim::Cube => "cube",
            Dim::D3(_) => "3d",
            Dim::D2Array(_) => "2d-array",
        }
    }
}

/// Which faces are culled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Cull {
    #[default]
    None,
    Front,
    Back,
}

/// How a sampler reads a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sampling {
    /// A depth compare (`LEQUAL`: 1 where the reference is at most the
    /// stored depth).
    pub compare: bool,
    /// Linear filtering (with `compare`: the hardware's 2x2 PCF).
    pub linear: bool,
    /// Clamp to a white (depth 1) border instead of the edge texels, where
    /// the consumer has it (the others clamp to the edge).
    pub border: bool,
    /// Repeat outside 0..1 (a scene's pattern or image texture, as GL's
    /// default wrap and the preview page do); `border` and edge otherwise.
    pub repeat: bool,
}

impl Sampling {
    /// The tutorial's shadow lookup: linear compare, clamped to the edge.
    pub const SHADOW: Sampling = Sampling { compare: true, linear: true, border: false, repeat: false };
    /// Plain texel reads, clamped to the edge.
    pub const NEAREST: Sampling = Sampling { compare: false, linear: false, border: false, repeat: false };
}

/// A target a pass samples: the program's sampler `sampler` (its DSL name;
/// an element of a sampler array is `name[i]`) reads `target`.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureInput {
    pub sampler: String,
    pub target: TargetId,
    pub sampling: Sampling,
}

/// A colour attachment cleared to a colour, or a depth attachment cleared
/// to a depth. Both are stored.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attachment<C> {
    pub target: TargetId,
    pub clear: C,
}

/// A vertex attribute's format in a mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VertexFormat {
    Float32,
    Float32x2,
    Float32x3,
    Float32x4,
}

impl VertexFormat {
    /// wgpu's (and the manifest's `vertex_format`) name.
    pub fn name(self) -> &'static str {
        match self {
            VertexFormat::Float32 => "Float32",
            VertexFormat::Float32x2 => "Float32x2",
            VertexFormat::Float32x3 => "Float32x3",
            VertexFormat::Float32x4 => "Float32x4",
        }
    }

    pub fn components(self) -> u32 {
        match self {
            VertexFormat::Float32 => 1,
            VertexFormat::Float32x2 => 2,
            VertexFormat::Float32x3 => 3,
            VertexFormat::Float32x4 => 4,
        }
    }
}

/// One named field of a mesh's vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// The vertex input it feeds, by its DSL name (`a_pos`).
    pub name: &'static str,
    pub offset: u32,
    pub format: VertexFormat,
    /// Read once per instance, at `offset` in the mesh's instance records
    /// ([`Mesh::instances`]), not per vertex.
    pub per_instance: bool,
}

/// Per-instance records, stored in a mesh's `vertices` after its vertices:
/// `count` records of `stride` bytes from byte `base`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Instances {
    pub base: u32,
    pub stride: u32,
    pub count: u32,
}

/// Indexed triangles with interleaved vertex fields. Plans refer to meshes
/// that live for the whole process, so executors keep them uploaded.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    pub name: &'static str,
    /// The vertex data, `stride` bytes per vertex.
    pub vertices: Vec<u8>,
    pub stride: u32,
    pub fields: Vec<Field>,
    pub indices: Vec<u32>,
    /// The field a vertex program must read to place the vertices.
    pub position: &'static str,
    /// Drawn instanced, with these per-instance records (none: once).
    pub instances: Option<Instances>,
    /// Its indices drawn as a point list (each vertex once), not triangles.
    pub points: bool,
}

impl Mesh {
    pub fn field(&self, name: &str) -> Option<&Field> {
        self.fields.iter().find(|f| f.name == name)
    }
}

/// What one draw rasterises.
#[derive(Clone, Copy, Debug)]
pub enum Geometry {
    Mesh(&'static Mesh),
    /// `n` vertices without vertex buffers (the vertex program reads
    /// `gl_VertexID`).
    Vertices(u32),
}

#[derive(Clone, Debug)]
pub struct Draw {
    pub geometry: Geometry,
    /// This draw's values; they override the pass's.
    pub values: Values,
}

/// One render pass: a program, its attachments and state, its draws.
#[derive(Clone, Debug)]
pub struct Pass {
    /// Names it in messages (`shadow`, `main`).
    pub name: String,
    pub vertex: String,
    /// `None`: a vertex-only pass (depth alone, no fragment stage), as
    /// dasVulkan's shadow pipeline is. GL, which links no program without
    /// a fragment shader on ES, gets an empty one.
    pub fragment: Option<String>,
    pub color: Option<Attachment<[f64; 4]>>,
    /// Colour attachments for fragment outputs at locations 1, 2, ... (a
    /// G-buffer pass); empty for a pass with one colour target or none.
    pub more_colors: Vec<Attachment<[f64; 4]>>,
    /// Depth test LESS with writes, against this attachment.
    pub depth: Option<Attachment<f32>>,
    pub cull: Cull,
    /// The shadow pass's slope-scaled depth bias (constant 4, slope 2; GL
    /// polygon offset 2.0 / 4.0).
    pub depth_bias: bool,
    pub textures: Vec<TextureInput>,
    /// Values every draw of the pass sets.
    pub values: Values,
    pub draws: Vec<Draw>,
}

impl Pass {
    /// A value of a draw of this pass, by name: the draw's, else the pass's.
    pub fn value<'a>(&'a self, draw: &'a Draw, name: &str) -> Option<&'a Value> {
        draw.values.get(name).or_else(|| self.values.get(name))
    }

    /// Every value name a draw of this pass sets, sorted.
    pub fn value_names(&self, draw: &Draw) -> Vec<String> {
        let mut names: Vec<String> = self.values.names().chain(draw.values.names()).map(str::to_string).collect();
        names.sort();
        names.dedup();
        names
    }

    /// The targets this pass renders into.
    pub fn writes(&self, target: TargetId) -> bool {
        self.colors().any(|a| a.target == target) || self.depth.is_some_and(|a| a.target == target)
    }

    /// Every colour attachment, output location 0 first.
    pub fn colors(&self) -> impl Iterator<Item = &Attachment<[f64; 4]>> {
        self.color.iter().chain(&self.more_colors)
    }
}

/// What a uniform the plan sets no value for, and that has no default in
/// the manifest, holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Unset {
    /// Nothing: it is an error naming it (the scenes: a value they do not
    /// know is a program that does not fit).
    #[default]
    Error,
    /// Zeros (self-checking programs, and the resources a SPIR-V
    /// passthrough layout binds for a pass that does not use them).
    Zero,
}

/// A value every program drawing the frame must declare, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Required {
    pub value: String,
    pub why: String,
}

/// A whole frame.
#[derive(Clone, Debug)]
pub struct FramePlan {
    /// Names the scene in messages (`the shadow scene`).
    pub scene: String,
    pub targets: Vec<Target>,
    pub passes: Vec<Pass>,
    /// The target whose texels come back (colour, depth or integers), top
    /// row first.
    pub readback: TargetId,
    pub required: Vec<Required>,
    pub unset: Unset,
}

impl FramePlan {
    pub fn target(&self, id: TargetId) -> &Target {
        &self.targets[id.0]
    }

    /// Adds a target and returns its id.
    pub fn add_target(&mut self, name: &str, width: u32, height: u32, format: Format) -> TargetId {
        self.targets.push(Target { name: name.to_string(), width, height, format, contents: None, dim: Dim::D2 });
        TargetId(self.targets.len() - 1)
    }

    /// Adds an `Rgba8` texture holding `texels` (top row first).
    pub fn add_texture(&mut self, name: &str, width: u32, height: u32, texels: Vec<u8>) -> TargetId {
        self.add_layered(name, width, height, Dim::D2, texels)
    }

    /// Adds an `Rgba8` texture of kind `dim` holding `texels` (its layers
    /// one after another, each top row first).
    pub fn add_layered(&mut self, name: &str, width: u32, height: u32, dim: Dim, texels: Vec<u8>) -> TargetId {
        debug_assert_eq!(texels.len(), (width * height * dim.layers() * 4) as usize);
        self.targets.push(Target { name: name.to_string(), width, height, format: Format::Rgba8, contents: Some(texels), dim });
        TargetId(self.targets.len() - 1)
    }

    /// Whether the plan asks nothing impossible of any executor: sizes of
    /// at least 1, attachments of the right kind, a pass per draw list.
    pub fn check(&self) -> Result<(), String> {
        for t in &self.targets {
            if t.width == 0 || t.height == 0 {
                return Err(format!("target `{}` is {}x{}: every size must be at least 1", t.name, t.width, t.height));
            }
        }
        for p in &self.passes {
            if p.color.is_none() && !p.more_colors.is_empty() {
                return Err(format!("pass `{}` has colour attachments for locations 1.. but none for location 0", p.name));
            }
            for c in p.colors() {
                if self.target(c.target).format.is_depth() {
                    return Err(format!("pass `{}` draws colour into the depth target `{}`", p.name, self.target(c.target).name));
                }
            }
            let colors: Vec<&Target> = p.colors().map(|c| self.target(c.target)).collect();
            if let Some(t) = colors.iter().find(|t| (t.width, t.height) != (colors[0].width, colors[0].height)) {
                return Err(format!("pass `{}` draws into `{}` and `{}`, of different sizes", p.name, colors[0].name, t.name));
            }
            if let Some((i, c)) = p.colors().enumerate().find(|(i, c)| p.colors().take(*i).any(|d| d.target == c.target)) {
                return Err(format!("pass `{}` draws colour location {i} into `{}`, which an earlier location also draws into", p.name, self.target(c.target).name));
            }
            if let Some(d) = p.depth {
                if !self.target(d.target).format.is_depth() {
                    return Err(format!("pass `{}` tests depth against the colour target `{}`", p.name, self.target(d.target).name));
                }
            }
            if p.color.is_none() && p.depth.is_none() {
                return Err(format!("pass `{}` has no attachment", p.name));
            }
            if let Some(t) = p.colors().map(|a| a.target).chain(p.depth.map(|a| a.target)).map(|t| self.target(t)).find(|t| t.dim != Dim::D2) {
                return Err(format!("pass `{}` draws into the {} texture `{}`: passes draw into 2D targets only", p.name, t.dim.name(), t.name));
            }
        }
        Ok(())
    }

    /// The size of the image that comes back.
    pub fn readback_size(&self) -> (u32, u32) {
        let t = self.target(self.readback);
        (t.width, t.height)
    }
}
