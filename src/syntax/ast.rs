//! The syntax tree the parser hands to semantic analysis.
//!
//! It holds only what the shaders need: every shader global (`var` with
//! `@uniform`, `@in`, `@out` or `@inout`), the functions annotated
//! `[vertex_program]` / `[fragment_program]`, and the functions, `let`
//! constants and structs they reach. Host code is skipped by the parser and
//! never appears here. Every node carries a [`Span`].

use std::path::PathBuf;

pub use super::token::Name;
use crate::source::Span;

#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    pub name: Name,
    pub span: Span,
}

/// The names one declaration declares (`var a, b : float3` has two). The
/// first is inline: nearly every declaration has just one, and then
/// nothing is allocated.
#[derive(Clone, Debug)]
pub struct Names {
    pub first: Ident,
    pub rest: Vec<Ident>,
}

impl Names {
    pub fn count(&self) -> usize {
        1 + self.rest.len()
    }

    pub fn iter(&self) -> impl Iterator<Item = &Ident> {
        std::iter::once(&self.first).chain(&self.rest)
    }
}

impl IntoIterator for Names {
    type Item = Ident;
    type IntoIter = std::iter::Chain<std::iter::Once<Ident>, std::vec::IntoIter<Ident>>;
    fn into_iter(self) -> Self::IntoIter {
        std::iter::once(self.first).chain(self.rest)
    }
}

#[derive(Clone, Debug, Default)]
pub struct Program {
    /// Items in source order.
    pub items: Vec<Item>,
    /// Required modules that were not found, for the checker's errors
    /// about names nothing defines.
    pub modules_not_found: Vec<MissingModule>,
    /// Names daslang's builtin-declaring modules declare.
    pub daslang_builtins: Vec<DaslangBuiltin>,
}

#[derive(Clone, Debug)]
pub enum Item {
    Global(GlobalVar),
    Const(ConstDecl),
    Function(FunctionDecl),
    Struct(StructDecl),
    Enum(EnumDecl),
}

/// `[name]` or `[name(key = value, flag, ...)]` before a `def` or `struct`.
#[derive(Clone, Debug)]
pub struct Annotation {
    pub name: Ident,
    pub args: Vec<AnnotationArg>,
    pub span: Span,
}

/// Which of daslang's two shader dialects an entry point is written in:
/// the GL one (`[vertex_program]`, GL conventions, varyings by name) or
/// dasSpirv's Vulkan one (`[vertex_shader]`, `[vulkan_vertex_shader]`,
/// Vulkan conventions, stage I/O by `@location`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Dialect {
    #[default]
    Gl,
    Vulkan,
}

/// What a stage annotation names: the stage (`None` for a stage of the
/// Vulkan dialect umbrac does not compile: ray tracing) and the dialect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StageAnnotation {
    pub stage: Option<naga::ShaderStage>,
    pub dialect: Dialect,
}

/// The stages of dasSpirv/dasVulkan umbrac recognises but does not compile,
/// with the name of the stage (for the refusal).
pub const UNCOMPILED_STAGES: &[(&str, &str)] = &[
    ("vulkan_raygen_shader", "ray generation"),
    ("vulkan_miss_shader", "miss"),
    ("vulkan_closest_hit_shader", "closest-hit"),
    ("vulkan_any_hit_shader", "any-hit"),
    ("vulkan_intersection_shader", "intersection"),
    ("vulkan_callable_shader", "callable"),
];

/// The one table of stage annotations: every place that asks "is this an
/// entry point, of which stage and dialect" asks here.
pub fn stage_annotation(name: &str) -> Option<StageAnnotation> {
    use naga::ShaderStage as S;
    let (stage, dialect) = match name {
        "vertex_program" => (Some(S::Vertex), Dialect::Gl),
        "fragment_program" => (Some(S::Fragment), Dialect::Gl),
        "compute_program" => (Some(S::Compute), Dialect::Gl),
        "vertex_shader" | "vulkan_vertex_shader" => (Some(S::Vertex), Dialect::Vulkan),
        "fragment_shader" | "vulkan_fragment_shader" => (Some(S::Fragment), Dialect::Vulkan),
        "compute_shader" | "vulkan_compute_shader" => (Some(S::Compute), Dialect::Vulkan),
        "mesh_shader" | "vulkan_mesh_shader" => (Some(S::Mesh), Dialect::Vulkan),
        "task_shader" | "vulkan_task_shader" => (Some(S::Task), Dialect::Vulkan),
        _ if UNCOMPILED_STAGES.iter().any(|&(a, _)| a == name) => (None, Dialect::Vulkan),
        _ => return None,
    };
    Some(StageAnnotation { stage, dialect })
}

impl FunctionDecl {
    /// The entry point annotation, if any, and what it names.
    pub fn stage_annotation(&self) -> Option<(&Annotation, StageAnnotation)> {
        self.annotations.iter().find_map(|a| stage_annotation(&a.name.name).map(|s| (a, s)))
    }
}

#[derive(Clone, Debug)]
pub struct AnnotationArg {
    pub name: Ident,
    /// `None` for a bare flag.
    pub value: Option<Expr>,
}

/// `var @uniform @location = 1 name : type [= init]` at top level, or a
/// module variable without qualifiers (`var angle = 0.0`, also inside a
/// `var { ... }` block), whose type may come from its initialiser.
#[derive(Clone, Debug)]
pub struct GlobalVar {
    pub qualifiers: Vec<Qualifier>,
    pub name: Ident,
    /// `None` only for a module variable with an initialiser.
    pub ty: Option<TypeExpr>,
    pub init: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Qualifier {
    pub kind: QualifierKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum QualifierKind {
    Uniform,
    In,
    Out,
    InOut,
    /// `@location = N`, or bare `@location` (`None`: the compiler assigns it).
    Location(Option<i64>),
    /// `@stage = N`: the GL unit of a sampler (texture unit), storage
    /// image (image unit) or `@ssbo` (binding point); bare `@stage`
    /// (`None`): the compiler assigns it.
    Stage(Option<i64>),
    /// `@set = N`: the bind group of a uniform or sampler on WGSL/SPIR-V.
    Set(i64),
    /// `@binding = N`: its binding in that group.
    Binding(i64),
    /// `@format = NAME` or `@format = "NAME"`: a storage image's texel
    /// format (`rgba8`, `r32f`); bare `@format` is `rgba8`, as in dasGlsl.
    Format(Ident),
    /// `@constant_id = N`: a specialization constant's id (dasSpirv).
    ConstantId(i64),
    /// Any other `@name [= value]`; semantic analysis reports it.
    Other(String),
}

/// `let NAME [: type] = value` at top level (one of a `let { ... }` block too).
#[derive(Clone, Debug)]
pub struct ConstDecl {
    pub name: Ident,
    pub ty: Option<TypeExpr>,
    pub value: Expr,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct FunctionDecl {
    pub annotations: Vec<Annotation>,
    pub name: Ident,
    pub params: Vec<Param>,
    /// `None` for `def f { ... }` / `def f(...) { ... }` with no `: type`.
    pub ret: Option<TypeExpr>,
    pub body: Block,
    pub span: Span,
}

/// One parameter. `def f(a, b : float3; uv : float2)` gives three params.
#[derive(Clone, Debug)]
pub struct Param {
    pub name: Ident,
    pub ty: TypeExpr,
    pub span: Span,
    /// `var a : T`: a mutable copy (or, with `&`, a reference it writes).
    pub mutable: bool,
    /// `a : T&`: passed by reference (with `var`, GLSL `inout`).
    pub by_ref: bool,
    /// `a : T const`, where written (parameters are immutable anyway).
    pub constant: Option<Span>,
    /// `a : T = value`: filled in at calls that leave it out.
    pub default: Option<Expr>,
}

#[derive(Clone, Debug)]
pub struct StructDecl {
    pub annotations: Vec<Annotation>,
    pub name: Ident,
    pub fields: Vec<Field>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Field {
    pub name: Ident,
    /// `None` for `x = value`: the type is the value's.
    pub ty: Option<TypeExpr>,
    /// `x : T = value`: the field's value where a construction leaves it out.
    pub init: Option<Expr>,
    pub span: Span,
}

/// `enum Name [: base] { A; B = value; ... }`.
#[derive(Clone, Debug)]
pub struct EnumDecl {
    pub name: Ident,
    /// The storage type (`int` when not written).
    pub base: Option<Ident>,
    pub values: Vec<(Ident, Option<Expr>)>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct TypeExpr {
    pub kind: TypeExprKind,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub enum TypeExprKind {
    /// `float3`, `sampler2DShadow`, `MyStruct`, ...
    Named(Ident),
    /// `T[N]`.
    Array(Box<TypeExpr>, Box<Expr>),
    /// `T[]`: sized by the buffer bound (an `@ssbo`'s last member).
    RuntimeArray(Box<TypeExpr>),
}

#[derive(Clone, Debug)]
pub struct Block {
    pub stmts: Vec<Stmt>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AssignOp {
    Set,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    BitAnd,
    BitOr,
    BitXor,
    Shl,
    Shr,
}

#[derive(Clone, Debug)]
pub enum StmtKind {
    /// `let` (immutable) or `var` (mutable); several names share the type
    /// and initialiser (`var a, b : int`).
    Local { mutable: bool, names: Names, ty: Option<TypeExpr>, init: Option<Expr> },
    Assign { target: Expr, op: AssignOp, value: Expr },
    /// An expression statement: a call, `i++`, `--j`.
    Expr(Expr),
    If { cond: Expr, then: Block, elifs: Vec<(Expr, Block)>, otherwise: Option<Block> },
    While { cond: Expr, body: Block },
    /// `for (a, b in x, y) body`: one variable per iterated source (a
    /// `range(...)` or an array), walked in parallel.
    For { vars: Vec<Ident>, iters: Vec<Expr>, body: Block },
    /// `with (subject) body`: the subject's fields are names in the body.
    With { subject: Expr, body: Block },
    Return(Option<Expr>),
    Break,
    Continue,
    Block(Block),
    /// `f(args) $ { ... }` (or `f(args) <| $ { ... }`, `f($ { ... })`): a
    /// call with daslang's block argument; in a shader only `unroll`.
    CallBlock { callee: Ident, args: Vec<Expr>, body: Block },
}

#[derive(Clone, Debug)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
    BitNot,
    PreInc,
    PreDec,
    PostInc,
    PostDec,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
    /// `^^`, logical exclusive or.
    Xor,
    BitAnd,
    BitOr,
    BitXor,
    Shl,
    Shr,
}

/// Suffix of an integer literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntSuffix {
    /// No suffix: `int`.
    None,
    /// `u` / `U`: `uint`.
    Unsigned,
}

#[derive(Clone, Debug)]
pub enum ExprKind {
    Int(u64, IntSuffix),
    Float(f64),
    Bool(bool),
    Name(Ident),
    Unary(UnaryOp, Box<Expr>),
    /// `lhs op rhs`: both operands in one allocation.
    Binary(BinaryOp, Box<(Expr, Expr)>),
    /// `cond ? a : b`
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `name(args)`: functions, builtins, constructors (`float3(...)`,
    /// `MyStruct(...)`), casts (`float(i)`).
    Call { callee: Ident, args: Vec<Expr> },
    /// `base.name`: struct fields and swizzles.
    Field(Box<Expr>, Ident),
    Index(Box<Expr>, Box<Expr>),
    /// `[a, b, c]` (no element type) or `fixed_array<T>(a, b, c)`.
    Array { elem: Option<TypeExpr>, items: Vec<Expr> },
    /// `(e)`: kept so diagnostics can point at the whole parenthesised text.
    Paren(Box<Expr>),
    /// A string literal, escapes resolved. The parser produces it only as an
    /// annotation argument value (`[vertex_program(name = "x")]`).
    Str(String),
    /// `name = value` as a call argument: a field of a struct construction
    /// (`Light(color = c, k = 1.0)`).
    Named(Ident, Box<Expr>),
    /// A `half` literal (`1.5h`): its value, rounded once from the decimal
    /// to the nearest binary16 value (held exactly in the `f64`).
    Half(f64),
    /// `reinterpret<T>(x)`: `x`'s bits as a `T` of the same size.
    Reinterpret(Ident, Box<Expr>),
}

/// A name one of daslang's builtin-declaring modules declares
/// (`syntax::modules::BUILTIN_DECLARING`): umbrac's builtin of that name
/// is meant, and one umbrac lacks is refused by name.
#[derive(Clone, Debug)]
pub struct DaslangBuiltin {
    pub name: String,
    /// `shader_lingua_franca`, ...
    pub module: String,
    /// The declaration's name.
    pub span: Span,
}

/// A required module that was not found, for the checker's errors about
/// unknown names.
#[derive(Clone, Debug)]
pub struct MissingModule {
    /// As written: `shaderlib/lighting`.
    pub name: String,
    /// The module name in the `require` line.
    pub span: Span,
    /// The files looked for.
    pub searched: Vec<PathBuf>,
    /// What to do about it.
    pub help: &'static str,
}
