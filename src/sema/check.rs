//! Name resolution and type checking of the parsed program.
//!
//! Declarations are checked first (structs, shader globals with their
//! locations and texture units); `let` constants and helper functions are
//! checked on first use, so helper functions land in the output callees
//! first, as naga requires, and recursion is found on the way.

use std::collections::hash_map::Entry;
use std::collections::BTreeMap;

use super::builtins::{self, Builtin};
use super::consts::{eval_const, ConstEnv};
use super::tree::*;
use super::types::{Scalar, StructId, Ty, TyDisplay, BOOL, FLOAT, INT, UINT};
use crate::diag::{suggest, Diagnostic, Diagnostics};
use rustc_hash::{FxHashMap, FxHashSet};
use crate::lower::SamplerKind;
use crate::source::Span;
use crate::syntax::ast::{self, BinaryOp, UnaryOp};

/// Largest `T[N]` accepted.
pub const MAX_ARRAY_LEN: u64 = 65_536;
/// Highest `@location` accepted (exclusive).
pub const MAX_LOCATIONS: u32 = 16;
/// Nesting depth of expressions and blocks the checker follows. A call of a
/// helper function that is checked on first use starts the callee at the
/// caller's depth plus [`CALL_DEPTH`], so chains of calls count too.
pub const MAX_DEPTH: usize = 256;
/// Depth one level of calls adds (the checker recurses into the callee).
pub const CALL_DEPTH: usize = 4;
/// Longest chain of constants defined in terms of each other.
pub const MAX_CONST_CHAIN: usize = 64;
/// Deepest nesting of struct and array types (`S { t : T[2] }` is 2).
pub const MAX_TYPE_DEPTH: usize = 32;

pub fn check(program: &ast::Program, diags: &mut Diagnostics) -> Option<Program> {
    let mut c = Checker::new(program, diags);
    c.declare();
    c.check_entry_points();
    if c.diags.has_errors() {
        None
    } else {
        Some(c.out)
    }
}

/// Size and alignment of a type in a WGSL uniform block (natural layout) and
/// under GLSL std140.
struct UniformLayout {
    size: u32,
    align: u32,
    std_size: u32,
    std_align: u32,
}

enum FuncState {
    Unchecked(usize),
    InProgress(Span),
    Done(FuncId),
    Failed,
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

/// Per-function state while checking a body.
struct FnCtx<'a> {
    locals: Vec<Local>,
    scopes: Scopes<'a>,
    ret: Ty,
    loop_depth: usize,
    uses: BTreeMap<GlobalId, Span>,
    fragment_only: Option<(Span, &'static str)>,
    implicit_lod: bool,
    callees: std::collections::BTreeSet<FuncId>,
    depth: usize,
}

impl<'a> FnCtx<'a> {
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
    consts: FxHashMap<&'a str, ConstId>,
    const_decls: FxHashMap<&'a str, &'a ast::ConstDecl>,
    const_in_progress: Vec<&'a str>,
    /// Constants already reported as wrong: their uses report nothing more.
    failed_consts: FxHashSet<&'a str>,
    funcs: FxHashMap<&'a str, FuncState>,
    fn_decls: Vec<&'a ast::FunctionDecl>,
    entry_decls: Vec<(&'a ast::FunctionDecl, naga::ShaderStage)>,
    builtin_vars: FxHashMap<BuiltinVar, GlobalId>,
    /// Depth at which the next helper function checked on first use starts.
    call_depth: usize,
    spare_scopes: Vec<Scopes<'a>>,
}

fn is_entry(f: &ast::FunctionDecl) -> Option<naga::ShaderStage> {
    f.annotations.iter().find_map(|a| match a.name.name.as_str() {
        "vertex_program" => Some(naga::ShaderStage::Vertex),
        "fragment_program" => Some(naga::ShaderStage::Fragment),
        _ => None,
    })
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
            consts: FxHashMap::default(),
            const_decls: FxHashMap::default(),
            const_in_progress: Vec::new(),
            failed_consts: FxHashSet::default(),
            funcs: FxHashMap::default(),
            fn_decls: Vec::new(),
            entry_decls: Vec::new(),
            builtin_vars: FxHashMap::default(),
            call_depth: 0,
            spare_scopes: Vec::new(),
        }
    }

    fn show(&self, ty: &Ty) -> String {
        let names: Vec<String> = self.out.structs.iter().map(|s| s.name.clone()).collect();
        TyDisplay { ty, struct_names: &names }.to_string()
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

    // ---------------------------------------------------------------- declarations

    fn declare(&mut self) {
        let items = &self.ast.items;
        // Sized once: these tables are filled in one go.
        let mut counts = [0usize; 4];
        for item in items {
            counts[match item {
                ast::Item::Struct(_) => 0,
                ast::Item::Global(_) => 1,
                ast::Item::Const(_) => 2,
                ast::Item::Function(_) => 3,
            }] += 1;
        }
        self.structs.reserve(counts[0]);
        self.globals.reserve(counts[1]);
        self.const_decls.reserve(counts[2]);
        self.consts.reserve(counts[2]);
        self.funcs.reserve(counts[3]);
        let mut seen: FxHashMap<&'a str, Span> = FxHashMap::with_capacity_and_hasher(items.len(), Default::default());
        // Struct names first, so fields and globals can use any struct.
        for item in items {
            if let ast::Item::Struct(s) = item {
                self.check_unique(&mut seen, &s.name);
                self.structs.insert(&s.name.name, self.out.structs.len());
                self.out.structs.push(StructDef { name: s.name.name.as_str().to_string(), fields: Vec::new(), span: s.span });
            }
        }
        for item in items {
            match item {
                ast::Item::Struct(s) => {
                    let id = self.structs[s.name.name.as_str()];
                    let mut fields: Vec<(String, Ty, Span)> = Vec::new();
                    for f in &s.fields {
                        let ty = self.resolve_type(&f.ty);
                        if let Some((_, _, prev)) = fields.iter().find(|(n, _, _)| *n == *f.name.name) {
                            let d = Diagnostic::error(format!("field `{}` is declared twice", f.name.name), f.name.span)
                                .with_secondary(*prev, "first declared here");
                            self.diags.push(d);
                        }
                        if !ty.is_value() && !ty.is_error() {
                            let d = Diagnostic::error(format!("a struct field cannot have type `{}`", self.show(&ty)), f.ty.span);
                            self.diags.push(d);
                        }
                        fields.push((f.name.name.as_str().to_string(), ty, f.name.span));
                    }
                    if fields.is_empty() {
                        let d = Diagnostic::error(format!("struct `{}` has no fields", s.name.name), s.name.span);
                        self.diags.push(d);
                    }
                    self.out.structs[id].fields = fields;
                }
                ast::Item::Const(k) => {
                    self.check_unique(&mut seen, &k.name);
                    self.const_decls.insert(&k.name.name, k);
                }
                ast::Item::Function(f) => {
                    self.check_unique(&mut seen, &f.name);
                    match is_entry(f) {
                        Some(stage) => {
                            if !f.params.is_empty() || f.ret.is_some() {
                                let d = Diagnostic::error(format!("entry point `{}` cannot take parameters or return a value", f.name.name), f.name.span)
                                    .with_note("entry points read `@in`/`@inout` globals and write `@out`/`@inout` globals and `gl_Position`");
                                self.diags.push(d);
                            }
                            self.entry_decls.push((f, stage));
                        }
                        None => {
                            self.funcs.insert(&f.name.name, FuncState::Unchecked(self.fn_decls.len()));
                            self.fn_decls.push(f);
                        }
                    }
                }
                ast::Item::Global(_) => {}
            }
        }
        self.check_struct_recursion();
        self.declare_globals(&mut seen);
    }

    /// Finds structs that contain themselves and structs nested deeper than
    /// [`MAX_TYPE_DEPTH`], reporting each and clearing its fields so later
    /// passes (which recurse through types) stay finite and shallow.
    fn check_struct_recursion(&mut self) {
        // Struct ids a type mentions, looking through arrays, with the array
        // levels on the way.
        fn edges(ty: &Ty, arrays: usize, out: &mut Vec<(StructId, usize)>) -> usize {
            match ty {
                Ty::Struct(id) => {
                    out.push((*id, arrays));
                    0
                }
                Ty::Array(elem, _) => edges(elem, arrays + 1, out),
                _ => arrays,
            }
        }
        #[derive(Clone, Copy, PartialEq)]
        enum State {
            New,
            Open,
            Done(usize),
        }
        let n = self.out.structs.len();
        let mut state = vec![State::New; n];
        let mut bad: Vec<(StructId, bool)> = Vec::new();
        // Iterative depth-first search: (struct, index of the next field edge).
        for root in 0..n {
            if state[root] != State::New {
                continue;
            }
            let mut stack: Vec<(StructId, Vec<(StructId, usize)>, usize, usize)> = Vec::new();
            let push = |id: StructId, structs: &[StructDef], state: &mut [State]| {
                let mut es = Vec::new();
                let mut depth = 1;
                for (_, t, _) in &structs[id].fields {
                    depth = depth.max(1 + edges(t, 0, &mut es));
                }
                state[id] = State::Open;
                (id, es, 0, depth)
            };
            stack.push(push(root, &self.out.structs, &mut state));
            while let Some(top) = stack.last_mut() {
                let (id, es, next, depth) = top;
                if let Some(&(child, arrays)) = es.get(*next) {
                    *next += 1;
                    match state[child] {
                        State::Done(d) => *depth = (*depth).max(1 + arrays + d),
                        State::Open => {
                            if !bad.iter().any(|(b, _)| *b == child) {
                                bad.push((child, true));
                            }
                        }
                        State::New => {
                            let frame = push(child, &self.out.structs, &mut state);
                            stack.push(frame);
                        }
                    }
                    continue;
                }
                let (id, d) = (*id, *depth);
                state[id] = State::Done(d);
                stack.pop();
                if d > MAX_TYPE_DEPTH && !bad.iter().any(|(b, _)| *b == id) {
                    bad.push((id, false));
                }
                if let Some(parent) = stack.last_mut() {
                    let arrays = parent.1[parent.2 - 1].1;
                    parent.3 = parent.3.max(1 + arrays + d);
                }
            }
        }
        bad.sort();
        for (id, cycle) in bad {
            let s = &self.out.structs[id];
            let d = if cycle {
                Diagnostic::error(format!("struct `{}` contains itself", s.name), s.span)
            } else {
                Diagnostic::error(format!("struct `{}` nests struct and array types deeper than the limit of {MAX_TYPE_DEPTH}", s.name), s.span)
            };
            self.diags.push(d);
            for f in &mut self.out.structs[id].fields {
                f.1 = Ty::Error;
            }
        }
    }

    fn declare_globals(&mut self, seen: &mut FxHashMap<&'a str, Span>) {
        // Explicit locations / texture units first, per interface class, so
        // automatic ones fill the gaps.
        let mut taken: FxHashMap<&'static str, FxHashMap<u32, Span>> = FxHashMap::default();
        let mut pending_auto: Vec<(GlobalId, &'static str, u32)> = Vec::new();
        let items = &self.ast.items;
        for item in items {
            let ast::Item::Global(g) = item else { continue };
            self.check_unique(seen, &g.name);
            if BuiltinVar::from_name(&g.name.name).is_some() || g.name.name.starts_with("gl_") {
                let d = Diagnostic::error(format!("`{}` is reserved for builtin variables", g.name.name), g.name.span);
                self.diags.push(d);
            }
            let ty = self.resolve_type(&g.ty);
            let mut class: Option<(&'static str, Span)> = None;
            let mut location: Option<(i64, Span)> = None;
            let mut stage: Option<(i64, Span)> = None;
            for q in &g.qualifiers {
                let c = match &q.kind {
                    ast::QualifierKind::Uniform => Some("uniform"),
                    ast::QualifierKind::In => Some("in"),
                    ast::QualifierKind::Out => Some("out"),
                    ast::QualifierKind::InOut => Some("inout"),
                    ast::QualifierKind::Location(l) => {
                        if let Some(l) = l {
                            location = Some((*l, q.span));
                        }
                        None
                    }
                    ast::QualifierKind::Stage(s) => {
                        stage = Some((*s, q.span));
                        None
                    }
                    ast::QualifierKind::Other(name) => {
                        let d = Diagnostic::error(format!("unknown annotation `@{name}`"), q.span)
                            .with_note("shader globals take @uniform, @in, @out, @inout, @location = N and @stage = N");
                        self.diags.push(d);
                        None
                    }
                };
                if let Some(c) = c {
                    if let Some((prev, prev_span)) = class {
                        let d = Diagnostic::error(format!("`@{c}` conflicts with `@{prev}`"), q.span).with_secondary(prev_span, "already declared here");
                        self.diags.push(d);
                    } else {
                        class = Some((c, q.span));
                    }
                }
            }
            if let Some(init) = &g.init {
                let d = Diagnostic::error("shader globals cannot have an initialiser", init.span)
                    .with_note("uniforms are set by the host; use a top-level `let` for a constant");
                self.diags.push(d);
            }
            let Some((class, class_span)) = class else {
                let d = Diagnostic::error(format!("`{}` has no shader qualifier", g.name.name), g.name.span);
                self.diags.push(d);
                continue;
            };
            let kind = match (class, &ty) {
                ("uniform", Ty::Sampler(_)) | ("uniform", Ty::Array(..)) if ty.is_sampler_like() => {
                    let (kind, count) = match &ty {
                        Ty::Array(elem, n) => match **elem {
                            Ty::Sampler(k) => (k, Some(*n)),
                            _ => (SamplerKind::Sampler2D, Some(*n)),
                        },
                        Ty::Sampler(k) => (*k, None),
                        _ => (SamplerKind::Sampler2D, None),
                    };
                    let n = count.unwrap_or(1);
                    if let Some((_, span)) = location {
                        self.diags.push(Diagnostic::error("`@location` does not apply to samplers; use `@stage = N` for the texture unit", span));
                    }
                    let unit = match stage {
                        Some((s, span)) if !(0..32).contains(&s) || s + n as i64 > 32 => {
                            let msg = if n > 1 {
                                format!("texture units {s}..{} are out of range (0..=31)", s + n as i64 - 1)
                            } else {
                                format!("texture unit {s} is out of range (0..=31)")
                            };
                            self.diags.push(Diagnostic::error(msg, span));
                            0
                        }
                        Some((s, span)) => {
                            let map = taken.entry("stage").or_default();
                            for u in s as u32..s as u32 + n {
                                if let Some(prev) = map.get(&u) {
                                    let d = Diagnostic::error(format!("texture unit {u} is used twice"), span).with_secondary(*prev, "first used here");
                                    self.diags.push(d);
                                    break;
                                }
                            }
                            for u in s as u32..s as u32 + n {
                                map.insert(u, span);
                            }
                            s as u32
                        }
                        None => {
                            pending_auto.push((self.out.globals.len(), "stage", n));
                            0
                        }
                    };
                    GlobalKind::Sampler { kind, texture_unit: unit, count }
                }
                ("uniform", _) => {
                    if let Some((_, span)) = location.or(stage) {
                        self.diags.push(Diagnostic::error("uniform values take no `@location` or `@stage`", span));
                    }
                    if !ty.is_error() {
                        if let Some(msg) = self.uniform_type_problem(&ty) {
                            self.diags.push(Diagnostic::error(msg, g.ty.span));
                        }
                    }
                    GlobalKind::Uniform
                }
                (c, _) => {
                    let io = match c {
                        "in" => IoKind::In,
                        "out" => IoKind::Out,
                        _ => IoKind::InOut,
                    };
                    if let Some((_, span)) = stage {
                        self.diags.push(Diagnostic::error("`@stage` applies only to samplers", span));
                    }
                    let ok = matches!(ty, Ty::Scalar(s) | Ty::Vector(s, _) if s != Scalar::Bool) || ty.is_error();
                    if !ok {
                        let d = Diagnostic::error(format!("`@{c}` variables must be numeric scalars or vectors, not `{}`", self.show(&ty)), g.ty.span);
                        self.diags.push(d);
                    }
                    let key = match io {
                        IoKind::In => "in",
                        IoKind::Out => "out",
                        IoKind::InOut => "inout",
                    };
                    let loc = match location {
                        Some((l, span)) if !(0..MAX_LOCATIONS as i64).contains(&l) => {
                            self.diags.push(Diagnostic::error(format!("location {l} is out of range (0..{MAX_LOCATIONS})"), span));
                            0
                        }
                        Some((l, span)) => {
                            let map = taken.entry(key).or_default();
                            if let Some(prev) = map.get(&(l as u32)) {
                                let d = Diagnostic::error(format!("duplicate location {l} for `@{c}` variables"), span)
                                    .with_label(format!("`{}` uses location {l}", g.name.name))
                                    .with_secondary(*prev, "already used here");
                                self.diags.push(d);
                            }
                            map.insert(l as u32, span);
                            l as u32
                        }
                        None => {
                            pending_auto.push((self.out.globals.len(), key, 1));
                            0
                        }
                    };
                    let _ = class_span;
                    GlobalKind::Io { kind: io, location: loc }
                }
            };
            self.globals.insert(&g.name.name, self.out.globals.len());
            self.out.globals.push(Global { name: g.name.name.as_str().to_string(), ty, kind, span: g.name.span });
        }
        // Automatic locations and units: the lowest free number, in declaration order.
        for (gid, key, count) in pending_auto {
            let map = taken.entry(key).or_default();
            let limit = if key == "stage" { 32 } else { MAX_LOCATIONS };
            let Some(n) = (0..limit.saturating_sub(count - 1)).find(|n| (*n..n + count).all(|u| !map.contains_key(&u))) else {
                let span = self.out.globals[gid].span;
                let what = if key == "stage" { "texture unit" } else { "location" };
                let msg = if count > 1 { format!("no {count} consecutive free {what}s left (at most {limit})") } else { format!("no free {what} left (at most {limit})") };
                self.diags.push(Diagnostic::error(msg, span));
                continue;
            };
            for u in n..n + count {
                map.insert(u, self.out.globals[gid].span);
            }
            match &mut self.out.globals[gid].kind {
                GlobalKind::Sampler { texture_unit, .. } => *texture_unit = n,
                GlobalKind::Io { location, .. } => *location = n,
                _ => {}
            }
        }
    }

    /// Why a type cannot be a uniform block, if it cannot.
    fn uniform_type_problem(&self, ty: &Ty) -> Option<String> {
        self.uniform_layout(ty, "").err()
    }

    /// The layout of `ty` in a uniform block, checked to be the same under
    /// GLSL's std140 rules and WGSL's uniform rules (naga writes WGSL
    /// structs without `@align`/`@size`, so the natural WGSL layout is the
    /// one every target must share).
    fn uniform_layout(&self, ty: &Ty, path: &str) -> Result<UniformLayout, String> {
        let round = |a: u32, x: u32| x.div_ceil(a) * a;
        match ty {
            Ty::Scalar(Scalar::Bool) | Ty::Vector(Scalar::Bool, _) => {
                Err("`bool` cannot live in a uniform block (it has no portable layout); use `int` or `uint`".into())
            }
            Ty::Scalar(_) => Ok(UniformLayout { size: 4, align: 4, std_size: 4, std_align: 4 }),
            Ty::Vector(_, n) => {
                let align = if *n == 2 { 8 } else { 16 };
                Ok(UniformLayout { size: 4 * *n as u32, align, std_size: 4 * *n as u32, std_align: align })
            }
            Ty::Matrix(_, 2) => Err(format!(
                "`{}` has different layouts in GLSL std140 and WGSL uniform blocks; use a float4 per column or a wider matrix",
                self.show(ty)
            )),
            Ty::Matrix(c, _) => Ok(UniformLayout { size: 16 * *c as u32, align: 16, std_size: 16 * *c as u32, std_align: 16 }),
            Ty::Array(elem, n) => {
                if matches!(**elem, Ty::Scalar(_) | Ty::Vector(_, 2) | Ty::Vector(_, 3)) {
                    return Err(format!(
                        "arrays of `{}` in a uniform block have a 16-byte element stride in GLSL std140, which WGSL cannot express; use float4 (or int4, uint4) elements and pack several values into each",
                        self.show(elem)
                    ));
                }
                let e = self.uniform_layout(elem, &format!("{path}[]"))?;
                let stride = round(e.align, e.size);
                let std_stride = round(16, e.std_size);
                if stride % 16 != 0 || stride != std_stride {
                    return Err(format!(
                        "elements of `{}` are {stride} bytes apart in WGSL but {std_stride} in GLSL std140; pad `{}` to a multiple of 16 bytes (e.g. with a float4 field)",
                        self.show(ty),
                        self.show(elem)
                    ));
                }
                Ok(UniformLayout { size: stride * n, align: e.align, std_size: std_stride * n, std_align: 16 })
            }
            Ty::Struct(id) => {
                let def = &self.out.structs[*id];
                let (mut end, mut std_end, mut align, mut std_align) = (0u32, 0u32, 1u32, 16u32);
                let mut prev_struct: Option<(String, u32)> = None;
                for (fname, fty, _) in &def.fields {
                    let fpath = if path.is_empty() { format!("{}.{fname}", def.name) } else { format!("{path}.{fname}") };
                    let m = self.uniform_layout(fty, &fpath).map_err(|e| if path.is_empty() && !e.contains('`') { format!("`{fpath}`: {e}") } else { e })?;
                    // WGSL uniform rule: struct and array members start at multiples of 16.
                    let member_align = if matches!(fty, Ty::Struct(_) | Ty::Array(..)) { round(16, m.align) } else { m.align };
                    let off = round(m.align, end);
                    let std_off = round(m.std_align, std_end);
                    if off != std_off || off % member_align != 0 {
                        return Err(format!(
                            "field `{fname}` of `{}` would be at offset {off} in WGSL but {std_off} in GLSL std140; reorder or pad the fields so that every struct or array field starts at a multiple of 16 and every struct used in a uniform is a multiple of 16 bytes",
                            def.name
                        ));
                    }
                    if let Some((pname, min)) = prev_struct.take() {
                        if off < min {
                            return Err(format!(
                                "field `{fname}` of `{}` follows struct field `{pname}` too closely for a WGSL uniform block; pad `{pname}`'s type to a multiple of 16 bytes",
                                def.name
                            ));
                        }
                    }
                    if matches!(fty, Ty::Struct(_)) {
                        prev_struct = Some((fname.clone(), off + round(16, m.size)));
                    }
                    end = off + m.size;
                    std_end = std_off + m.std_size;
                    align = align.max(m.align);
                    std_align = std_align.max(round(16, m.std_align));
                }
                Ok(UniformLayout { size: round(align, end), align, std_size: round(std_align, std_end), std_align })
            }
            _ => Err(format!("`{}` cannot be in a uniform block", self.show(ty))),
        }
    }

    fn resolve_type(&mut self, t: &'a ast::TypeExpr) -> Ty {
        match &t.kind {
            ast::TypeExprKind::Named(id) => {
                if let Some(ty) = Ty::from_builtin_name(&id.name) {
                    return ty;
                }
                if let Some(&sid) = self.structs.get(id.name.as_str()) {
                    return Ty::Struct(sid);
                }
                let candidates: Vec<&str> = self.structs.keys().copied().chain(TYPE_NAMES.iter().copied()).collect();
                let mut d = Diagnostic::error(format!("unknown type `{}`", id.name), id.span).with_label("not a type");
                if let Some(s) = suggest(&id.name, candidates.iter().copied()) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                if id.name == "double" {
                    d = d.with_note("double precision is not available in shaders");
                }
                self.diags.push(d);
                Ty::Error
            }
            ast::TypeExprKind::Array(elem, len) => {
                let elem_ty = self.resolve_type(elem);
                let mut names = Vec::new();
                super::consts::collect_names(len, &mut names);
                for n in names {
                    if self.const_decls.contains_key(n) {
                        self.const_id(n, len.span);
                    }
                }
                let n = match eval_const(len, &ConstEnvAdapter { c: self }).map(|(v, _)| v) {
                    Ok(ConstValue::Int(n)) if n > 0 && (n as u64) <= MAX_ARRAY_LEN => n as u32,
                    Ok(ConstValue::Uint(n)) if n > 0 && n <= MAX_ARRAY_LEN => n as u32,
                    Ok(_) => {
                        let d = Diagnostic::error(format!("array length must be a positive integer constant of at most {MAX_ARRAY_LEN}"), len.span);
                        self.diags.push(d);
                        return Ty::Error;
                    }
                    Err(d) => {
                        self.diags.push(d);
                        return Ty::Error;
                    }
                };
                if matches!(elem_ty, Ty::Array(..)) && elem_ty.is_sampler_like() {
                    self.diags.push(Diagnostic::error("arrays of arrays of samplers are not supported; use one array of samplers", t.span));
                    return Ty::Error;
                }
                if elem_ty.is_error() {
                    return Ty::Error;
                }
                Ty::Array(Box::new(elem_ty), n)
            }
        }
    }

    // ---------------------------------------------------------------- constants

    /// Looks up (checking on first use) a top-level constant.
    fn const_id(&mut self, name: &str, use_span: Span) -> Option<ConstId> {
        if let Some(&id) = self.consts.get(name) {
            return Some(id);
        }
        if self.failed_consts.contains(name) {
            return None;
        }
        let decl: &'a ast::ConstDecl = self.const_decls.get(name)?;
        // Keys borrow the declaration's own name.
        let name: &'a str = &decl.name.name;
        if self.const_in_progress.iter().any(|n| *n == name) {
            let d = Diagnostic::error(format!("constant `{name}` depends on itself"), use_span).with_secondary(decl.name.span, "defined here");
            self.diags.push(d);
            return None;
        }
        if self.const_in_progress.len() >= MAX_CONST_CHAIN {
            let d = Diagnostic::error(format!("constants are defined in terms of each other too deeply (limit {MAX_CONST_CHAIN})"), decl.name.span)
                .with_label("the limit is reached at this constant");
            self.diags.push(d);
            self.failed_consts.insert(name);
            return None;
        }
        // Constants this one names are evaluated first.
        let mut names = Vec::new();
        super::consts::collect_names(&decl.value, &mut names);
        self.const_in_progress.push(name);
        let mut deps_ok = true;
        for n in names {
            if n != name && self.const_decls.contains_key(n) {
                deps_ok &= self.const_id(n, use_span).is_some();
            }
        }
        // A constant built from a wrong one is wrong too, but that was
        // reported already.
        let value = if deps_ok { Some(eval_const(&decl.value, &ConstEnvAdapter { c: self })) } else { None };
        self.const_in_progress.pop();
        let (value, ty) = match value {
            Some(Ok(v)) => v,
            Some(Err(d)) => {
                self.diags.push(d);
                self.failed_consts.insert(name);
                return None;
            }
            None => {
                self.failed_consts.insert(name);
                return None;
            }
        };
        if let Some(t) = &decl.ty {
            let declared = self.resolve_type(t);
            if !declared.is_error() && declared != ty {
                let d = Diagnostic::error(
                    format!("constant `{name}` is declared `{}` but its value is `{}`", self.show(&declared), self.show(&ty)),
                    decl.value.span,
                );
                self.diags.push(d);
                self.failed_consts.insert(name);
                return None;
            }
        }
        let id = self.out.consts.len();
        self.out.consts.push(Const { name: name.to_string(), ty, value, span: decl.name.span });
        self.consts.insert(name, id);
        Some(id)
    }

    // ---------------------------------------------------------------- functions

    fn check_entry_points(&mut self) {
        let entries = self.entry_decls.clone();
        let mut names: FxHashMap<String, Span> = FxHashMap::with_capacity_and_hasher(entries.len(), Default::default());
        for (decl, stage) in entries {
            let name = entry_name(decl);
            if let Some(prev) = names.insert(name.clone(), decl.name.span) {
                let d = Diagnostic::error(format!("two entry points are named `{name}`"), decl.name.span).with_secondary(prev, "first one here");
                self.diags.push(d);
                continue;
            }
            let Some(func) = self.check_function(decl, Some(stage)) else { continue };
            self.check_stage_rules(&name, stage, &func);
            self.out.entry_points.push(EntryPoint { name, stage, func });
        }
    }

    /// Reports uses that the entry point's stage does not allow.
    fn check_stage_rules(&mut self, name: &str, stage: naga::ShaderStage, func: &Function) {
        for (&gid, &span) in &func.uses {
            let g = &self.out.globals[gid];
            if let GlobalKind::Builtin(b) = g.kind {
                if b.stage() != stage {
                    let d = Diagnostic::error(format!("`{}` is not available in {} entry point `{name}`", b.name(), stage_name(stage)), span)
                        .with_note(format!("`{}` belongs to the {} stage", b.name(), stage_name(b.stage())));
                    self.diags.push(d);
                }
            }
        }
        if let (naga::ShaderStage::Vertex, Some((span, what))) = (stage, func.fragment_only) {
            let d = Diagnostic::error(format!("{what} is only available in fragment entry points, and `{name}` is a vertex entry point"), span);
            self.diags.push(d);
        }
        // Inputs and outputs of one entry point need distinct locations:
        // `@in`/`@inout` inputs of a fragment entry point, `@inout`/`@out`
        // outputs of a vertex entry point (transform feedback outputs).
        let vertex = stage == naga::ShaderStage::Vertex;
        let mut seen: FxHashMap<(bool, u32), GlobalId> = FxHashMap::with_capacity_and_hasher(func.uses.len(), Default::default());
        for (&gid, &span) in &func.uses {
            let GlobalKind::Io { kind, location } = self.out.globals[gid].kind else { continue };
            let output = match kind {
                IoKind::In => false,
                IoKind::Out => true,
                IoKind::InOut => vertex,
            };
            if let Some(&prev) = seen.get(&(output, location)) {
                let (a, b) = (&self.out.globals[prev], &self.out.globals[gid]);
                let d = Diagnostic::error(
                    format!("{} entry point `{name}` uses `{}` and `{}`, which are both {} at location {location}", stage_name(stage), a.name, b.name, if output { "outputs" } else { "inputs" }),
                    span,
                )
                .with_secondary(a.span, format!("`{}` declared here", a.name))
                .with_secondary(b.span, format!("`{}` declared here", b.name))
                .with_note("`@in` and `@inout` share the input locations of a fragment entry point, `@inout` and `@out` the output locations of a vertex entry point; give one of them another `@location = N`");
                self.diags.push(d);
            } else {
                seen.insert((output, location), gid);
            }
        }
    }

    /// Looks up (checking on first use) a helper function.
    fn function_id(&mut self, name: &str, call_span: Span) -> Option<FuncId> {
        match self.funcs.get(name)? {
            FuncState::Done(id) => Some(*id),
            FuncState::Failed => None,
            FuncState::InProgress(def) => {
                let d = Diagnostic::error(format!("`{name}` calls itself; shaders cannot recurse"), call_span).with_secondary(*def, "function defined here");
                self.diags.push(d);
                None
            }
            FuncState::Unchecked(idx) => {
                let decl = self.fn_decls[*idx];
                let name: &'a str = &decl.name.name;
                if self.call_depth > MAX_DEPTH {
                    let d = Diagnostic::error(format!("calls nest too deeply (limit {MAX_DEPTH} levels of nested calls, expressions and blocks)"), call_span)
                        .with_secondary(decl.name.span, "this function is called at the limit");
                    self.diags.push(d);
                    self.funcs.insert(name, FuncState::Failed);
                    return None;
                }
                self.funcs.insert(name, FuncState::InProgress(decl.name.span));
                match self.check_function(decl, None) {
                    Some(f) => {
                        let id = self.out.functions.len();
                        self.out.functions.push(f);
                        self.funcs.insert(name, FuncState::Done(id));
                        Some(id)
                    }
                    None => {
                        self.funcs.insert(name, FuncState::Failed);
                        None
                    }
                }
            }
        }
    }

    fn check_function(&mut self, decl: &'a ast::FunctionDecl, entry: Option<naga::ShaderStage>) -> Option<Function> {
        let errors_before = self.diags.error_count();
        let ret = match &decl.ret {
            Some(t) if entry.is_none() => self.resolve_type(t),
            _ => Ty::Void,
        };
        if ret.is_sampler_like() {
            self.diags.push(Diagnostic::error("functions cannot return samplers", decl.ret.as_ref().map(|t| t.span).unwrap_or(decl.name.span)));
        }
        // Scope tables are reused from function to function (a callee is
        // checked in the middle of its first caller, hence a pool).
        let mut scopes = self.spare_scopes.pop().unwrap_or_else(|| Scopes { visible: FxHashMap::with_capacity_and_hasher(16, Default::default()), ..Default::default() });
        // The parameters' scope.
        scopes.open.push((0, 0));
        let mut cx = FnCtx {
            locals: Vec::new(),
            scopes,
            ret: ret.clone(),
            loop_depth: 0,
            uses: BTreeMap::new(),
            fragment_only: None,
            implicit_lod: false,
            callees: Default::default(),
            depth: if entry.is_some() { 0 } else { self.call_depth },
        };
        for p in &decl.params {
            let ty = self.resolve_type(&p.ty);
            if ty.is_sampler_like() {
                let d = Diagnostic::error("sampler parameters are not supported yet; use the sampler global directly", p.ty.span);
                self.diags.push(d);
            }
            self.declare_local(&mut cx, &p.name, ty, false);
        }
        let params = cx.locals.len();
        let body = self.check_block(&mut cx, &decl.body.stmts);
        let mut scopes = std::mem::take(&mut cx.scopes);
        scopes.visible.clear();
        scopes.shadowed.clear();
        scopes.open.clear();
        self.spare_scopes.push(scopes);
        if !ret.is_error() && ret != Ty::Void && !always_returns(&body) {
            let d = Diagnostic::error(format!("function `{}` can reach its end without returning a `{}`", decl.name.name, self.show(&ret)), decl.body.span)
                .with_label("the last statement here does not return");
            self.diags.push(d);
        }
        if self.diags.error_count() > errors_before {
            return None;
        }
        Some(Function {
            name: decl.name.name.as_str().to_string(),
            params,
            locals: cx.locals,
            ret,
            body,
            span: decl.span,
            uses: cx.uses,
            fragment_only: cx.fragment_only,
            implicit_lod: cx.implicit_lod,
            callees: cx.callees,
        })
    }

    fn declare_local(&mut self, cx: &mut FnCtx<'a>, id: &'a ast::Ident, ty: Ty, mutable: bool) -> LocalId {
        if self.globals.contains_key(id.name.as_str()) {
            let gspan = self.out.globals[self.globals[id.name.as_str()]].span;
            let d = Diagnostic::error(format!("`{}` shadows the shader global of the same name", id.name), id.span).with_secondary(gspan, "global declared here");
            self.diags.push(d);
        } else if let Some(prev) = cx.in_innermost_scope(&id.name) {
            let d = Diagnostic::error(format!("`{}` is already declared in this block", id.name), id.span).with_secondary(cx.locals[prev].span, "first declared here");
            self.diags.push(d);
        }
        let lid = cx.locals.len();
        cx.locals.push(Local { name: id.name.clone(), ty, mutable, span: id.span });
        cx.declare(&id.name, lid);
        lid
    }

    // ---------------------------------------------------------------- statements

    fn check_block(&mut self, cx: &mut FnCtx<'a>, stmts: &'a [ast::Stmt]) -> Vec<Stmt> {
        cx.depth += 1;
        if cx.depth > MAX_DEPTH {
            cx.depth -= 1;
            if let Some(s) = stmts.first() {
                self.diags.push(Diagnostic::error(format!("blocks nest deeper than the limit of {MAX_DEPTH}"), s.span));
            }
            return Vec::new();
        }
        cx.open_scope();
        // Usually one checked statement per statement.
        let mut out = Vec::with_capacity(stmts.len());
        for s in stmts {
            self.check_stmt(cx, s, &mut out);
        }
        cx.close_scope();
        cx.depth -= 1;
        out
    }

    fn check_stmt(&mut self, cx: &mut FnCtx<'a>, s: &'a ast::Stmt, out: &mut Vec<Stmt>) {
        match &s.kind {
            ast::StmtKind::Local { mutable, names, ty, init } => {
                let declared = ty.as_ref().map(|t| self.resolve_type(t));
                let init_expr = init.as_ref().map(|e| self.check_expr(cx, e));
                let ty = match (&declared, &init_expr) {
                    (Some(d), Some(e)) => {
                        if !d.is_error() && !e.ty.is_error() && *d != e.ty {
                            let d = Diagnostic::error(format!("type mismatch: `{}` is declared `{}` but initialised with `{}`", names[0].name, self.show(d), self.show(&e.ty)), e.span)
                                .with_label(format!("this is `{}`", self.show(&e.ty)));
                            self.diags.push(d);
                        }
                        d.clone()
                    }
                    (Some(d), None) => {
                        if !*mutable {
                            self.diags.push(Diagnostic::error(format!("`let {}` needs a value", names[0].name), s.span));
                        }
                        d.clone()
                    }
                    (None, Some(e)) => e.ty.clone(),
                    (None, None) => {
                        self.diags.push(Diagnostic::error(format!("`{}` needs a type or an initial value", names[0].name), s.span));
                        Ty::Error
                    }
                };
                if !ty.is_value() && !ty.is_error() {
                    let msg = match ty {
                        Ty::Void => "this expression has no value".to_string(),
                        _ => format!("a local variable cannot hold a `{}`", self.show(&ty)),
                    };
                    self.diags.push(Diagnostic::error(msg, init_expr.as_ref().map(|e| e.span).unwrap_or(s.span)));
                }
                // `var a, b = x`: every name gets its own copy of the value.
                let mut init_expr = init_expr;
                for (i, n) in names.iter().enumerate() {
                    let init = if i + 1 == names.len() {
                        init_expr.take()
                    } else {
                        init.as_ref().map(|e| self.check_expr(cx, e))
                    };
                    let local = self.declare_local(cx, n, ty.clone(), *mutable);
                    out.push(Stmt::Local { local, init, span: s.span });
                }
            }
            ast::StmtKind::Assign { target, op, value } => {
                let t = self.check_place(cx, target);
                let v = self.check_expr(cx, value);
                let bin = assign_binop(*op);
                if !t.ty.is_error() && !v.ty.is_error() {
                    match bin {
                        None if t.ty != v.ty => {
                            let d = Diagnostic::error(format!("type mismatch: cannot assign `{}` to `{}`", self.show(&v.ty), self.show(&t.ty)), v.span)
                                .with_label(format!("this is `{}`", self.show(&v.ty)))
                                .with_secondary(t.span, format!("this is `{}`", self.show(&t.ty)));
                            self.diags.push(d);
                        }
                        Some(op) => {
                            if let Some(rt) = self.binary_type(op, &t.ty, &v.ty, s.span) {
                                if rt != t.ty {
                                    let d = Diagnostic::error(
                                        format!("`{}` of `{}` and `{}` gives `{}`, which cannot be stored back into `{}`", op_text(op), self.show(&t.ty), self.show(&v.ty), self.show(&rt), self.show(&t.ty)),
                                        s.span,
                                    );
                                    self.diags.push(d);
                                }
                            }
                        }
                        None => {}
                    }
                }
                out.push(Stmt::Assign { target: t, op: bin, value: v, span: s.span });
            }
            ast::StmtKind::Expr(e) => self.check_expr_stmt(cx, e, s.span, out),
            ast::StmtKind::If { cond, then, elifs, otherwise } => {
                let c = self.check_cond(cx, cond);
                let then = self.check_block(cx, &then.stmts);
                // elif chains become nested ifs.
                let mut tail = otherwise.as_ref().map(|b| self.check_block(cx, &b.stmts)).unwrap_or_default();
                for (ec, eb) in elifs.iter().rev() {
                    let ec2 = self.check_cond(cx, ec);
                    let body = self.check_block(cx, &eb.stmts);
                    tail = vec![Stmt::If { cond: ec2, then: body, otherwise: tail, span: ec.span.to(eb.span) }];
                }
                out.push(Stmt::If { cond: c, then, otherwise: tail, span: s.span });
            }
            ast::StmtKind::While { cond, body } => {
                let c = self.check_cond(cx, cond);
                cx.loop_depth += 1;
                let body = self.check_block(cx, &body.stmts);
                cx.loop_depth -= 1;
                out.push(Stmt::While { cond: c, body, span: s.span });
            }
            ast::StmtKind::For { var, iter, body } => {
                let (start, end) = self.check_range(cx, iter);
                cx.open_scope();
                let ty = start.ty.clone();
                let local = self.declare_local(cx, var, ty, false);
                cx.loop_depth += 1;
                let body = self.check_block(cx, &body.stmts);
                cx.loop_depth -= 1;
                cx.close_scope();
                out.push(Stmt::For { var: local, start, end, body, span: s.span });
            }
            ast::StmtKind::Return(value) => {
                let v = value.as_ref().map(|e| self.check_expr(cx, e));
                match (&v, &cx.ret) {
                    (None, Ty::Void) => {}
                    (Some(e), Ty::Void) => {
                        self.diags.push(Diagnostic::error("this function returns nothing, so `return` takes no value", e.span));
                    }
                    (None, r) if !r.is_error() => {
                        let msg = format!("`return` needs a `{}` value here", self.show(r));
                        self.diags.push(Diagnostic::error(msg, s.span));
                    }
                    (Some(e), r) if !r.is_error() && !e.ty.is_error() && e.ty != *r => {
                        let d = Diagnostic::error(format!("type mismatch: returning `{}` from a function declared to return `{}`", self.show(&e.ty), self.show(r)), e.span);
                        self.diags.push(d);
                    }
                    _ => {}
                }
                out.push(Stmt::Return(v, s.span));
            }
            ast::StmtKind::Break | ast::StmtKind::Continue => {
                let is_break = matches!(s.kind, ast::StmtKind::Break);
                if cx.loop_depth == 0 {
                    let d = Diagnostic::error(format!("`{}` outside of a loop", if is_break { "break" } else { "continue" }), s.span);
                    self.diags.push(d);
                }
                out.push(if is_break { Stmt::Break(s.span) } else { Stmt::Continue(s.span) });
            }
            ast::StmtKind::Block(b) => {
                let inner = self.check_block(cx, &b.stmts);
                // A nested block only scopes names; its statements run in order.
                out.push(Stmt::If { cond: Expr { kind: ExprKind::Bool(true), ty: BOOL, span: b.span }, then: inner, otherwise: Vec::new(), span: b.span });
            }
        }
    }

    fn check_expr_stmt(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr, span: Span, out: &mut Vec<Stmt>) {
        match &e.kind {
            ast::ExprKind::Unary(op @ (UnaryOp::PreInc | UnaryOp::PreDec | UnaryOp::PostInc | UnaryOp::PostDec), inner) => {
                let t = self.check_place(cx, inner);
                let one = match t.ty {
                    Ty::Scalar(Scalar::Int) => Some(ExprKind::Int(1)),
                    Ty::Scalar(Scalar::Uint) => Some(ExprKind::Uint(1)),
                    Ty::Scalar(Scalar::Float) => Some(ExprKind::Float(1.0)),
                    Ty::Error => None,
                    _ => {
                        let d = Diagnostic::error(format!("`++`/`--` need an int, uint or float, not `{}`", self.show(&t.ty)), t.span);
                        self.diags.push(d);
                        None
                    }
                };
                if let Some(one) = one {
                    let bop = if matches!(op, UnaryOp::PreInc | UnaryOp::PostInc) { BinaryOp::Add } else { BinaryOp::Sub };
                    let value = Expr { kind: one, ty: t.ty.clone(), span: e.span };
                    out.push(Stmt::Assign { target: t, op: Some(bop), value, span });
                }
            }
            ast::ExprKind::Call { callee, args } if callee.name == "discard" => {
                if !args.is_empty() {
                    self.diags.push(Diagnostic::error("`discard()` takes no arguments", e.span));
                }
                cx.fragment_only.get_or_insert((e.span, "`discard()`"));
                out.push(Stmt::Discard(span));
            }
            ast::ExprKind::Call { .. } => {
                let x = self.check_expr(cx, e);
                out.push(Stmt::Expr(x));
            }
            ast::ExprKind::Paren(inner) => self.check_expr_stmt(cx, inner, span, out),
            _ => {
                let x = self.check_expr(cx, e);
                if !x.ty.is_error() {
                    let d = Diagnostic::error("this expression's value is not used", e.span).with_note("only calls, assignments and `++`/`--` can stand alone as statements");
                    self.diags.push(d);
                }
            }
        }
    }

    fn check_cond(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let c = self.check_expr(cx, e);
        if !c.ty.is_error() && c.ty != BOOL {
            let d = Diagnostic::error(format!("type mismatch: a condition must be `bool`, found `{}`", self.show(&c.ty)), c.span);
            self.diags.push(d);
        }
        c
    }

    /// `range(n)` or `range(a, b)`.
    fn check_range(&mut self, cx: &mut FnCtx<'a>, iter: &'a ast::Expr) -> (Expr, Expr) {
        let bad = |span| Expr { kind: ExprKind::Int(0), ty: Ty::Error, span };
        let ast::ExprKind::Call { callee, args } = &iter.kind else {
            self.diags.push(Diagnostic::error("`for` loops iterate over `range(n)` or `range(a, b)`", iter.span));
            return (bad(iter.span), bad(iter.span));
        };
        if callee.name != "range" || args.is_empty() || args.len() > 2 {
            let msg = if callee.name == "range" { "`range` takes one or two arguments: range(n) or range(a, b)" } else { "`for` loops iterate over `range(n)` or `range(a, b)`" };
            self.diags.push(Diagnostic::error(msg, iter.span));
            return (bad(iter.span), bad(iter.span));
        }
        let mut xs: Vec<Expr> = args.iter().map(|a| self.check_expr(cx, a)).collect();
        for x in &xs {
            if !x.ty.is_error() && x.ty != INT && x.ty != UINT {
                let d = Diagnostic::error(format!("type mismatch: `range` bounds must be `int` or `uint`, found `{}`", self.show(&x.ty)), x.span);
                self.diags.push(d);
            }
        }
        if xs.len() == 2 && xs[0].ty != xs[1].ty && !xs[0].ty.is_error() && !xs[1].ty.is_error() {
            let d = Diagnostic::error(format!("type mismatch: `range` bounds are `{}` and `{}`", self.show(&xs[0].ty), self.show(&xs[1].ty)), iter.span);
            self.diags.push(d);
        }
        if xs.len() == 1 {
            let end = xs.pop().expect("one argument");
            let zero = if end.ty == UINT { ExprKind::Uint(0) } else { ExprKind::Int(0) };
            let ty = if end.ty == UINT { UINT } else { INT };
            (Expr { kind: zero, ty, span: iter.span }, end)
        } else {
            let end = xs.pop().expect("two arguments");
            let start = xs.pop().expect("two arguments");
            (start, end)
        }
    }

    // ---------------------------------------------------------------- places

    /// An assignable expression: a `var` local, an output global, or a
    /// field, swizzle or element of one.
    fn check_place(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let x = self.check_expr(cx, e);
        if let Err(d) = self.place_ok(cx, &x) {
            self.diags.push(d);
        }
        x
    }

    fn place_ok(&self, cx: &FnCtx<'a>, x: &Expr) -> Result<(), Diagnostic> {
        match &x.kind {
            ExprKind::Local(id) => {
                let l = &cx.locals[*id];
                if l.mutable {
                    Ok(())
                } else {
                    Err(Diagnostic::error(format!("cannot assign to `{}`: it is declared with `let`", l.name), x.span)
                        .with_label("cannot assign")
                        .with_secondary(l.span, "declared here")
                        .with_note(format!("help: declare it with `var {}` to make it mutable", l.name)))
                }
            }
            ExprKind::Global(id) => {
                let g = &self.out.globals[*id];
                let why = match g.kind {
                    GlobalKind::Uniform | GlobalKind::Sampler { .. } => Some("it is a uniform, set by the host"),
                    GlobalKind::Io { kind: IoKind::In, .. } => Some("it is an `@in` input"),
                    GlobalKind::Builtin(b) if !b.is_output() => Some("it is a builtin input"),
                    _ => None,
                };
                match why {
                    None => Ok(()),
                    Some(why) => Err(Diagnostic::error(format!("cannot assign to `{}`: {why}", g.name), x.span).with_secondary(g.span, "declared here")),
                }
            }
            ExprKind::Const(_) => Err(Diagnostic::error("cannot assign to a constant", x.span)),
            ExprKind::Field(base, _) | ExprKind::Index(base, _) => self.place_ok(cx, base),
            ExprKind::Swizzle(base, comps) => {
                let mut seen = [false; 4];
                for &c in comps {
                    if std::mem::replace(&mut seen[c as usize], true) {
                        return Err(Diagnostic::error("cannot assign to a swizzle that repeats a component", x.span));
                    }
                }
                self.place_ok(cx, base)
            }
            _ if x.ty.is_error() => Ok(()),
            _ => Err(Diagnostic::error("cannot assign to this expression", x.span).with_label("not a variable")),
        }
    }

    // ---------------------------------------------------------------- expressions

    fn check_expr(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        cx.depth += 1;
        let r = if cx.depth > MAX_DEPTH {
            self.diags.push(Diagnostic::error(format!("expression nests deeper than the limit of {MAX_DEPTH}"), e.span));
            err_expr(e.span)
        } else {
            self.check_expr_inner(cx, e)
        };
        cx.depth -= 1;
        r
    }

    fn check_expr_inner(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let span = e.span;
        let mk = |kind, ty| Expr { kind, ty, span };
        match &e.kind {
            ast::ExprKind::Int(v, suffix) => match suffix {
                ast::IntSuffix::None => match i32::try_from(*v) {
                    Ok(v) => mk(ExprKind::Int(v as i64), INT),
                    // 2147483648 is fine as the operand of unary minus; see Unary below.
                    Err(_) => {
                        self.diags.push(Diagnostic::error(format!("integer literal {v} does not fit in `int`"), span).with_note("help: add a `u` suffix for `uint`"));
                        err_expr(span)
                    }
                },
                ast::IntSuffix::Unsigned => match u32::try_from(*v) {
                    Ok(v) => mk(ExprKind::Uint(v as u64), UINT),
                    Err(_) => {
                        self.diags.push(Diagnostic::error(format!("integer literal {v} does not fit in `uint`"), span));
                        err_expr(span)
                    }
                },
            },
            ast::ExprKind::Float(v) => {
                if v.is_finite() && (*v == 0.0 || v.abs() <= f32::MAX as f64) {
                    mk(ExprKind::Float(*v), FLOAT)
                } else {
                    self.diags.push(Diagnostic::error("float literal is out of range for `float`", span));
                    err_expr(span)
                }
            }
            ast::ExprKind::Bool(b) => mk(ExprKind::Bool(*b), BOOL),
            ast::ExprKind::Str(_) => {
                self.diags.push(Diagnostic::error("strings are not shader values", span));
                err_expr(span)
            }
            ast::ExprKind::Paren(inner) => {
                let mut x = self.check_expr(cx, inner);
                x.span = span;
                x
            }
            ast::ExprKind::Name(id) => self.check_name(cx, id),
            ast::ExprKind::Unary(op, inner) => {
                if let (UnaryOp::Neg, ast::ExprKind::Int(2147483648, ast::IntSuffix::None)) = (op, &inner.kind) {
                    return mk(ExprKind::Int(i32::MIN as i64), INT);
                }
                let x = self.check_expr(cx, inner);
                if x.ty.is_error() {
                    return err_expr(span);
                }
                let ok = match op {
                    UnaryOp::Neg | UnaryOp::Plus => matches!(x.ty.scalar(), Some(Scalar::Float | Scalar::Int)) && !matches!(x.ty, Ty::Matrix(..)),
                    UnaryOp::Not => x.ty == BOOL,
                    UnaryOp::BitNot => matches!(x.ty.scalar(), Some(Scalar::Int | Scalar::Uint)),
                    _ => {
                        self.diags.push(Diagnostic::error("`++` and `--` can only be used as statements", span));
                        return err_expr(span);
                    }
                };
                if !ok {
                    let d = Diagnostic::error(format!("type mismatch: `{}` cannot be applied to `{}`", unary_text(*op), self.show(&x.ty)), span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                if *op == UnaryOp::Plus {
                    return Expr { span, ..x };
                }
                let ty = x.ty.clone();
                mk(ExprKind::Unary(*op, Box::new(x)), ty)
            }
            ast::ExprKind::Binary(op, lr) => {
                let l = self.check_expr(cx, &lr.0);
                let r = self.check_expr(cx, &lr.1);
                if l.ty.is_error() || r.ty.is_error() {
                    return err_expr(span);
                }
                match self.binary_type(*op, &l.ty, &r.ty, span) {
                    Some(ty) => {
                        // Constant operands make a constant expression in the
                        // WGSL output, which WGSL evaluates at shader creation
                        // and rejects on overflow, division by zero or a
                        // non-finite result: report those here.
                        if let (Some(a), Some(b)) = (self.literal_value(&l), self.literal_value(&r)) {
                            if let Err(msg) = super::consts::binary(*op, &a, &l.ty, &b, &r.ty) {
                                if !msg.contains("not supported") && !msg.contains("mismatch") {
                                    self.diags.push(Diagnostic::error(msg, span).with_note("both operands are constants, so this is evaluated at compile time"));
                                    return err_expr(span);
                                }
                            }
                        }
                        mk(ExprKind::Binary(*op, Box::new((l, r))), ty)
                    }
                    None => err_expr(span),
                }
            }
            ast::ExprKind::Ternary(c, a, b) => {
                let c = self.check_expr(cx, c);
                let a = self.check_expr(cx, a);
                let b = self.check_expr(cx, b);
                if c.ty.is_error() || a.ty.is_error() || b.ty.is_error() {
                    return err_expr(span);
                }
                let cond_ok = c.ty == BOOL || matches!((&c.ty, &a.ty), (Ty::Vector(Scalar::Bool, n), Ty::Vector(_, m)) if n == m);
                if !cond_ok {
                    let d = Diagnostic::error(format!("type mismatch: the condition of `?:` must be `bool` (or a bool vector as wide as the values), found `{}`", self.show(&c.ty)), c.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                if a.ty != b.ty {
                    let d = Diagnostic::error(format!("type mismatch: the branches of `?:` are `{}` and `{}`", self.show(&a.ty), self.show(&b.ty)), span)
                        .with_secondary(a.span, format!("`{}`", self.show(&a.ty)))
                        .with_secondary(b.span, format!("`{}`", self.show(&b.ty)));
                    self.diags.push(d);
                    return err_expr(span);
                }
                if !a.ty.is_value() || matches!(a.ty, Ty::Array(..) | Ty::Struct(_)) {
                    let d = Diagnostic::error(format!("`?:` cannot choose between `{}` values", self.show(&a.ty)), span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                let ty = a.ty.clone();
                mk(ExprKind::Select { cond: Box::new(c), accept: Box::new(a), reject: Box::new(b) }, ty)
            }
            ast::ExprKind::Call { callee, args } => self.check_call(cx, callee, args, span),
            ast::ExprKind::Field(base, name) => {
                let b = self.check_expr(cx, base);
                self.check_field(b, name, span)
            }
            ast::ExprKind::Index(base, index) => {
                let b = self.check_expr(cx, base);
                let i = self.check_expr(cx, index);
                if b.ty.is_error() || i.ty.is_error() {
                    return err_expr(span);
                }
                if i.ty != INT && i.ty != UINT {
                    let d = Diagnostic::error(format!("type mismatch: an index must be `int` or `uint`, found `{}`", self.show(&i.ty)), i.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                let (elem, len) = match &b.ty {
                    Ty::Vector(s, n) => (Ty::Scalar(*s), *n as u32),
                    Ty::Matrix(c, r) => (Ty::Vector(Scalar::Float, *r), *c as u32),
                    Ty::Array(elem, n) => ((**elem).clone(), *n),
                    other => {
                        let d = Diagnostic::error(format!("`{}` cannot be indexed", self.show(other)), b.span);
                        self.diags.push(d);
                        return err_expr(span);
                    }
                };
                // A literal or a named constant index is checked here; naga
                // would otherwise reject the IR (an internal error).
                let constant_index = match &i.kind {
                    ExprKind::Int(k) => Some(*k),
                    ExprKind::Uint(k) => Some(*k as i64),
                    ExprKind::Unary(UnaryOp::Neg, x) => match x.kind {
                        ExprKind::Int(k) => Some(-k),
                        _ => None,
                    },
                    ExprKind::Const(c) => match self.out.consts[*c].value {
                        ConstValue::Int(k) => Some(k),
                        ConstValue::Uint(k) => Some(k as i64),
                        _ => None,
                    },
                    _ => None,
                };
                if let Some(k) = constant_index {
                    if k < 0 || k as u64 >= len as u64 {
                        let d = Diagnostic::error(format!("index {k} is out of bounds for `{}` (length {len})", self.show(&b.ty)), i.span);
                        self.diags.push(d);
                        return err_expr(span);
                    }
                }
                mk(ExprKind::Index(Box::new(b), Box::new(i)), elem)
            }
            ast::ExprKind::Array { elem, items } => {
                let declared = elem.as_ref().map(|t| self.resolve_type(t));
                let xs: Vec<Expr> = items.iter().map(|i| self.check_expr(cx, i)).collect();
                if xs.iter().any(|x| x.ty.is_error()) || declared.as_ref().is_some_and(|d| d.is_error()) {
                    return err_expr(span);
                }
                let Some(elem_ty) = declared.or_else(|| xs.first().map(|x| x.ty.clone())) else {
                    self.diags.push(Diagnostic::error("an empty array has no type", span));
                    return err_expr(span);
                };
                for x in &xs {
                    if x.ty != elem_ty {
                        let d = Diagnostic::error(format!("type mismatch: array element is `{}`, expected `{}`", self.show(&x.ty), self.show(&elem_ty)), x.span);
                        self.diags.push(d);
                        return err_expr(span);
                    }
                }
                if xs.is_empty() || xs.len() as u64 > MAX_ARRAY_LEN {
                    self.diags.push(Diagnostic::error(format!("an array needs 1 to {MAX_ARRAY_LEN} elements"), span));
                    return err_expr(span);
                }
                let ty = Ty::Array(Box::new(elem_ty), xs.len() as u32);
                mk(ExprKind::Construct(xs), ty)
            }
        }
    }

    /// The value of a literal or named scalar constant.
    fn literal_value(&self, e: &Expr) -> Option<ConstValue> {
        match &e.kind {
            ExprKind::Int(v) => Some(ConstValue::Int(*v)),
            ExprKind::Uint(v) => Some(ConstValue::Uint(*v)),
            ExprKind::Float(v) => Some(ConstValue::Float(*v as f32 as f64)),
            ExprKind::Const(c) if matches!(self.out.consts[*c].ty, Ty::Scalar(_)) => Some(self.out.consts[*c].value.clone()),
            _ => None,
        }
    }

    fn check_name(&mut self, cx: &mut FnCtx<'a>, id: &'a ast::Ident) -> Expr {
        let span = id.span;
        if let Some(l) = cx.lookup(&id.name) {
            return Expr { kind: ExprKind::Local(l), ty: cx.locals[l].ty.clone(), span };
        }
        if let Some(&g) = self.globals.get(id.name.as_str()) {
            cx.uses.entry(g).or_insert(span);
            return Expr { kind: ExprKind::Global(g), ty: self.out.globals[g].ty.clone(), span };
        }
        if self.const_decls.contains_key(id.name.as_str()) || self.consts.contains_key(id.name.as_str()) {
            return match self.const_id(&id.name, span) {
                Some(c) => Expr { kind: ExprKind::Const(c), ty: self.out.consts[c].ty.clone(), span },
                None => err_expr(span),
            };
        }
        if let Some(b) = BuiltinVar::from_name(&id.name) {
            let g = *self.builtin_vars.entry(b).or_insert_with(|| {
                self.out.globals.push(Global { name: b.name().to_string(), ty: b.ty(), kind: GlobalKind::Builtin(b), span });
                self.out.globals.len() - 1
            });
            cx.uses.entry(g).or_insert(span);
            return Expr { kind: ExprKind::Global(g), ty: b.ty(), span };
        }
        if self.funcs.contains_key(id.name.as_str()) || builtins::is_builtin(&id.name) {
            self.diags.push(Diagnostic::error(format!("`{}` is a function; call it with `{}(...)`", id.name, id.name), span));
            return err_expr(span);
        }
        let mut d = Diagnostic::error(format!("unknown name `{}`", id.name), span).with_label("not found in this scope");
        let mut candidates: Vec<&str> = cx.scopes.visible.keys().copied().collect();
        candidates.extend(self.globals.keys().copied());
        candidates.extend(self.const_decls.keys().copied());
        candidates.extend(BuiltinVar::NAMES);
        if let Some(s) = suggest(&id.name, candidates.iter().copied()) {
            d = d.with_note(format!("help: did you mean `{s}`?"));
        }
        self.diags.push(d);
        err_expr(span)
    }

    fn check_field(&mut self, b: Expr, name: &ast::Ident, span: Span) -> Expr {
        match &b.ty {
            Ty::Error => err_expr(span),
            Ty::Struct(sid) => {
                let fields = &self.out.structs[*sid].fields;
                match fields.iter().position(|(n, _, _)| *n == *name.name) {
                    Some(i) => {
                        let ty = fields[i].1.clone();
                        Expr { kind: ExprKind::Field(Box::new(b), i as u32), ty, span }
                    }
                    None => {
                        let names: Vec<&str> = fields.iter().map(|(n, _, _)| n.as_str()).collect();
                        let mut d = Diagnostic::error(format!("struct `{}` has no field `{}`", self.out.structs[*sid].name, name.name), name.span);
                        if let Some(s) = suggest(&name.name, names.iter().copied()) {
                            d = d.with_note(format!("help: did you mean `{s}`?"));
                        } else {
                            d = d.with_note(format!("its fields are: {}", names.join(", ")));
                        }
                        self.diags.push(d);
                        err_expr(span)
                    }
                }
            }
            Ty::Vector(s, n) => {
                let s = *s;
                let n = *n;
                match parse_swizzle(&name.name, n) {
                    Ok(comps) => {
                        let ty = Ty::vec(s, comps.len() as u8);
                        Expr { kind: ExprKind::Swizzle(Box::new(b), comps), ty, span }
                    }
                    Err(msg) => {
                        let d = Diagnostic::error(format!("invalid swizzle `.{}` on `{}`: {msg}", name.name, self.show(&b.ty)), name.span);
                        self.diags.push(d);
                        err_expr(span)
                    }
                }
            }
            other => {
                let d = Diagnostic::error(format!("`{}` has no fields (`.{}`)", self.show(other), name.name), name.span);
                self.diags.push(d);
                err_expr(span)
            }
        }
    }

    // ---------------------------------------------------------------- calls

    fn check_call(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, args: &'a [ast::Expr], span: Span) -> Expr {
        let name = callee.name.as_str();
        // Constructors and casts.
        let ctor_ty = Ty::from_builtin_name(name).filter(|t| !matches!(t, Ty::Sampler(_))).or_else(|| self.structs.get(name).map(|&s| Ty::Struct(s)));
        let xs: Vec<Expr> = args.iter().map(|a| self.check_expr(cx, a)).collect();
        if xs.iter().any(|x| x.ty.is_error()) {
            return err_expr(span);
        }
        if let Some(ty) = ctor_ty {
            return self.check_constructor(ty, xs, span);
        }
        if name == "range" {
            self.diags.push(Diagnostic::error("`range` can only be used as the iterator of a `for` loop", span));
            return err_expr(span);
        }
        if name == "discard" {
            self.diags.push(Diagnostic::error("`discard()` is a statement and has no value", span));
            return err_expr(span);
        }
        if self.funcs.contains_key(name) {
            self.call_depth = cx.depth + CALL_DEPTH;
            let Some(fid) = self.function_id(name, callee.span) else { return err_expr(span) };
            let f = &self.out.functions[fid];
            let params = &f.locals[..f.params];
            if params.len() != xs.len() {
                let sig = self.signature_text(fid);
                let d = Diagnostic::error(format!("wrong number of arguments: `{name}` takes {} but {} were given", params.len(), xs.len()), span)
                    .with_secondary(f.span, "defined here")
                    .with_note(format!("expected: {sig}"));
                self.diags.push(d);
                return err_expr(span);
            }
            if let Some((x, p)) = xs.iter().zip(params).find(|(x, p)| x.ty != p.ty) {
                let sig = self.signature_text(fid);
                let d = Diagnostic::error(format!("type mismatch: argument is `{}` but `{name}` expects `{}`", self.show(&x.ty), self.show(&p.ty)), x.span)
                    .with_note(format!("expected: {sig}"));
                self.diags.push(d);
                return err_expr(span);
            }
            // The callee's global uses become the caller's.
            for &g in f.uses.keys() {
                cx.uses.entry(g).or_insert(span);
            }
            if let Some(fo) = f.fragment_only {
                cx.fragment_only.get_or_insert((span, fo.1));
            }
            cx.implicit_lod |= f.implicit_lod;
            cx.callees.insert(fid);
            return Expr { kind: ExprKind::Call(fid, xs), ty: f.ret.clone(), span };
        }
        if let Some((_, b)) = builtins::TEXTURE_FUNCTIONS.iter().find(|(n, _)| *n == name) {
            return self.check_texture_call(cx, *b, name, xs, span);
        }
        match builtins::resolve(name, xs.iter().map(|x| &x.ty)) {
            Ok(Some((b, ret))) => {
                if matches!(b, Builtin::Derivative(..)) {
                    cx.fragment_only.get_or_insert((span, "a derivative"));
                }
                if b == Builtin::Math(naga::MathFunction::Determinant) && !matches!(xs[0].ty, Ty::Matrix(c, r) if c == r) {
                    self.diags.push(Diagnostic::error("`determinant` needs a square matrix", span));
                    return err_expr(span);
                }
                Expr { kind: ExprKind::Builtin(b, xs), ty: ret, span }
            }
            Ok(None) if builtins::UNSUPPORTED.iter().any(|(n, _)| *n == name) => {
                let why = builtins::UNSUPPORTED.iter().find(|(n, _)| *n == name).map(|(_, w)| *w).unwrap_or_default();
                let d = Diagnostic::error(format!("`{name}` is not available in umbrac shaders"), callee.span).with_note(format!("help: {why}"));
                self.diags.push(d);
                err_expr(span)
            }
            Ok(None) => {
                let mut d = Diagnostic::error(format!("unknown function `{name}`"), callee.span).with_label("not a function, builtin or type");
                let mut candidates: Vec<&str> = builtins::all_names().collect();
                candidates.extend(self.funcs.keys().copied());
                candidates.extend(self.structs.keys().copied());
                candidates.extend(TYPE_NAMES.iter().copied());
                if let Some(s) = suggest(name, candidates) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                self.diags.push(d);
                err_expr(span)
            }
            Err(sigs) => {
                let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
                let what = if sigs.iter().all(|s| s.matches(", ").count() + 1 != xs.len()) { "wrong number of arguments" } else { "type mismatch" };
                let mut d = Diagnostic::error(format!("{what}: no overload of `{name}` takes ({})", given.join(", ")), span);
                d = d.with_note(format!("expected one of:\n  {}", sigs.join("\n  ")));
                self.diags.push(d);
                err_expr(span)
            }
        }
    }

    fn signature_text(&self, fid: FuncId) -> String {
        let f = &self.out.functions[fid];
        let ps: Vec<String> = f.locals[..f.params].iter().map(|l| format!("{} : {}", l.name, self.show(&l.ty))).collect();
        let ret = if f.ret == Ty::Void { String::new() } else { format!(" : {}", self.show(&f.ret)) };
        format!("{}({}){}", f.name, ps.join("; "), ret)
    }

    fn check_constructor(&mut self, ty: Ty, xs: Vec<Expr>, span: Span) -> Expr {
        // The type's name is formatted only for a message.
        let fail = |this: &mut Self, msg: String| {
            this.diags.push(Diagnostic::error(msg, span));
            err_expr(span)
        };
        match &ty {
            Ty::Scalar(_) => {
                if xs.len() != 1 || !matches!(xs[0].ty, Ty::Scalar(_)) {
                    let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
                    let name = self.show(&ty);
                    return fail(self, format!("wrong arguments: `{name}(...)` converts one scalar, given ({})", given.join(", ")));
                }
            }
            Ty::Vector(_, n) => {
                let n = *n as usize;
                let single_ok = xs.len() == 1 && (matches!(xs[0].ty, Ty::Scalar(_)) || matches!(xs[0].ty, Ty::Vector(_, m) if m as usize >= n));
                if !single_ok {
                    let mut count = 0;
                    for x in &xs {
                        match x.ty {
                            Ty::Scalar(_) => count += 1,
                            Ty::Vector(_, m) => count += m as usize,
                            _ => {
                                let name = self.show(&ty);
                                return fail(self, format!("type mismatch: `{name}(...)` takes scalars and vectors, not `{}`", self.show(&x.ty)));
                            }
                        }
                    }
                    if count != n {
                        let name = self.show(&ty);
                        return fail(self, format!("wrong number of components: `{name}` needs {n}, the arguments give {count}"));
                    }
                }
            }
            Ty::Matrix(c, r) => {
                let (c, r) = (*c as usize, *r as usize);
                let cols_ok = xs.len() == c && xs.iter().all(|x| x.ty == Ty::Vector(Scalar::Float, r as u8));
                let scalars_ok = xs.len() == c * r && xs.iter().all(|x| x.ty == FLOAT);
                let diag_ok = xs.len() == 1 && xs[0].ty == FLOAT;
                let copy_ok = xs.len() == 1 && xs[0].ty == ty;
                if !(cols_ok || scalars_ok || diag_ok || copy_ok) {
                    let name = self.show(&ty);
                    return fail(self, format!("wrong arguments: `{name}` is built from {c} float{r} columns, {} floats, or one float (a diagonal)", c * r));
                }
            }
            Ty::Struct(sid) => {
                let fields = &self.out.structs[*sid].fields;
                if fields.len() != xs.len() {
                    let (name, n) = (self.show(&ty), fields.len());
                    return fail(self, format!("wrong number of arguments: `{name}` has {n} fields but {} values were given", xs.len()));
                }
                if let Some(((fname, fty, _), x)) = fields.iter().zip(&xs).find(|((_, fty, _), x)| *fty != x.ty) {
                    let name = self.show(&ty);
                    let d = Diagnostic::error(format!("type mismatch: field `{fname}` of `{name}` is `{}`, given `{}`", self.show(fty), self.show(&x.ty)), x.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
            }
            _ => {
                let name = self.show(&ty);
                return fail(self, format!("`{name}` cannot be constructed"));
            }
        }
        if xs.iter().any(|x| !x.ty.is_value() || matches!(x.ty, Ty::Array(..)) && !matches!(ty, Ty::Struct(_))) {
            let name = self.show(&ty);
            return fail(self, format!("invalid argument for `{name}(...)`"));
        }
        Expr { kind: ExprKind::Construct(xs), ty, span }
    }

    fn check_texture_call(&mut self, _cx: &mut FnCtx<'a>, b: Builtin, name: &str, xs: Vec<Expr>, span: Span) -> Expr {
        let Some(first) = xs.first() else {
            self.diags.push(Diagnostic::error(format!("wrong number of arguments: `{name}` takes a sampler first"), span));
            return err_expr(span);
        };
        let kind = match (&first.ty, &first.kind) {
            (Ty::Sampler(k), ExprKind::Global(_)) => *k,
            (Ty::Sampler(k), ExprKind::Index(base, _)) if matches!(base.kind, ExprKind::Global(_)) => *k,
            _ => {
                let d = Diagnostic::error(format!("type mismatch: the first argument of `{name}` must be a sampler, found `{}`", self.show(&first.ty)), first.span);
                self.diags.push(d);
                return err_expr(span);
            }
        };
        let f2 = Ty::Vector(Scalar::Float, 2);
        let f3 = Ty::Vector(Scalar::Float, 3);
        let f4 = Ty::Vector(Scalar::Float, 4);
        let coord = match kind {
            SamplerKind::Sampler2D | SamplerKind::Sampler2DShadow | SamplerKind::ISampler2D | SamplerKind::USampler2D => f2.clone(),
            _ => f3.clone(),
        };
        let texel = match kind {
            SamplerKind::ISampler2D => Ty::Vector(Scalar::Int, 4),
            SamplerKind::USampler2D => Ty::Vector(Scalar::Uint, 4),
            _ => f4.clone(),
        };
        let shadow = kind.is_shadow();
        let icoord = match kind {
            SamplerKind::Sampler3D | SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow => Ty::Vector(Scalar::Int, 3),
            _ => Ty::Vector(Scalar::Int, 2),
        };
        let (sigs, ret): (Vec<Vec<Ty>>, Ty) = match b {
            Builtin::Texture | Builtin::TextureLod | Builtin::TextureGrad if shadow => {
                let d = Diagnostic::error(format!("`{name}` on shadow sampler `{}` is not supported", kind.name()), span)
                    .with_note("help: use textureCompare(sampler, uv, reference_depth) for a depth comparison");
                self.diags.push(d);
                return err_expr(span);
            }
            Builtin::Texture => (vec![vec![coord.clone()], vec![coord.clone(), FLOAT]], texel),
            Builtin::TextureLod => (vec![vec![coord.clone(), FLOAT]], texel),
            Builtin::TextureGrad => {
                let grad = match kind.dim() {
                    naga::ImageDimension::D2 => f2.clone(),
                    _ => f3.clone(),
                };
                (vec![vec![coord.clone(), grad.clone(), grad]], texel)
            }
            Builtin::TextureCompare => {
                if !shadow {
                    let d = Diagnostic::error(format!("`textureCompare` needs a shadow sampler, but `{}` is a `{}`", self.sampler_name(first), kind.name()), first.span)
                        .with_label(format!("this is a `{}`", kind.name()))
                        .with_note("help: declare it as sampler2DShadow, sampler2DArrayShadow or samplerCubeShadow, or read it with texture()");
                    self.diags.push(d);
                    return err_expr(span);
                }
                (vec![vec![coord.clone(), FLOAT]], FLOAT)
            }
            Builtin::TextureProj => match kind {
                SamplerKind::Sampler2D => (vec![vec![f3.clone()], vec![f4.clone()]], texel),
                SamplerKind::Sampler2DShadow => (vec![vec![f4.clone()]], FLOAT),
                _ => {
                    self.diags.push(Diagnostic::error(format!("`textureProj` supports sampler2D and sampler2DShadow, not `{}`", kind.name()), span));
                    return err_expr(span);
                }
            },
            Builtin::TexelFetch => {
                if shadow || kind.dim() == naga::ImageDimension::Cube {
                    self.diags.push(Diagnostic::error(format!("`texelFetch` does not support `{}`", kind.name()), span));
                    return err_expr(span);
                }
                (vec![vec![icoord.clone(), INT]], texel)
            }
            Builtin::TextureSize => {
                let size = match kind {
                    SamplerKind::Sampler3D | SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow => Ty::Vector(Scalar::Int, 3),
                    _ => Ty::Vector(Scalar::Int, 2),
                };
                (vec![vec![INT]], size)
            }
            _ => unreachable!("only texture builtins reach check_texture_call"),
        };
        let given: Vec<Ty> = xs[1..].iter().map(|x| x.ty.clone()).collect();
        if !sigs.contains(&given) {
            let show_sig = |s: &Vec<Ty>| {
                let mut parts = vec![kind.name().to_string()];
                parts.extend(s.iter().map(|t| self.show(t)));
                format!("{name}({})", parts.join(", "))
            };
            let expected: Vec<String> = sigs.iter().map(show_sig).collect();
            let given_s: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
            let what = if sigs.iter().all(|s| s.len() != given.len()) { "wrong number of arguments" } else { "type mismatch" };
            let d = Diagnostic::error(format!("{what}: `{name}` cannot take ({})", given_s.join(", ")), span).with_note(format!("expected one of:\n  {}", expected.join("\n  ")));
            self.diags.push(d);
            return err_expr(span);
        }
        if matches!(b, Builtin::Texture | Builtin::TextureProj | Builtin::TextureCompare) {
            // Allowed in vertex entry points too: lowered with level 0 there.
            _cx.implicit_lod = true;
        }
        Expr { kind: ExprKind::Builtin(b, xs), ty: ret, span }
    }

    fn sampler_name(&self, e: &Expr) -> String {
        match &e.kind {
            ExprKind::Global(g) => self.out.globals[*g].name.clone(),
            ExprKind::Index(b, _) => format!("{}[...]", self.sampler_name(b)),
            _ => "the sampler".into(),
        }
    }

    // ---------------------------------------------------------------- operators

    /// The result type of `l op r`, or reports why there is none.
    fn binary_type(&mut self, op: BinaryOp, l: &Ty, r: &Ty, span: Span) -> Option<Ty> {
        use BinaryOp::*;
        let res = match op {
            Add | Sub | Mul | Div | Mod => arith_type(op, l, r),
            Lt | Le | Gt | Ge => match (l, r) {
                (Ty::Scalar(a), Ty::Scalar(b)) if a == b && a.is_numeric() => Ok(BOOL),
                (Ty::Vector(..), _) | (_, Ty::Vector(..)) => Err("compare vectors component-wise with lessThan(), greaterThan(), ...".to_string()),
                _ => Err(String::new()),
            },
            Eq | Ne => match (l, r) {
                (a, b) if a == b && matches!(a, Ty::Scalar(_) | Ty::Vector(..)) => Ok(BOOL),
                _ => Err(String::new()),
            },
            And | Or | Xor => {
                if *l == BOOL && *r == BOOL {
                    Ok(BOOL)
                } else {
                    Err(format!("`{}` needs bool operands", op_text(op)))
                }
            }
            BitAnd | BitOr | BitXor | Shl | Shr => match (l.scalar(), r.scalar()) {
                (Some(a), Some(b)) if a.is_integer() && b.is_integer() && !matches!(l, Ty::Matrix(..)) => {
                    let shift = matches!(op, Shl | Shr);
                    if (shift && l.width() == r.width()) || (!shift && (l == r || (a == b && (l.width() == Some(1) || r.width() == Some(1))))) {
                        Ok(if l.width() == Some(1) && !shift { r.clone() } else { l.clone() })
                    } else {
                        Err(String::new())
                    }
                }
                _ => Err(format!("`{}` needs int or uint operands", op_text(op))),
            },
        };
        match res {
            Ok(t) => Some(t),
            Err(hint) => {
                let mut d = Diagnostic::error(format!("type mismatch: `{}` cannot be applied to `{}` and `{}`", op_text(op), self.show(l), self.show(r)), span);
                if !hint.is_empty() {
                    d = d.with_note(format!("help: {hint}"));
                } else if l.scalar().is_some() && r.scalar().is_some() && l.scalar() != r.scalar() {
                    d = d.with_note(format!("help: there are no implicit conversions; convert one side, e.g. `{}(...)`", l.scalar().map(|s| s.name()).unwrap_or("float")));
                }
                self.diags.push(d);
                None
            }
        }
    }
}

/// Arithmetic result types, GLSL rules: same-shape operands, scalar with
/// vector (or matrix for `*`), and the linear-algebra products.
fn arith_type(op: BinaryOp, l: &Ty, r: &Ty) -> Result<Ty, String> {
    let num = |t: &Ty| t.scalar().is_some_and(|s| s.is_numeric());
    if !num(l) || !num(r) {
        return Err("arithmetic needs numeric operands".into());
    }
    if l.scalar() != r.scalar() {
        return Err(String::new());
    }
    match (l, r) {
        (Ty::Matrix(c1, r1), Ty::Matrix(c2, r2)) => match op {
            BinaryOp::Mul if c1 == r2 => Ok(Ty::Matrix(*c2, *r1)),
            BinaryOp::Add | BinaryOp::Sub if c1 == c2 && r1 == r2 => Ok(l.clone()),
            _ => Err("matrix dimensions do not fit".into()),
        },
        (Ty::Matrix(c, rows), Ty::Vector(_, n)) if op == BinaryOp::Mul => {
            if c == n {
                Ok(Ty::Vector(Scalar::Float, *rows))
            } else {
                Err(format!("a matrix with {c} columns multiplies a float{c}"))
            }
        }
        (Ty::Vector(_, n), Ty::Matrix(c, rows)) if op == BinaryOp::Mul => {
            if rows == n {
                Ok(Ty::Vector(Scalar::Float, *c))
            } else {
                Err(format!("a float{n} multiplies a matrix with {n} rows"))
            }
        }
        (Ty::Matrix(..), Ty::Scalar(_)) | (Ty::Scalar(_), Ty::Matrix(..)) if op == BinaryOp::Mul => Ok(if matches!(l, Ty::Matrix(..)) { l.clone() } else { r.clone() }),
        (Ty::Matrix(..), _) | (_, Ty::Matrix(..)) => Err("this operator does not apply to matrices".into()),
        (a, b) if a == b => Ok(a.clone()),
        (Ty::Vector(..), Ty::Scalar(_)) => Ok(l.clone()),
        (Ty::Scalar(_), Ty::Vector(..)) => Ok(r.clone()),
        _ => Err("vector sizes differ".into()),
    }
}

fn err_expr(span: Span) -> Expr {
    Expr { kind: ExprKind::Bool(false), ty: Ty::Error, span }
}

fn stage_name(s: naga::ShaderStage) -> &'static str {
    match s {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        _ => "compute",
    }
}

/// Whether every path through `stmts` ends in `return` (or `discard`).
fn always_returns(stmts: &[Stmt]) -> bool {
    match stmts.last() {
        Some(Stmt::Return(..)) | Some(Stmt::Discard(_)) => true,
        Some(Stmt::If { then, otherwise, cond, .. }) => {
            (always_returns(then) && always_returns(otherwise)) || (matches!(cond.kind, ExprKind::Bool(true)) && always_returns(then))
        }
        _ => false,
    }
}

fn assign_binop(op: ast::AssignOp) -> Option<BinaryOp> {
    use ast::AssignOp as A;
    Some(match op {
        A::Set => return None,
        A::Add => BinaryOp::Add,
        A::Sub => BinaryOp::Sub,
        A::Mul => BinaryOp::Mul,
        A::Div => BinaryOp::Div,
        A::Mod => BinaryOp::Mod,
        A::BitAnd => BinaryOp::BitAnd,
        A::BitOr => BinaryOp::BitOr,
        A::BitXor => BinaryOp::BitXor,
        A::Shl => BinaryOp::Shl,
        A::Shr => BinaryOp::Shr,
    })
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

fn unary_text(op: UnaryOp) -> &'static str {
    match op {
        UnaryOp::Neg => "-",
        UnaryOp::Plus => "+",
        UnaryOp::Not => "!",
        UnaryOp::BitNot => "~",
        UnaryOp::PreInc | UnaryOp::PostInc => "++",
        UnaryOp::PreDec | UnaryOp::PostDec => "--",
    }
}

/// Component indices of a swizzle (`xyzw` or `rgba`, not mixed).
fn parse_swizzle(s: &str, width: u8) -> Result<Components, String> {
    if s.is_empty() || s.len() > 4 {
        return Err("a swizzle has 1 to 4 components".into());
    }
    // Bytes: a string all of whose bytes are in a set is ASCII.
    let sets: [&[u8; 4]; 3] = [b"xyzw", b"rgba", b"stpq"];
    let set = sets.iter().find(|set| s.bytes().all(|c| set.contains(&c))).ok_or_else(|| "use components from one of xyzw, rgba or stpq".to_string())?;
    let mut comps = Components::new();
    for c in s.bytes() {
        let i = set.iter().position(|&x| x == c).expect("checked above") as u8;
        if i >= width {
            return Err(format!("component `{}` does not exist on a {width}-component vector", c as char));
        }
        comps.push(i);
    }
    Ok(comps)
}

const TYPE_NAMES: &[&str] = &[
    "float", "float2", "float3", "float4", "int", "int2", "int3", "int4", "uint", "uint2", "uint3", "uint4", "bool", "bool2", "bool3", "bool4", "float2x2",
    "float3x3", "float4x4", "sampler2D", "sampler2DShadow", "sampler2DArray", "sampler2DArrayShadow", "sampler3D", "samplerCube", "samplerCubeShadow",
];

/// Lets the constant evaluator look up other constants through the checker.
struct ConstEnvAdapter<'c, 'a, 'd> {
    c: &'c Checker<'a, 'd>,
}

impl ConstEnv for ConstEnvAdapter<'_, '_, '_> {
    fn lookup(&self, name: &str) -> Option<(ConstValue, Ty)> {
        let &id = self.c.consts.get(name)?;
        let k = &self.c.out.consts[id];
        Some((k.value.clone(), k.ty.clone()))
    }

    fn struct_type(&self, name: &str) -> Option<(Ty, Vec<Ty>)> {
        let &sid = self.c.structs.get(name)?;
        Some((Ty::Struct(sid), self.c.out.structs[sid].fields.iter().map(|f| f.1.clone()).collect()))
    }
}
