//! The checked program: every name resolved, every expression typed.
//! Lowering walks this and never has to report a user error.

use super::builtins::Builtin;
use super::types::Ty;
pub use super::types::{ConstValue, StructDef};
use super::types::SamplerKind;
use crate::source::Span;
use crate::syntax::ast::{BinaryOp, UnaryOp};

pub type GlobalId = usize;
pub type ConstId = usize;
pub type FuncId = usize;
pub type LocalId = usize;

/// Highest `@binding` accepted (exclusive): a bound on the checker's
/// tables, in both dialects; the sampler halves of the Vulkan dialect's
/// combined image-samplers must fit below it too.
pub const MAX_BINDINGS: u32 = 1000;

#[derive(Debug, Default)]
pub struct Program {
    pub structs: Vec<StructDef>,
    pub enums: Vec<EnumDef>,
    pub globals: Vec<Global>,
    pub consts: Vec<Const>,
    /// Helper functions, callees before callers.
    pub functions: Vec<Function>,
    pub entry_points: Vec<EntryPoint>,
    /// The vertex and fragment entry points that form one program (a host
    /// links them into one GL program): see `check::programs`.
    pub links: Vec<Link>,
    /// The integer places an atomic builtin operates on: a `@groupshared`
    /// integer or integer array (`None`), or a member of a `@ssbo`
    /// (`Some(member)`). Lowering gives them atomic types, which plain
    /// reads and writes of them load and store.
    pub atomics: std::collections::BTreeSet<(GlobalId, Option<u32>)>,
    /// The `@push_constant` globals (uniform buffers on every target; the
    /// manifest marks them).
    pub push_constants: std::collections::BTreeSet<GlobalId>,
    /// The `@flat` interface globals (no interpolation).
    pub flat: std::collections::BTreeSet<GlobalId>,
    /// The program has Vulkan-dialect entry points: its resources follow
    /// dasSpirv's rules (a `sampler2D` is one combined image-sampler,
    /// storage images rgba8 by default).
    pub vulkan: bool,
    /// In the Vulkan dialect, the binding of each used (non-array)
    /// sampler's sampler half, in the sampler's group: naga has no
    /// combined image-sampler, so the GPU module binds its texture at the
    /// sampler's binding and its sampler here, past every other binding
    /// of the group in the programs that use it (docs/targets.md).
    pub sampler_halves: std::collections::BTreeMap<GlobalId, u32>,
    /// The `@binding = N` written on a global, where one is.
    pub written_bindings: std::collections::BTreeMap<GlobalId, u32>,
}

/// A vertex entry point and a fragment entry point of one program: they
/// share a varying, or neither shares one with any entry point of the
/// other stage (a depth-only pass, a transform-feedback step).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link {
    /// Indices into `Program::entry_points`.
    pub vertex: usize,
    pub fragment: usize,
}

impl Program {
    /// Whether the program has a compute entry point, a storage buffer or
    /// a storage image: what GLSL 330 and ES 3.00 lack.
    pub fn needs_compute(&self) -> bool {
        self.entry_points.iter().any(|e| e.stage == naga::ShaderStage::Compute)
            || self.globals.iter().any(|g| g.bind.is_some() && matches!(g.kind, GlobalKind::Storage { .. } | GlobalKind::Image { .. }))
    }

    pub fn struct_names(&self) -> Vec<String> {
        self.structs.iter().map(|s| s.name.clone()).collect()
    }

    pub fn enum_names(&self) -> Vec<String> {
        self.enums.iter().map(|e| e.name.clone()).collect()
    }
}

/// An enumeration: its values are `int` (or `uint`) constants of its own type.
#[derive(Debug)]
pub struct EnumDef {
    pub name: String,
    /// `Int` or `Uint`.
    pub base: super::types::Scalar,
    pub values: Vec<(String, i64)>,
    pub span: Span,
}

/// Builtin variables (`gl_*`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BuiltinVar {
    Position,
    PointSize,
    FragDepth,
    FragCoord,
    FrontFacing,
    PointCoord,
    VertexId,
    InstanceId,
    // Compute inputs (`uint3`, `gl_LocalInvocationIndex` a `uint`).
    GlobalInvocationId,
    LocalInvocationId,
    LocalInvocationIndex,
    WorkGroupId,
    NumWorkGroups,
    /// `gl_WorkGroupSize`: the entry point's `local_size_*`, a constant
    /// there (no target reads it from the device).
    WorkGroupSize,
    /// dasSpirv's `gl_DrawID` (vertex, `int`): the draw's index in a
    /// multi-draw; not every target has it (sema/check/targets.rs).
    DrawId,
    /// `gl_PrimitiveID` (fragment, `int`).
    PrimitiveId,
    /// The subgroup inputs (`uint`): size and lane in compute and fragment
    /// entry points, the subgroup count and index in compute ones.
    SubgroupSize,
    SubgroupInvocationId,
    NumSubgroups,
    SubgroupId,
    /// A mesh entry point's outputs (dasSpirv's VK_EXT_mesh_shader arrays):
    /// `gl_MeshVerticesEXT[i].gl_Position`, `gl_PrimitiveTriangleIndicesEXT[i]`
    /// and `gl_MeshPrimitivesEXT[i].gl_PrimitiveID`.
    MeshVertices,
    PrimitiveTriangleIndices,
    MeshPrimitives,
}

impl BuiltinVar {
    pub fn name(self) -> &'static str {
        match self {
            BuiltinVar::Position => "gl_Position",
            BuiltinVar::PointSize => "gl_PointSize",
            BuiltinVar::FragDepth => "gl_FragDepth",
            BuiltinVar::FragCoord => "gl_FragCoord",
            BuiltinVar::FrontFacing => "gl_FrontFacing",
            BuiltinVar::PointCoord => "gl_PointCoord",
            BuiltinVar::VertexId => "gl_VertexID",
            BuiltinVar::InstanceId => "gl_InstanceID",
            BuiltinVar::GlobalInvocationId => "gl_GlobalInvocationID",
            BuiltinVar::LocalInvocationId => "gl_LocalInvocationID",
            BuiltinVar::LocalInvocationIndex => "gl_LocalInvocationIndex",
            BuiltinVar::WorkGroupId => "gl_WorkGroupID",
            BuiltinVar::NumWorkGroups => "gl_NumWorkGroups",
            BuiltinVar::WorkGroupSize => "gl_WorkGroupSize",
            BuiltinVar::DrawId => "gl_DrawID",
            BuiltinVar::MeshVertices => "gl_MeshVerticesEXT",
            BuiltinVar::PrimitiveTriangleIndices => "gl_PrimitiveTriangleIndicesEXT",
            BuiltinVar::MeshPrimitives => "gl_MeshPrimitivesEXT",
            BuiltinVar::PrimitiveId => "gl_PrimitiveID",
            BuiltinVar::SubgroupSize => "gl_SubgroupSize",
            BuiltinVar::SubgroupInvocationId => "gl_SubgroupInvocationID",
            BuiltinVar::NumSubgroups => "gl_NumSubgroups",
            BuiltinVar::SubgroupId => "gl_SubgroupID",
        }
    }

    pub fn from_name(name: &str) -> Option<BuiltinVar> {
        Some(match name {
            "gl_Position" => BuiltinVar::Position,
            "gl_PointSize" => BuiltinVar::PointSize,
            "gl_FragDepth" => BuiltinVar::FragDepth,
            "gl_FragCoord" => BuiltinVar::FragCoord,
            "gl_FrontFacing" => BuiltinVar::FrontFacing,
            "gl_PointCoord" => BuiltinVar::PointCoord,
            "gl_VertexID" | "gl_VertexIndex" => BuiltinVar::VertexId,
            "gl_InstanceID" | "gl_InstanceIndex" => BuiltinVar::InstanceId,
            "gl_GlobalInvocationID" => BuiltinVar::GlobalInvocationId,
            "gl_LocalInvocationID" => BuiltinVar::LocalInvocationId,
            "gl_LocalInvocationIndex" => BuiltinVar::LocalInvocationIndex,
            "gl_WorkGroupID" => BuiltinVar::WorkGroupId,
            "gl_NumWorkGroups" => BuiltinVar::NumWorkGroups,
            "gl_WorkGroupSize" => BuiltinVar::WorkGroupSize,
            "gl_DrawID" => BuiltinVar::DrawId,
            "gl_MeshVerticesEXT" => BuiltinVar::MeshVertices,
            "gl_PrimitiveTriangleIndicesEXT" => BuiltinVar::PrimitiveTriangleIndices,
            "gl_MeshPrimitivesEXT" => BuiltinVar::MeshPrimitives,
            "gl_PrimitiveID" => BuiltinVar::PrimitiveId,
            "gl_SubgroupSize" => BuiltinVar::SubgroupSize,
            "gl_SubgroupInvocationID" => BuiltinVar::SubgroupInvocationId,
            "gl_NumSubgroups" => BuiltinVar::NumSubgroups,
            "gl_SubgroupID" => BuiltinVar::SubgroupId,
            _ => return None,
        })
    }

    pub const NAMES: [&'static str; 25] = [
        "gl_DrawID",
        "gl_MeshVerticesEXT",
        "gl_PrimitiveTriangleIndicesEXT",
        "gl_MeshPrimitivesEXT",
        "gl_PrimitiveID",
        "gl_SubgroupSize",
        "gl_SubgroupInvocationID",
        "gl_NumSubgroups",
        "gl_SubgroupID",
        "gl_GlobalInvocationID",
        "gl_LocalInvocationID",
        "gl_LocalInvocationIndex",
        "gl_WorkGroupID",
        "gl_NumWorkGroups",
        "gl_WorkGroupSize",
        "gl_Position",
        "gl_PointSize",
        "gl_FragDepth",
        "gl_FragCoord",
        "gl_FrontFacing",
        "gl_PointCoord",
        "gl_VertexID",
        "gl_VertexIndex",
        "gl_InstanceID",
        "gl_InstanceIndex",
    ];

    pub fn ty(self) -> Ty {
        use super::types::*;
        match self {
            BuiltinVar::Position | BuiltinVar::FragCoord => Ty::Vector(Scalar::Float, 4),
            BuiltinVar::PointSize | BuiltinVar::FragDepth => FLOAT,
            BuiltinVar::FrontFacing => BOOL,
            BuiltinVar::PointCoord => Ty::Vector(Scalar::Float, 2),
            BuiltinVar::VertexId | BuiltinVar::InstanceId | BuiltinVar::DrawId | BuiltinVar::PrimitiveId => INT,
            // The element structs of the other two are the checker's
            // (`Checker::mesh_output_ty`), which the global's type holds.
            BuiltinVar::PrimitiveTriangleIndices => Ty::RuntimeArray(Box::new(Ty::Vector(Scalar::Uint, 3))),
            BuiltinVar::MeshVertices | BuiltinVar::MeshPrimitives => Ty::Error,
            BuiltinVar::LocalInvocationIndex | BuiltinVar::SubgroupSize | BuiltinVar::SubgroupInvocationId | BuiltinVar::NumSubgroups | BuiltinVar::SubgroupId => UINT,
            _ => Ty::Vector(Scalar::Uint, 3),
        }
    }

    /// Written by the shader (an output) rather than read.
    pub fn is_output(self) -> bool {
        matches!(self, BuiltinVar::Position | BuiltinVar::PointSize | BuiltinVar::FragDepth) || self.is_mesh_output()
    }

    /// One of a mesh entry point's output arrays.
    pub fn is_mesh_output(self) -> bool {
        matches!(self, BuiltinVar::MeshVertices | BuiltinVar::PrimitiveTriangleIndices | BuiltinVar::MeshPrimitives)
    }

    /// The stage it belongs to (the first of its stages).
    pub fn stage(self) -> naga::ShaderStage {
        match self {
            BuiltinVar::Position | BuiltinVar::PointSize | BuiltinVar::VertexId | BuiltinVar::InstanceId | BuiltinVar::DrawId => naga::ShaderStage::Vertex,
            BuiltinVar::FragDepth | BuiltinVar::FragCoord | BuiltinVar::FrontFacing | BuiltinVar::PointCoord | BuiltinVar::PrimitiveId => naga::ShaderStage::Fragment,
            BuiltinVar::MeshVertices | BuiltinVar::PrimitiveTriangleIndices | BuiltinVar::MeshPrimitives => naga::ShaderStage::Mesh,
            _ => naga::ShaderStage::Compute,
        }
    }

    /// Whether an entry point of `stage` may read or write it: the
    /// subgroup size and lane exist in fragment entry points too (WGSL
    /// has no subgroups in vertex ones).
    pub fn available_in(self, stage: naga::ShaderStage) -> bool {
        match self {
            BuiltinVar::SubgroupSize | BuiltinVar::SubgroupInvocationId => matches!(stage, naga::ShaderStage::Compute | naga::ShaderStage::Fragment),
            // The workgroup inputs in mesh and task entry points too.
            BuiltinVar::GlobalInvocationId | BuiltinVar::LocalInvocationId | BuiltinVar::LocalInvocationIndex | BuiltinVar::WorkGroupId | BuiltinVar::NumWorkGroups => {
                matches!(stage, naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task)
            }
            _ => self.stage() == stage,
        }
    }

    /// A subgroup input (targets without subgroups refuse it).
    pub fn is_subgroup(self) -> bool {
        matches!(self, BuiltinVar::SubgroupSize | BuiltinVar::SubgroupInvocationId | BuiltinVar::NumSubgroups | BuiltinVar::SubgroupId)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IoKind {
    /// `@in`: a vertex attribute, or a fragment-stage input.
    In,
    /// `@out`: a fragment output (or a vertex output).
    Out,
    /// `@inout`: a varying, written by the vertex stage, read by the fragment stage.
    InOut,
}

#[derive(Clone, Debug)]
pub enum GlobalKind {
    /// A uniform value (or block, for a struct); `default`: the host's
    /// default from `var @uniform x : T = value` (the manifest, the Rust
    /// bindings and the runner use it).
    Uniform { default: Option<ConstValue> },
    /// A sampler, or an array of `count` samplers (`ty` is `T[count]`) on
    /// consecutive texture units from `texture_unit`: its `@stage = N`, or
    /// the lowest units free in every program that uses it.
    Sampler { kind: SamplerKind, texture_unit: u32, count: Option<u32> },
    /// `location` is the `@location = N` written, if any; each entry point
    /// has the location it uses (`EntryPoint::locations`), numbered per
    /// program where none is written.
    Io { kind: IoKind, location: Option<u32> },
    Builtin(BuiltinVar),
    /// `@ssbo`: a storage buffer (`ty` is a struct, std430; its last
    /// member may be a run-time-sized array), read-write or `@readonly`.
    /// `unit`: its GL binding point (`@stage = N`, or numbered).
    Storage { access: super::types::Access, unit: u32 },
    /// A storage image (`ty` is `Ty::Image`) with its `@format`, access
    /// and GL image unit (`@stage = N`, or numbered).
    Image { format: super::types::ImageFormat, access: super::types::Access, unit: u32 },
    /// `@groupshared`: workgroup memory, shared by the invocations of one
    /// workgroup of a compute entry point (zero at the start of each).
    Workgroup,
    /// `@task_payload`: what a task workgroup hands the mesh workgroups it
    /// launches (written by the task entry point, read by the mesh one).
    TaskPayload,
    /// `@constant_id = N`: a specialization constant (a `bool`, `int`,
    /// `uint` or `float` the host may set when it creates the pipeline),
    /// with its default. WGSL `override`, SPIR-V `OpSpecConstant`; the
    /// default on GLSL (docs/targets.md, "Specialization constants").
    SpecConstant { id: u32, default: ConstValue },
    /// A module variable (`var angle = 0.0`, no qualifier) a shader reaches:
    /// private to each invocation, starting from `init` (zero when `None`).
    Private { init: Option<ConstValue> },
}

#[derive(Clone, Debug)]
pub struct Global {
    pub name: String,
    pub ty: Ty,
    pub kind: GlobalKind,
    pub span: Span,
    /// Where a uniform or sampler is bound on WGSL/SPIR-V: its `@set = N`
    /// (else group 0) and `@binding = N` (else the lowest free in the
    /// group, in declaration order). A sampler takes two bindings (its
    /// texture, then its sampler), an array of samplers two per element;
    /// the loose uniforms of a group share one binding, their uniform
    /// buffer's (see [`Global::is_loose_uniform`]).
    /// `None` for other globals and for resources no entry point uses.
    pub bind: Option<Bind>,
}

impl Global {
    /// A uniform that is not a struct: a member of its group's uniform
    /// buffer on WGSL/SPIR-V, a plain `uniform T name;` in GLSL.
    /// A uniform, sampler, storage buffer or storage image: what a host
    /// binds.
    pub fn is_resource(&self) -> bool {
        matches!(self.kind, GlobalKind::Uniform { .. } | GlobalKind::Sampler { .. } | GlobalKind::Storage { .. } | GlobalKind::Image { .. })
    }

    pub fn is_loose_uniform(&self) -> bool {
        matches!(self.kind, GlobalKind::Uniform { .. }) && !matches!(self.ty, Ty::Struct(_))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bind {
    pub group: u32,
    pub binding: u32,
}

#[derive(Clone, Debug)]
pub struct Const {
    pub name: String,
    pub ty: Ty,
    pub value: ConstValue,
    pub span: Span,
}

#[derive(Debug)]
pub struct Local {
    pub name: crate::syntax::ast::Name,
    pub ty: Ty,
    pub mutable: bool,
    /// A `var p : T&` parameter: the caller's variable, written through
    /// (GLSL `inout`).
    pub by_ref: bool,
    pub span: Span,
}

#[derive(Debug)]
pub struct Function {
    pub name: String,
    /// The first `params` locals are the parameters.
    pub params: usize,
    pub locals: Vec<Local>,
    pub ret: Ty,
    pub body: Vec<Stmt>,
    pub span: Span,
    /// Globals this function and everything it calls touch, each with the
    /// span of one use (for stage errors).
    pub uses: std::collections::BTreeMap<GlobalId, Span>,
    /// A `discard()` or derivative reached from this function (fragment only).
    pub fragment_only: Option<(Span, &'static str)>,
    /// A subgroup operation reached from this function (not in vertex).
    pub subgroup_op: Option<Span>,
    /// Implicit-LOD sampling (`texture`, `textureCompare`, `textureProj`)
    /// reached from this function: lowered with level 0 when a vertex entry
    /// point reaches it.
    pub implicit_lod: bool,
    /// Helper functions called directly.
    pub callees: std::collections::BTreeSet<FuncId>,
    /// Globals this function's own body passes to a `var p : T&`
    /// parameter, which the call may write.
    pub ref_writes: Vec<GlobalId>,
}

impl Function {
    /// Whether a parameter is a sampler (each call names the one it is).
    pub fn takes_samplers(&self) -> bool {
        self.locals[..self.params].iter().any(|l| matches!(l.ty, Ty::Sampler(_)))
    }
}

#[derive(Debug)]
pub struct EntryPoint {
    pub name: String,
    pub stage: naga::ShaderStage,
    /// The body, with no parameters and no result.
    pub func: Function,
    /// The location of each `@in`, `@out` and `@inout` global this entry
    /// point reads or writes, sorted by global (a few per entry point).
    pub locations: Vec<(GlobalId, u32)>,
    /// A compute entry point's `local_size_x/y/z` (1 where not written);
    /// `[0; 3]` for the other stages.
    pub workgroup_size: [u32; 3],
    /// Its stage annotation (`[compute_program(...)]`), where limits on the
    /// workgroup point.
    pub annotation: Span,
    /// The dialect its stage annotation names: Vulkan-dialect entry points
    /// link stage I/O by location and are written in Vulkan conventions.
    pub dialect: crate::syntax::ast::Dialect,
    /// A mesh entry point's `max_vertices` and `max_primitives` (triangles).
    pub mesh: Option<[u32; 2]>,
}

impl EntryPoint {
    /// The location of interface global `g` in this entry point.
    pub fn location(&self, g: GlobalId) -> u32 {
        self.locations.binary_search_by_key(&g, |&(g, _)| g).map_or(0, |i| self.locations[i].1)
    }
}

#[derive(Clone, Debug)]
pub struct Expr {
    pub kind: ExprKind,
    pub ty: Ty,
    pub span: Span,
}

impl Expr {
    /// An integer known when compiling: a literal or a named constant (an
    /// index that picks one sampler of an array statically).
    pub fn const_int(&self, consts: &[Const]) -> Option<i64> {
        match &self.kind {
            ExprKind::Int(k) => Some(*k),
            ExprKind::Uint(k) => i64::try_from(*k).ok(),
            ExprKind::Const(c) => match consts[*c].value {
                ConstValue::Int(k) => Some(k),
                ConstValue::Uint(k) => i64::try_from(k).ok(),
                _ => None,
            },
            _ => None,
        }
    }
}

impl Expr {
    /// The components of an integer scalar or vector known when compiling:
    /// a literal, a named constant, a negated one, or a constructor of
    /// those (`int2(1, -1)`, `int2(2)`).
    pub fn const_ints(&self, consts: &[Const]) -> Option<arrayvec::ArrayVec<i64, 4>> {
        let mut out = arrayvec::ArrayVec::new();
        match &self.kind {
            ExprKind::Const(c) => match &consts[*c].value {
                ConstValue::Composite(parts) => {
                    for p in parts {
                        match p {
                            ConstValue::Int(k) => out.try_push(*k).ok()?,
                            _ => return None,
                        }
                    }
                }
                ConstValue::Int(k) => out.push(*k),
                _ => return None,
            },
            ExprKind::Unary(UnaryOp::Neg, inner) => {
                for k in inner.const_ints(consts)? {
                    out.push(k.checked_neg()?);
                }
            }
            ExprKind::Construct(parts) => {
                for p in parts {
                    for k in p.const_ints(consts)? {
                        out.try_push(k).ok()?;
                    }
                }
                // A splat: one scalar for every component.
                if let (Ty::Vector(_, n), 1) = (&self.ty, out.len()) {
                    let k = out[0];
                    out.clear();
                    out.extend(std::iter::repeat_n(k, *n as usize));
                }
            }
            _ => out.push(self.const_int(consts)?),
        }
        Some(out)
    }
}

/// A swizzle's component indices (0-3), held inline: no allocation.
pub type Components = arrayvec::ArrayVec<u8, 4>;

#[derive(Clone, Debug)]
pub enum ExprKind {
    Float(f64),
    Int(i64),
    Uint(u64),
    Bool(bool),
    Local(LocalId),
    Global(GlobalId),
    Const(ConstId),
    Unary(UnaryOp, Box<Expr>),
    /// Operands already have matching shapes where naga needs them (a
    /// scalar operand of a vector op is splatted in lowering).
    /// Both operands in one allocation.
    Binary(BinaryOp, Box<(Expr, Expr)>),
    Select { cond: Box<Expr>, accept: Box<Expr>, reject: Box<Expr> },
    Call(FuncId, Vec<Expr>),
    Builtin(Builtin, Vec<Expr>),
    /// Constructor of `Expr::ty` from the arguments: splat, per-component
    /// conversion, concatenation of scalars and vectors, matrices from
    /// columns or scalars, structs, arrays.
    Construct(Vec<Expr>),
    /// Swizzle with 1 to 4 components (1 = a single component).
    Swizzle(Box<Expr>, Components),
    /// Struct field by index.
    Field(Box<Expr>, u32),
    Index(Box<Expr>, Box<Expr>),
    /// The zero value of `Expr::ty` (a field a named construction leaves
    /// out and that has no initial value).
    Zero,
}

#[derive(Debug)]
pub enum Stmt {
    /// `var` (stored in a local variable) or `let` (a named value).
    Local { local: LocalId, init: Option<Expr>, span: Span },
    /// `target op= value`; `op` is `None` for plain `=`.
    Assign { target: Expr, op: Option<BinaryOp>, value: Expr, span: Span },
    Expr(Expr),
    If { cond: Expr, then: Vec<Stmt>, otherwise: Vec<Stmt>, span: Span },
    While { cond: Expr, body: Vec<Stmt>, span: Span },
    /// `for (var in range(start, end))`, counting up by one.
    For { var: LocalId, start: Expr, end: Expr, body: Vec<Stmt>, span: Span },
    Return(Option<Expr>, Span),
    Break(Span),
    Continue(Span),
    Discard(Span),
}
