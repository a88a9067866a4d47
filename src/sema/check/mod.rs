//! Name resolution and type checking of the parsed program.
//!
//! Declarations are checked first (structs, shader globals with their
//! locations and texture units); `let` constants and helper functions are
//! checked on first use, so helper functions land in the output callees
//! first, as naga requires, and recursion is found on the way.
//!
//! The [`Checker`] is defined here; its methods are split by what they check:
//! [`decls`] (structs, globals, types, constants), [`stmts`] (functions,
//! statements, places), [`exprs`] (expressions, calls, operators) and
//! [`programs`] (which entry points form a program; locations and texture
//! units numbered and checked per program), [`math`] (daslang's math
//! module: its constants, `sincos`) and [`targets`] (constructs only some
//! targets have).

mod calls;
mod compute;
mod decls;
mod enums;
mod exprs;
mod folding;
mod loops;
mod math;
mod programs;
mod stmts;
mod subgroup;
mod targets;
mod uniformity;

use std::collections::hash_map::Entry;
use std::collections::BTreeMap;

use super::builtins::{self, Builtin};
use super::consts::{eval_const, ConstEnv};
use super::tree::*;
use super::limits::*;
use super::types::{Access, EnumId, ImageFormat, ImageKind, SamplerKind, Scalar, StructId, Ty, TyDisplay, BOOL, FLOAT, HALF, INT, UINT};
use crate::diag::{suggest, Diagnostic, Diagnostics};
use rustc_hash::{FxHashMap, FxHashSet};
use crate::source::Span;
use crate::syntax::ast::{self, BinaryOp, UnaryOp};

/// Checks a program for every target.
pub fn check(program: &ast::Program, diags: &mut Diagnostics) -> Option<Program> {
    check_for_targets(program, &[], diags)
}

/// Checks a program for the targets requested (empty: all): a construct
/// that only some targets have (`half`) is an error naming the others.
pub fn check_for_targets(program: &ast::Program, targets: &[crate::target::Target], diags: &mut Diagnostics) -> Option<Program> {
    let mut c = Checker::new(program, diags);
    c.targets = if targets.is_empty() { crate::target::Target::ALL.to_vec() } else { targets.to_vec() };
    c.targets_defaulted = targets.is_empty();
    c.vulkan = program.items.iter().any(|i| matches!(i, ast::Item::Function(f) if f.stage_annotation().is_some_and(|(_, s)| s.dialect == ast::Dialect::Vulkan)));
    c.out.vulkan = c.vulkan;
    c.declare();
    c.check_entry_points();
    folding::check_program(&c.out, c.diags);
    if c.saw_barrier {
        uniformity::check_program(&c.out, c.diags);
    }
    compute::check_whole_values(&c.out, c.diags);
    c.link_programs();
    if c.diags.has_errors() {
        None
    } else {
        Some(c.out)
    }
}


/// Where a helper function's checking stands (per declaration: an
/// overloaded name has several).
#[derive(Clone, Copy)]
enum FuncState {
    Unchecked,
    InProgress(Span),
    Done(FuncId),
    Failed,
}

/// A helper's parameter types, resolved before its body is checked (calls
/// pick an overload by them).
struct Signature {
    params: Vec<Ty>,
    /// How many leading parameters a call must give: those after have
    /// default values.
    required: usize,
}

/// The local names visible in a body. Each name maps to its innermost
/// local; a scope's declarations are logged with what they hid and restored
/// when it closes, so a use is one hash lookup however deep the blocks.
#[derive(Default)]
struct Scopes<'a> {
    visible: FxHashMap<&'a str, LocalId>,
    shadowed: Vec<(&'a str, Option<LocalId>)>,
    /// For each open scope: its start in `shadowed` and its first local.
    open: Vec<(usize, LocalId)>,
}

/// A `with (subject)` block being checked: its fields are names inside.
struct WithScope {
    /// The subject, safe to evaluate again at each use (`loops::stable`).
    subject: Expr,
    id: StructId,
}

/// Per-function state while checking a body.
struct FnCtx<'a> {
    locals: Vec<Local>,
    scopes: Scopes<'a>,
    ret: Ty,
    /// No declared result: the first `return` decides it (its span here).
    infer_ret: bool,
    ret_from: Option<Span>,
    /// Checking an entry point (its `return` takes no value).
    entry: bool,
    /// Loop variables that stand for an element of an iterated array
    /// (`for (x in arr)`): each use is this expression.
    aliases: FxHashMap<LocalId, Expr>,
    withs: Vec<WithScope>,
    /// Locals before this one are the parameters (which `with` fields hide).
    params: LocalId,
    ref_writes: Vec<GlobalId>,
    loop_depth: usize,
    uses: BTreeMap<GlobalId, Span>,
    fragment_only: Option<(Span, &'static str)>,
    /// A subgroup operation reached (none in vertex entry points).
    subgroup_op: Option<Span>,
    implicit_lod: bool,
    callees: std::collections::BTreeSet<FuncId>,
    depth: usize,
}

impl<'a> FnCtx<'a> {
    /// A context for a body returning `ret`, starting at call depth
    /// `depth`, with room for `locals`.
    fn new(scopes: Scopes<'a>, ret: Ty, depth: usize, locals: usize) -> Self {
        let mut cx = FnCtx {
            locals: Vec::with_capacity(locals),
            scopes,
            ret,
            infer_ret: false,
            ret_from: None,
            entry: false,
            aliases: FxHashMap::default(),
            withs: Vec::new(),
            params: 0,
            ref_writes: Vec::new(),
            loop_depth: 0,
            uses: BTreeMap::new(),
            fragment_only: None,
            subgroup_op: None,
            implicit_lod: false,
            callees: Default::default(),
            depth,
        };
        // The parameters' scope.
        cx.scopes.open.push((0, 0));
        cx
    }

    fn open_scope(&mut self) {
        let s = &mut self.scopes;
        s.open.push((s.shadowed.len(), self.locals.len()));
    }

    fn close_scope(&mut self) {
        let s = &mut self.scopes;
        let (start, _) = s.open.pop().expect("a scope is open");
        // Newest first, so a name declared twice gets back its first hidden local.
        for (name, hidden) in s.shadowed.drain(start..).rev() {
            match hidden {
                Some(id) => s.visible.insert(name, id),
                None => s.visible.remove(name),
            };
        }
    }

    fn declare(&mut self, name: &'a str, local: LocalId) {
        let hidden = self.scopes.visible.insert(name, local);
        self.scopes.shadowed.push((name, hidden));
    }

    fn lookup(&self, name: &str) -> Option<LocalId> {
        self.scopes.visible.get(name).copied()
    }

    /// The local `name` refers to, if it was declared in the innermost scope
    /// (locals are numbered in order, and closed scopes are no longer visible).
    fn in_innermost_scope(&self, name: &str) -> Option<LocalId> {
        let first = self.scopes.open.last().map_or(0, |s| s.1);
        self.lookup(name).filter(|&id| id >= first)
    }
}

struct Checker<'a, 'd> {
    ast: &'a ast::Program,
    diags: &'d mut Diagnostics,
    out: Program,
    // Names are borrowed from the syntax tree.
    structs: FxHashMap<&'a str, StructId>,
    globals: FxHashMap<&'a str, GlobalId>,
    enums: FxHashMap<&'a str, EnumId>,
    consts: FxHashMap<&'a str, ConstId>,
    const_decls: FxHashMap<&'a str, &'a ast::ConstDecl>,
    const_in_progress: Vec<&'a str>,
    /// Constants already reported as wrong: their uses report nothing more.
    failed_consts: FxHashSet<&'a str>,
    /// Helper function names and their declarations (indices into
    /// `fn_decls`; several for an overloaded name).
    funcs: FxHashMap<&'a str, Vec<usize>>,
    fn_decls: Vec<&'a ast::FunctionDecl>,
    fn_states: Vec<FuncState>,
    fn_sigs: Vec<Option<Option<std::rc::Rc<Signature>>>>,
    /// Per struct, per field: its initial value, if declared (empty for a
    /// struct without any).
    field_inits: Vec<Vec<Option<&'a ast::Expr>>>,
    /// Initial values being checked (struct, field): one that needs itself
    /// is an error, not an endless recursion.
    inits_in_progress: Vec<(StructId, usize)>,
    /// Initial values already reported as wrong: their uses report nothing more.
    failed_inits: FxHashSet<(StructId, usize)>,
    entry_decls: Vec<(&'a ast::FunctionDecl, naga::ShaderStage)>,
    builtin_vars: FxHashMap<BuiltinVar, GlobalId>,
    /// Per struct, its field names' indices.
    field_index: Vec<FxHashMap<&'a str, u32>>,
    /// The `@location = N` qualifier of each global that has one, and the
    /// `@stage = N` of each sampler that has one (for clash diagnostics).
    location_spans: FxHashMap<GlobalId, Span>,
    unit_spans: FxHashMap<GlobalId, Span>,
    /// The `@set = N` and `@binding = N` written on a resource.
    bind_written: FxHashMap<GlobalId, (Option<(u32, Span)>, Option<(u32, Span)>)>,
    /// Depth at which the next helper function checked on first use starts.
    call_depth: usize,
    spare_scopes: Vec<Scopes<'a>>,
    /// The targets requested, for the constructs only some have.
    targets: Vec<crate::target::Target>,
    /// No target was named: every one that can run the program is made
    /// (`Target::defaults`), so compute constructs refuse no target.
    targets_defaulted: bool,
    /// A barrier call was checked: only then is the uniformity pass run
    /// (it walks every body, and most programs have no barrier).
    saw_barrier: bool,
    /// `half` was refused already (reported once, at its first use).
    half_refused: bool,
    /// Constructs already refused for the targets lacking them (one error
    /// each, at the first use): `targets::lacking_targets_used`.
    refused_constructs: std::collections::BTreeSet<&'static str>,
    /// Compute constructs were refused already (once, at the first).
    compute_refused: bool,
    /// The program has Vulkan-dialect entry points (`Program::vulkan`).
    vulkan: bool,
    /// The `local_size_*` of the compute entry point being checked
    /// (`gl_WorkGroupSize` there); `[0; 3]` elsewhere.
    entry_workgroup_size: [u32; 3],
    /// The stage of the entry point being checked (helpers: its caller's).
    entry_stage: Option<naga::ShaderStage>,
}

fn is_entry(f: &ast::FunctionDecl) -> Option<naga::ShaderStage> {
    f.stage_annotation().and_then(|(_, s)| s.stage)
}

fn entry_name(f: &ast::FunctionDecl) -> String {
    for a in &f.annotations {
        for arg in &a.args {
            if arg.name.name == "name" {
                match &arg.value {
                    Some(ast::Expr { kind: ast::ExprKind::Str(s), .. }) => return s.clone(),
                    Some(ast::Expr { kind: ast::ExprKind::Name(id), .. }) => return id.name.as_str().to_string(),
                    _ => {}
                }
            }
        }
    }
    f.name.name.as_str().to_string()
}

impl<'a, 'd> Checker<'a, 'd> {
    fn new(ast: &'a ast::Program, diags: &'d mut Diagnostics) -> Self {
        Checker {
            ast,
            diags,
            out: Program::default(),
            structs: FxHashMap::default(),
            globals: FxHashMap::default(),
            enums: FxHashMap::default(),
            consts: FxHashMap::default(),
            const_decls: FxHashMap::default(),
            const_in_progress: Vec::new(),
            failed_consts: FxHashSet::default(),
            funcs: FxHashMap::default(),
            fn_decls: Vec::new(),
            fn_states: Vec::new(),
            fn_sigs: Vec::new(),
            field_inits: Vec::new(),
            inits_in_progress: Vec::new(),
            failed_inits: FxHashSet::default(),
            entry_decls: Vec::new(),
            builtin_vars: FxHashMap::default(),
            field_index: Vec::new(),
            location_spans: FxHashMap::default(),
            unit_spans: FxHashMap::default(),
            bind_written: FxHashMap::default(),
            call_depth: 0,
            spare_scopes: Vec::new(),
            targets: crate::target::Target::ALL.to_vec(),
            targets_defaulted: true,
            vulkan: false,
            saw_barrier: false,
            compute_refused: false,
            entry_workgroup_size: [0; 3],
            entry_stage: None,
            half_refused: false,
            refused_constructs: Default::default(),
        }
    }

    fn show(&self, ty: &Ty) -> String {
        let names: Vec<String> = self.out.structs.iter().map(|s| s.name.clone()).collect();
        let enum_names = self.out.enum_names();
        TyDisplay { ty, struct_names: &names, enum_names: &enum_names }.to_string()
    }

    /// Reports a name defined twice at top level.
    fn check_unique(&mut self, seen: &mut FxHashMap<&'a str, Span>, id: &'a ast::Ident) {
        match seen.entry(&id.name) {
            Entry::Occupied(prev) => {
                let d = Diagnostic::error(format!("`{}` is defined more than once", id.name), id.span)
                    .with_label("defined again here")
                    .with_secondary(*prev.get(), "first defined here");
                self.diags.push(d);
            }
            Entry::Vacant(v) => {
                v.insert(id.span);
            }
        }
    }
}

impl Checker<'_, '_> {
    /// The error for a name one of daslang's builtin-declaring modules
    /// declares and umbrac does not implement (`syntax::modules`), if
    /// `name` is one: refused by name, never compiled from its CPU body.
    fn unsupported_daslang_builtin(&self, name: &str, span: Span) -> Option<Diagnostic> {
        let b = self.ast.daslang_builtins.iter().find(|b| b.name == name)?;
        let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
        let d = Diagnostic::error(format!("`{name}` (a builtin of daslang's `{}`) is not supported by umbrac on {}", b.module, targets.join(", ")), span)
            .with_label("not supported")
            .with_secondary(b.span, "daslang declares it here")
            .with_note("help: umbrac compiles the builtins it implements under their daslang names, and refuses the others rather than translate their CPU stand-ins; write it from supported builtins");
        Some(d)
    }

    /// An error about a name nothing defines, with each required module
    /// that was not found, which might have defined it.
    fn with_missing_modules(&self, mut d: Diagnostic) -> Diagnostic {
        for m in &self.ast.modules_not_found {
            d = d.with_secondary(m.span, format!("module `{}` not found: it may define this", m.name));
            let searched: Vec<String> = m.searched.iter().map(|p| format!("`{}`", p.display())).collect();
            let searched = if searched.is_empty() { "nowhere".to_string() } else { searched.join(", ") };
            d = d.with_note(format!("module `{}` was not found (searched {searched}); help: {}", m.name, m.help));
        }
        d
    }
}

/// A placeholder for an expression already reported as wrong (type `Error`:
/// its uses report nothing more).
pub(super) fn err_expr(span: Span) -> Expr {
    Expr { kind: ExprKind::Bool(false), ty: Ty::Error, span }
}

pub fn op_text(op: BinaryOp) -> &'static str {
    use BinaryOp::*;
    match op {
        Add => "+",
        Sub => "-",
        Mul => "*",
        Div => "/",
        Mod => "%",
        Eq => "==",
        Ne => "!=",
        Lt => "<",
        Le => "<=",
        Gt => ">",
        Ge => ">=",
        And => "&&",
        Or => "||",
        Xor => "^^",
        BitAnd => "&",
        BitOr => "|",
        BitXor => "^",
        Shl => "<<",
        Shr => ">>",
    }
}

/// The built-in type names, offered when a type or constructor name is misspelt.
const TYPE_NAMES: &[&str] = &[
    "float", "float2", "float3", "float4", "int", "int2", "int3", "int4", "uint", "uint2", "uint3", "uint4", "bool", "bool2", "bool3", "bool4", "half", "half2", "half3", "half4", "float2x2",
    "float3x3", "float4x4", "sampler2D", "sampler2DShadow", "sampler2DArray", "sampler2DArrayShadow", "sampler3D", "samplerCube", "samplerCubeShadow",
];
