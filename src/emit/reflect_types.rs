//! The reflection manifest: everything a host needs to bind a compiled
//! shader file on every target. Serialised as `STEM.reflect.json`.
//!
//! Binding model (docs/targets.md says how each host binds):
//! - a struct-typed `@uniform` is a uniform buffer of its own, with the
//!   struct's fields as members: a std140 block `<name>_ubo` in GLSL;
//! - the loose uniforms (`var @uniform u_model : float4x4`, every one that
//!   is not a struct) of each `@set` group are the members of one uniform
//!   buffer on WGSL/SPIR-V (`uniforms`, `set1_uniforms`, ...); in GLSL
//!   they are plain `uniform T name;` globals (`uniforms`, set with
//!   `glUniform*`), or with `--gl-uniforms blocks` the buffer as a std140
//!   block `uniforms_ubo`;
//! - every sampler is a texture plus (on WGSL/SPIR-V) a separate sampler
//!   binding; on GL it is one `sampler*` uniform on a texture unit.

//!
//! Serialised by `serde::Serialize` impls written out below (the keys and
//! their order are the JSON format); `serde::Deserialize`, for reading a
//! manifest back, is derived with the feature `deserialize` (in the
//! defaults and in `render`).

/// Bumped when the JSON shape changes incompatibly (adding a field is
/// compatible: `structs` was added in format 1). Format 2: loose uniforms
/// share a buffer per group (`uniform_buffers`, `uniforms`), GLSL declares
/// them plain, and interface variables have GLSL locations only where the
/// source gives one.
pub const REFLECTION_FORMAT: u32 = 2;

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
    /// How GLSL declares the loose uniforms: `"plain"` (`uniform T name;`)
    /// or `"blocks"` (the loose buffers as std140 blocks).
    pub gl_uniforms: String,
    /// What WGSL/SPIR-V bind: the struct uniforms, and a buffer per group
    /// of the loose uniforms. In GLSL, the ones with a `glsl_block`.
    pub uniform_buffers: Vec<UniformBuffer>,
    /// Every loose uniform some entry point reads, in declaration order.
    pub uniforms: Vec<Uniform>,
    /// Every struct type a uniform block is or contains, at any depth (a
    /// member's type, an array's element type), each once, a struct after
    /// the structs it contains: what a host needs to lay out a nested
    /// struct. `Member::ty` and `UniformBlock::ty` name them.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub structs: Vec<StructLayout>,
    pub samplers: Vec<Sampler>,
    /// `@ssbo` storage buffers (left out when there are none).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub storage_buffers: Option<Vec<StorageBuffer>>,
    /// Storage images (left out when there are none).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub storage_images: Option<Vec<StorageImage>>,
    /// The WebGPU limits (by their `requiredLimits` names) the WGSL/SPIR-V
    /// program needs above WebGPU's defaults, with the value to request:
    /// only with `--limit` (left out when it needs none; docs/targets.md,
    /// "Device limits").
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub required_limits: Option<std::collections::BTreeMap<String, u64>>,
    /// What a host must enable for the program's subgroups, `gl_DrawID`
    /// or `gl_PrimitiveID` (left out when it needs nothing).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub requires: Option<Requirements>,
    /// The `@constant_id` specialization constants (left out when none).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub specialization_constants: Option<Vec<SpecConstant>>,
}

/// Device features a program needs beyond a target's baseline.
#[derive(Clone, Debug, PartialEq, Default)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Requirements {
    /// wgpu `Features` by their Rust names (`SUBGROUP`, `PRIMITIVE_INDEX`).
    pub wgpu_features: Vec<String>,
    /// The WGSL `enable` directives the WGSL starts with (`subgroups`,
    /// `primitive_index`); naga 30 does not know `enable subgroups;` and a
    /// wgpu host drops that line (docs/targets.md).
    pub wgsl_enable: Vec<String>,
    /// The SPIR-V version written: `"1.0"`, or `"1.3"` (Vulkan 1.1) with
    /// subgroups.
    pub spirv_version: String,
    /// Vulkan features the SPIR-V needs (`subgroupSupportedOperations`
    /// bits by name, `shaderDrawParameters`).
    pub vulkan: Vec<String>,
}

/// One specialization constant: WGSL `override` with `@id(id)`, SPIR-V
/// `OpSpecConstant` with `SpecId id`, GLSL holds its default
/// (docs/targets.md, "Specialization constants").
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct SpecConstant {
    pub name: String,
    /// Its `@constant_id`: WGSL's `@id`, the key of wgpu's
    /// `PipelineCompilationOptions::constants`.
    pub id: u32,
    /// `bool`, `int`, `uint` or `float`.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// The default as a number (a bool is 0 or 1: wgpu's constants are
    /// `f64`s).
    pub default: f64,
    /// The default's 32 bits (a Vulkan `VkSpecializationInfo` word).
    pub default_bits: u32,
    /// What each target holds: `"override"` (WGSL) and `"spec_constant"`
    /// (SPIR-V: `OpSpecConstant`, `SpecId id`), which the host may set;
    /// `"default"` (GLSL: the default, fixed at compile time, the line
    /// `const T NAME = default;`, which a GL host may edit before
    /// compiling).
    pub wgsl: String,
    pub spirv: String,
    pub glsl: String,
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
    /// Names of the uniform buffers (`UniformBuffer::name`) this stage uses.
    pub uniform_buffers: Vec<String>,
    /// Names of the loose uniforms (`Uniform::name`) this stage reads (in
    /// GLSL's plain form, the `uniform` globals its file declares).
    pub uniforms: Vec<String>,
    /// Names of the samplers (`Sampler::name`) this stage uses.
    pub samplers: Vec<String>,
    /// A compute entry point's `local_size_x/y/z`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub workgroup_size: Option<[u32; 3]>,
    /// Names of the storage buffers (`StorageBuffer::name`) it uses, where any.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub storage_buffers: Option<Vec<String>>,
    /// Names of the storage images (`StorageImage::name`) it uses, where any.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub storage_images: Option<Vec<String>>,
    /// `"vulkan"` for an entry point of daslang's Vulkan dialect (absent
    /// for the GL dialect): stage I/O by location, Vulkan conventions.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub dialect: Option<String>,
    /// A Vulkan-dialect vertex entry point: the clip-space adaptation each
    /// target's output applies to `gl_Position` (`"none"`,
    /// `"z' = 2z - w"`, `"y' = -y"`; docs/targets.md).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub clip_space: Option<std::collections::BTreeMap<String, String>>,
}

/// An `@ssbo` storage buffer: std430 (WGSL's storage layout, the same).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct StorageBuffer {
    pub name: String,
    /// The DSL struct's name.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// `"read"` (`@readonly`) or `"read_write"`.
    pub access: String,
    /// Bytes before the run-time-sized array (the whole struct without one).
    pub size: u32,
    /// The run-time-sized last member's element stride, where it has one:
    /// the buffer holds `size + n * runtime_stride` bytes for `n` elements.
    pub runtime_stride: Option<u32>,
    pub group: u32,
    pub binding: u32,
    /// GLSL: `layout(std430, binding = glsl_binding) buffer glsl_block`.
    pub glsl_block: String,
    pub glsl_binding: u32,
    /// Members at their std430 offsets (a run-time array with `size` 0).
    pub members: Vec<Member>,
}

/// A storage image.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct StorageImage {
    pub name: String,
    /// `image2D`, `uimage3D`, `image2DArray`, ...
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// The GLSL format qualifier (`rgba8`, `r32ui`).
    pub format: String,
    /// The WebGPU texture format (`rgba8unorm`, `r32uint`).
    pub wgpu_format: String,
    /// `"read"`, `"write"` or `"read_write"`.
    pub access: String,
    /// `"2d"`, `"3d"`, `"2d-array"`.
    pub dimension: String,
    pub group: u32,
    pub binding: u32,
    pub glsl_name: String,
    /// GL image unit (`layout(binding = N)` in GLSL; `glBindImageTexture`).
    pub image_unit: u32,
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
    /// The `layout(location = N)` the GLSL declares: only where the source
    /// gives `@location = N` (and on each colour output of an ES fragment
    /// shader with several). Otherwise the host binds by name
    /// (`glBindAttribLocation`, `glBindFragDataLocation`; `location` is the
    /// number to bind).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub glsl_location: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct UniformBuffer {
    /// The struct uniform's name, or the loose buffer's (`uniforms` for
    /// group 0, `set1_uniforms` for group 1, ...).
    pub name: String,
    /// The struct's name (the loose buffer's struct: `Uniforms`, ...).
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// Whether this buffer holds the loose uniforms of its group (its
    /// members are `Reflection::uniforms` entries).
    pub loose: bool,
    /// Size in bytes (the WGSL uniform layout, identical to std140 for
    /// what a buffer holds), rounded up to 16.
    pub size: u32,
    pub group: u32,
    pub binding: u32,
    /// Its std140 block's name in GLSL (bind with glGetUniformBlockIndex +
    /// glUniformBlockBinding), the same in every stage: `<name>_ubo`. A
    /// loose buffer has one only with `--gl-uniforms blocks`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub glsl_block: Option<String>,
    /// The GL binding point of `glsl_block` (glUniformBlockBinding,
    /// glBindBufferRange), as daslang's GL binder assigns it: struct
    /// uniforms by name, an `@binding = N` kept (docs/targets.md).
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub glsl_binding: Option<u32>,
    /// Members with byte offsets.
    pub members: Vec<Member>,
    /// `true` for a `@push_constant` (absent otherwise): a uniform buffer
    /// at its `group`/`binding` on WGSL/SPIR-V, the `glsl_block` on GL
    /// (docs/targets.md, "Push constants").
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub push_constant: Option<bool>,
}

/// A loose uniform: a member of its group's uniform buffer, a plain
/// `uniform` in GLSL.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "deserialize", derive(serde::Deserialize))]
pub struct Uniform {
    /// The DSL global's name.
    pub name: String,
    /// DSL type, e.g. `float3x2`, `bool`, `float[9]`.
    #[cfg_attr(feature = "deserialize", serde(rename = "type"))]
    pub ty: String,
    /// The uniform buffer (`UniformBuffer::name`) it is a member of.
    pub buffer: String,
    /// Its name in GLSL's plain form (`glGetUniformLocation`); `None`
    /// with `--gl-uniforms blocks`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub glsl_name: Option<String>,
    /// Its GLSL type (`mat3x2`, `bool`, `float[9]`): which `glUniform*`
    /// sets it.
    pub glsl_type: String,
    /// Its default value (`var @uniform x : T = value`) as the values a
    /// `glUniform*v` call takes: every component in order (matrices column
    /// by column, arrays element by element), as 32-bit words (floats by
    /// their IEEE-754 bits, `bool` 0 or 1), no padding. The buffer layout
    /// of the same default is the member's `default`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub default: Option<Vec<u32>>,
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
    /// The type the buffer stores it as, where that is not its own (a
    /// loose uniform's only): `uint` for `bool` (0 or 1), `uintN` for
    /// `boolN`, `float4[N]` for `float[N]` or `float2[N]` (each element in
    /// the first components of a `float4`), `float4[C]` for `floatCx2`.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub storage: Option<String>,
    /// A uniform block member's name for a GL host
    /// (`glGetUniformIndices`): `<glsl_block>.<member>`, the block being
    /// declared with an instance name. `None` elsewhere.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub glsl_name: Option<String>,
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
    /// The length of a descriptor array (a Vulkan-dialect `sampler2D[N]`:
    /// N textures at `texture_binding`, N samplers at `sampler_binding`);
    /// absent for one sampler.
    #[cfg_attr(feature = "deserialize", serde(default))]
    pub count: Option<u32>,
}

serialize_struct!(Reflection {
    "format": format,
    "source": source,
    "conventions": conventions,
    "entry_points": entry_points,
    "programs": programs,
    "gl_uniforms": gl_uniforms,
    "uniform_buffers": uniform_buffers,
    "uniforms": uniforms,
    "structs": structs,
    "samplers": samplers,
    "storage_buffers": storage_buffers?,
    "storage_images": storage_images?,
    "required_limits": required_limits?,
    "requires": requires?,
    "specialization_constants": specialization_constants?,
});

serialize_struct!(Requirements {
    "wgpu_features": wgpu_features,
    "wgsl_enable": wgsl_enable,
    "spirv_version": spirv_version,
    "vulkan": vulkan,
});

serialize_struct!(SpecConstant {
    "name": name,
    "id": id,
    "type": ty,
    "default": default,
    "default_bits": default_bits,
    "wgsl": wgsl,
    "spirv": spirv,
    "glsl": glsl,
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
    "uniform_buffers": uniform_buffers,
    "uniforms": uniforms,
    "samplers": samplers,
    "workgroup_size": workgroup_size?,
    "storage_buffers": storage_buffers?,
    "storage_images": storage_images?,
    "dialect": dialect?,
    "clip_space": clip_space?,
});

serialize_struct!(StorageBuffer {
    "name": name,
    "type": ty,
    "access": access,
    "size": size,
    "runtime_stride": runtime_stride?,
    "group": group,
    "binding": binding,
    "glsl_block": glsl_block,
    "glsl_binding": glsl_binding,
    "members": members,
});

serialize_struct!(StorageImage {
    "name": name,
    "type": ty,
    "format": format,
    "wgpu_format": wgpu_format,
    "access": access,
    "dimension": dimension,
    "group": group,
    "binding": binding,
    "glsl_name": glsl_name,
    "image_unit": image_unit,
});

serialize_struct!(Io {
    "name": name,
    "location": location,
    "type": ty,
    "vertex_format": vertex_format?,
    "size": size,
    "interpolation": interpolation?,
    "glsl_name": glsl_name,
    "glsl_location": glsl_location?,
});

serialize_struct!(UniformBuffer {
    "name": name,
    "type": ty,
    "loose": loose,
    "size": size,
    "group": group,
    "binding": binding,
    "glsl_block": glsl_block?,
    "glsl_binding": glsl_binding?,
    "members": members,
    "push_constant": push_constant?,
});

serialize_struct!(Uniform {
    "name": name,
    "type": ty,
    "buffer": buffer,
    "glsl_name": glsl_name?,
    "glsl_type": glsl_type,
    "default": default?,
});

serialize_struct!(Member {
    "name": name,
    "type": ty,
    "offset": offset,
    "size": size,
    "array_stride": array_stride?,
    "matrix_stride": matrix_stride?,
    "storage": storage?,
    "glsl_name": glsl_name?,
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
    "count": count?,
});
