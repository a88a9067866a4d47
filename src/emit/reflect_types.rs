//! The reflection manifest: everything a host needs to bind a compiled
//! shader file on every target. Serialised as `STEM.reflect.json`.
//!
//! Binding model (the same for every target, see docs/targets.md):
//! - every `@uniform` value that is not a sampler is one uniform block: a
//!   struct-typed uniform is a block with the struct's fields as members, a
//!   loose value (`var @uniform u_model : float4x4`) is a block with that one
//!   member;
//! - every sampler is a texture plus (on WGSL/SPIR-V) a separate sampler
//!   binding; on GL it is one `sampler*` uniform on a texture unit.

//!
//! Serialised by `serde::Serialize` impls written out below (the keys and
//! their order are the JSON format); `serde::Deserialize`, for reading a
//! manifest back, is derived with the feature `deserialize` (in the
//! defaults and in `render`).

/// Bumped when the JSON shape changes incompatibly (adding a field is
/// compatible: `structs` was added in format 1).
pub const REFLECTION_FORMAT: u32 = 1;

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Reflection {
    pub format: u32,
    /// The input file's name as given to the compiler.
    pub source: String,
    /// `"portable"` (WGSL/SPIR-V adapted to GL conventions: the host flips
    /// the final image and uses clockwise front faces) or `"native"`.
    pub conventions: String,
    pub entry_points: Vec<EntryPoint>,
    /// The vertex and fragment entry points that form a program (a GL host
    /// links each pair into one program object; locations and texture
    /// units are numbered per program).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub programs: Vec<ProgramLink>,
    pub uniform_blocks: Vec<UniformBlock>,
    /// Every struct type a uniform block is or contains, at any depth (a
    /// member's type, an array's element type), each once, a struct after
    /// the structs it contains: what a host needs to lay out a nested
    /// struct. `Member::ty` and `UniformBlock::ty` name them.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub structs: Vec<StructLayout>,
    pub samplers: Vec<Sampler>,
}

/// One program: a vertex and a fragment entry point, by name.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct ProgramLink {
    pub vertex: String,
    pub fragment: String,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct EntryPoint {
    /// Entry point name (the `def` name, or `[vertex_program(name = "...")]`).
    pub name: String,
    /// `"vertex"` or `"fragment"`.
    pub stage: String,
    /// Output file names per target, e.g. `{"glsl330": "main_vs.330.vert"}`.
    pub files: std::collections::BTreeMap<String, String>,
    /// Vertex attributes (vertex stage) or varyings read (fragment stage),
    /// sorted by location.
    pub inputs: Vec<Io>,
    /// Varyings written (vertex stage) or colour outputs (fragment stage).
    pub outputs: Vec<Io>,
    /// Builtins read or written, by their DSL names (`gl_Position`, ...).
    pub builtins: Vec<String>,
    /// Names of the uniform blocks (`UniformBlock::name`) this stage uses.
    pub uniform_blocks: Vec<String>,
    /// Names of the samplers (`Sampler::name`) this stage uses.
    pub samplers: Vec<String>,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Io {
    /// The DSL global's name.
    pub name: String,
    pub location: u32,
    /// DSL type, e.g. `float3`.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// wgpu vertex format name for vertex attributes, e.g. `Float32x3`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub vertex_format: Option<String>,
    /// Byte size of one element of this type in a tightly packed vertex buffer.
    pub size: u32,
    /// `"perspective"` or `"flat"` for varyings.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub interpolation: Option<String>,
    /// The identifier the GLSL output uses for it (both GLSL profiles).
    pub glsl_name: String,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct UniformBlock {
    /// The DSL global's name.
    pub name: String,
    /// DSL type of the global.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// Block size in bytes (std140 on GL, the identical WGSL uniform layout
    /// on WGSL/SPIR-V), rounded up to 16.
    pub size: u32,
    pub group: u32,
    pub binding: u32,
    /// The uniform block's name in GLSL (bind with glGetUniformBlockIndex +
    /// glUniformBlockBinding); the same in every stage.
    pub glsl_block: String,
    /// Members with byte offsets. A loose value is one member at offset 0.
    pub members: Vec<Member>,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Member {
    pub name: String,
    /// DSL type: `float3`, `float4x4`, a struct's name (see
    /// `Reflection::structs`), `T[N]` for arrays (`T[N][M]`: M arrays of
    /// `T[N]`).
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// Byte offset from the start of the block or struct.
    pub offset: u32,
    /// Byte size (a struct's own size, without the padding to 16 that
    /// follows a nested struct).
    pub size: u32,
    /// Stride between elements for arrays (of the outer array, for arrays
    /// of arrays: the elements of an inner array are its size over its
    /// length apart).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub array_stride: Option<u32>,
    /// Stride between columns for matrices.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub matrix_stride: Option<u32>,
    /// The member's default contents, from `var @uniform x : T = value`:
    /// its `size` bytes as little-endian 32-bit words (floats by their
    /// IEEE-754 bits, padding zero), to copy to `offset` before the host
    /// sets anything. Only members of uniform blocks have one.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub default: Option<Vec<u32>>,
}

/// The layout of a struct type in uniform blocks: the same on every target
/// (std140 on GL, the identical WGSL uniform layout on WGSL/SPIR-V).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct StructLayout {
    /// The DSL struct's name.
    pub name: String,
    /// Size in bytes: WGSL's size of the struct, its last member's end
    /// rounded up to the struct's alignment. std140 rounds a struct up to
    /// 16 bytes; whatever follows a nested struct starts at a multiple of
    /// 16 on every target, and a block's `size` is rounded up to 16.
    pub size: u32,
    /// Members with byte offsets from the start of the struct, in
    /// declaration order.
    pub members: Vec<Member>,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Sampler {
    /// The DSL global's name; also its `uniform sampler*` name in GLSL.
    pub name: String,
    /// DSL type, e.g. `sampler2DShadow`.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// The identifier the GLSL output uses (set its texture unit with
    /// glUniform1i on this name).
    pub glsl_name: String,
    /// GL texture unit: `@stage = N`, or assigned in declaration order.
    pub texture_unit: u32,
    pub group: u32,
    /// WGSL/SPIR-V binding of the texture.
    pub texture_binding: u32,
    /// WGSL/SPIR-V binding of the sampler (a comparison sampler for shadow
    /// samplers).
    pub sampler_binding: u32,
    /// `"2d"`, `"2d-array"`, `"3d"`, `"cube"`.
    pub dimension: String,
    /// `"float"`, `"depth"`, `"sint"`, `"uint"`.
    pub sample_type: String,
    /// Whether the sampler must be a comparison sampler.
    pub comparison: bool,
}

serialize_struct!(Reflection {
    "format": format,
    "source": source,
    "conventions": conventions,
    "entry_points": entry_points,
    "programs": programs,
    "uniform_blocks": uniform_blocks,
    "structs": structs,
    "samplers": samplers,
});

serialize_struct!(ProgramLink {
    "vertex": vertex,
    "fragment": fragment,
});

serialize_struct!(EntryPoint {
    "name": name,
    "stage": stage,
    "files": files,
    "inputs": inputs,
    "outputs": outputs,
    "builtins": builtins,
    "uniform_blocks": uniform_blocks,
    "samplers": samplers,
});

serialize_struct!(Io {
    "name": name,
    "location": location,
    "type": ty,
    "vertex_format": vertex_format?,
    "size": size,
    "interpolation": interpolation?,
    "glsl_name": glsl_name,
});

serialize_struct!(UniformBlock {
    "name": name,
    "type": ty,
    "size": size,
    "group": group,
    "binding": binding,
    "glsl_block": glsl_block,
    "members": members,
});

serialize_struct!(Member {
    "name": name,
    "type": ty,
    "offset": offset,
    "size": size,
    "array_stride": array_stride?,
    "matrix_stride": matrix_stride?,
    "default": default?,
});

serialize_struct!(StructLayout {
    "name": name,
    "size": size,
    "members": members,
});

serialize_struct!(Sampler {
    "name": name,
    "type": ty,
    "glsl_name": glsl_name,
    "texture_unit": texture_unit,
    "group": group,
    "texture_binding": texture_binding,
    "sampler_binding": sampler_binding,
    "dimension": dimension,
    "sample_type": sample_type,
    "comparison": comparison,
});
