//! Helper functions: lowered once, or twice where both stages reach one
//! that samples with implicit LOD (a `_vertex` copy samples level 0), or
//! once per set of samplers for a helper with sampler parameters.

use naga::{Block, Expression as E, Handle};

use super::function::{FnBuilder, FnKind, LocalSlot};
use super::module::{GlobalSlot, ModuleBuilder, SamplerRef, Specialised};
use super::reach::Reach;
use crate::sema::{self, Expr, ExprKind, Ty};

/// Lowers the helper functions the module holds, in sema's order (callees
/// first). Implicit-LOD sampling means level 0 in a vertex entry point, so
/// a helper that samples and is reached from both stages is lowered twice
/// (a one-entry module needs only the copy for its stage). A helper with
/// sampler parameters is lowered at its calls instead
/// ([`specialised_helper`]).
pub(super) fn lower_helpers(m: &mut ModuleBuilder<'_>, only: Option<usize>, reach: &Reach) {
    let p = m.p;
    let (from_vertex, from_fragment) = (&reach.vertex, &reach.fragment);
    let reached = only.map(|i| &reach.by_entry[i]);
    let vertex_entry = only.map(|i| p.entry_points[i].stage == naga::ShaderStage::Vertex);
    for (fid, f) in p.functions.iter().enumerate() {
        if reached.as_ref().is_some_and(|r| !r[fid]) || f.takes_samplers() {
            m.functions.push(None);
            m.vertex_functions.push(None);
            continue;
        }
        let two_copies = f.implicit_lod && from_vertex[fid] && from_fragment[fid];
        let vertex_only = f.implicit_lod && from_vertex[fid] && !from_fragment[fid];
        let h = (!(two_copies && vertex_entry == Some(true))).then(|| lower_helper(m, f, &f.name, vertex_only, &[]));
        m.functions.push(h);
        let copy = (two_copies && vertex_entry != Some(false)).then(|| lower_helper(m, f, &[&f.name, "_vertex"].concat(), true, &[]));
        m.vertex_functions.push(copy);
    }
}

/// Lowers one helper function; `vertex_lod`: implicit-LOD sampling at
/// level 0; `samplers`: what its sampler parameters stand for, in order.
pub(super) fn lower_helper<'p>(m: &mut ModuleBuilder<'p>, f: &'p sema::Function, name: &str, vertex_lod: bool, samplers: &[SamplerRef]) -> naga::Handle<naga::Function> {
    let mut b = FnBuilder::new(m, name, &f.locals, FnKind::Helper);
    b.vertex_lod = vertex_lod;
    let mut samplers = samplers.iter();
    // Copies of `var` parameters, then the body, in a block sized for
    // both (growing it costs reallocations in every helper).
    let mut body = super::function::block_for(f.body.len() + f.params);
    for (i, l) in f.locals[..f.params].iter().enumerate() {
        let sampler = matches!(l.ty, Ty::Sampler(_)).then(|| *samplers.next().expect("one sampler per sampler parameter"));
        b.add_param(i, sampler, &mut body);
    }
    b.stmts_into(&f.body, &mut body);
    let ret = (f.ret != Ty::Void).then(|| naga::FunctionResult { ty: b.m.ty(&f.ret), binding: None });
    match &ret {
        None => naga::proc::ensure_block_returns(&mut body),
        // The checker let only paths that end in `discard()` lack a
        // `return`: they return a zero value, never used.
        Some(r) if super::function::falls_through(&body) => {
            let zero = b.append_plain(naga::Expression::ZeroValue(r.ty), f.span);
            body.push(naga::Statement::Return { value: Some(zero) }, f.span.into());
        }
        Some(_) => {}
    }
    let func = b.finish(body, ret);
    m.module.functions.append(func, f.span.into())
}

/// Helper `fid` specialised for `samplers` (its sampler parameters, in
/// order), lowered on first request: one naga function per distinct set
/// of samplers (and per stage, for implicit LOD), named after them
/// (`blur_albedo`), since naga's backends have no sampler parameters that
/// all of GLSL, WGSL and SPIR-V share.
pub(super) fn specialised_helper(m: &mut ModuleBuilder<'_>, fid: usize, vertex_lod: bool, samplers: Vec<SamplerRef>) -> naga::Handle<naga::Function> {
    let p = m.p;
    let f = &p.functions[fid];
    // Level 0 matters only where the helper samples with implicit LOD.
    let vertex_lod = vertex_lod && f.implicit_lod;
    if let Some(s) = m.specialised.iter().find(|s| s.function == fid && s.vertex_lod == vertex_lod && s.samplers == samplers) {
        return s.handle;
    }
    let mut name = f.name.clone();
    for r in &samplers {
        name.push('_');
        name.push_str(&p.globals[r.global].name);
        if matches!(p.globals[r.global].ty, Ty::Array(..)) {
            name.push_str(&format!("_{}", r.elem));
        }
    }
    if vertex_lod {
        name.push_str("_vertex");
    }
    // Names are at most MAX_IDENT_LEN characters, but a helper with many
    // sampler parameters would join many: past 512 (GLSL allows 1024, and
    // naga may add a suffix), the function's name and the copy's number.
    if name.len() > 2 * crate::syntax::MAX_IDENT_LEN {
        name = format!("{}_{}", f.name, m.specialised.len());
    }
    let handle = lower_helper(m, f, &name, vertex_lod, &samplers);
    m.specialised.push(Specialised { function: fid, vertex_lod, samplers, handle });
    handle
}


/// After a call: the temporaries that stood for `var p : T&` arguments,
/// copied back to the places they stand for (GLSL `inout`'s copy-out).
pub(super) type WriteBack = Vec<(Handle<naga::LocalVariable>, Place)>;

/// Where a temporary is copied back to: a pointer, or the components
/// `comps` of the vector of `width` components (its type `ty`) behind a
/// pointer (a swizzle of several components has no pointer).
pub(super) enum Place {
    Whole(Handle<E>),
    Components { vector: Handle<E>, comps: crate::sema::Components, width: u8, ty: Handle<naga::Type> },
}

impl FnBuilder<'_, '_> {
    /// A call of helper `fid`: the function it reaches from here, its
    /// argument values, and the copies back that follow the call. A helper
    /// with sampler parameters is specialised for the samplers given
    /// (lowered on its first such call); those arguments are not passed.
    /// A `var p : T&` argument is a pointer: to the caller's own local
    /// variable where the argument is one (and no other reference
    /// argument of the call names it), else to a temporary copy written
    /// back after the call, as GLSL's `inout` does (a field, an element, a
    /// global: what WGSL does not let a pointer argument name).
    pub(super) fn call(&mut self, fid: usize, args: &[Expr], block: &mut Block) -> (Handle<naga::Function>, Vec<Handle<E>>, WriteBack) {
        let f = &self.m.p.functions[fid];
        let mut samplers = Vec::new();
        let mut values = Vec::with_capacity(args.len());
        let mut write_back = Vec::new();
        let mut passed: Vec<usize> = Vec::new();
        for (i, a) in args.iter().enumerate() {
            if f.locals[i].by_ref && !self.writable(a) {
                // A value for a `var` struct or array parameter: the
                // callee's own copy, nothing to write back.
                let value = self.expr(a, block);
                let ty = self.m.ty(&a.ty);
                let tmp = self.func.local_variables.append(naga::LocalVariable { name: Some(super::function::local_name(f.locals[i].name.as_str())), ty, init: None }, a.span.into());
                let tmp_ptr = self.append_plain(E::LocalVariable(tmp), a.span);
                self.push(block, naga::Statement::Store { pointer: tmp_ptr, value }, a.span);
                values.push(tmp_ptr);
                continue;
            }
            if f.locals[i].by_ref {
                let whole = match a.kind {
                    ExprKind::Local(l) if !passed.contains(&l) && matches!(self.locals[l], LocalSlot::Var(_) | LocalSlot::Ptr(_)) => Some(l),
                    _ => None,
                };
                if let Some(l) = whole {
                    passed.push(l);
                    values.push(self.pointer(a, block).expect("a variable is a place"));
                    continue;
                }
                let (place, value) = match &a.kind {
                    ExprKind::Swizzle(base, comps) if comps.len() > 1 => {
                        let vector = self.pointer(base, block).expect("sema checks that a reference argument is a place");
                        let whole = self.append(E::Load { pointer: vector }, a.span);
                        let value = self.swizzle(whole, comps, a.span);
                        let ty = self.m.ty(&base.ty);
                        (Place::Components { vector, comps: comps.clone(), width: base.ty.width().unwrap_or(4), ty }, value)
                    }
                    _ => {
                        let place = self.pointer(a, block).expect("sema checks that a reference argument is a place");
                        (Place::Whole(place), self.append(E::Load { pointer: place }, a.span))
                    }
                };
                let ty = self.m.ty(&a.ty);
                let tmp = self.func.local_variables.append(naga::LocalVariable { name: Some(super::function::local_name(f.locals[i].name.as_str())), ty, init: None }, a.span.into());
                let tmp_ptr = self.append_plain(E::LocalVariable(tmp), a.span);
                self.push(block, naga::Statement::Store { pointer: tmp_ptr, value }, a.span);
                write_back.push((tmp, place));
                values.push(tmp_ptr);
                continue;
            }
            if !matches!(a.ty, Ty::Sampler(_)) {
                values.push(self.expr(a, block));
                continue;
            }
            match self.sampler_of(a) {
                Some(Ok(r)) => samplers.push(r),
                _ => unreachable!("sema checks that a sampler argument is known"),
            }
        }
        let function = match samplers.is_empty() {
            true => self.callee(fid),
            false => specialised_helper(self.m, fid, self.vertex_lod, samplers),
        };
        (function, values, write_back)
    }

    /// Whether `e` is a place this function may write: a variable, an
    /// output or private global, or a part of one (not a uniform).
    pub(super) fn writable(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Local(l) => matches!(self.locals[*l], LocalSlot::Var(_) | LocalSlot::Ptr(_)),
            ExprKind::Global(g) => match self.global_slot(*g) {
                Some(slot) => matches!(slot, LocalSlot::Var(_)),
                // A plain GLSL uniform is a private global too.
                None if matches!(self.m.p.globals[*g].kind, sema::GlobalKind::Uniform { .. }) => false,
                None => match self.m.globals[*g] {
                    GlobalSlot::Var(h) => self.m.module.global_variables[h].space == naga::AddressSpace::Private,
                    _ => false,
                },
            },
            ExprKind::Field(b, _) | ExprKind::Index(b, _) => self.writable(b),
            ExprKind::Swizzle(b, _) => self.writable(b),
            _ => false,
        }
    }

    /// Copies the temporaries of a call's reference arguments back.
    pub(super) fn write_back(&mut self, write_back: WriteBack, block: &mut Block, s: crate::source::Span) {
        for (tmp, place) in write_back {
            let tmp_ptr = self.append_plain(E::LocalVariable(tmp), s);
            let value = self.append(E::Load { pointer: tmp_ptr }, s);
            match place {
                Place::Whole(pointer) => self.push(block, naga::Statement::Store { pointer, value }, s),
                Place::Components { vector, comps, width, ty } => {
                    // The vector with the swizzled components replaced.
                    let old = self.append(E::Load { pointer: vector }, s);
                    let parts = (0..width)
                        .map(|c| match comps.iter().position(|&k| k == c) {
                            Some(k) => self.append(E::AccessIndex { base: value, index: k as u32 }, s),
                            None => self.append(E::AccessIndex { base: old, index: c as u32 }, s),
                        })
                        .collect();
                    let whole = self.append(E::Compose { ty, components: parts }, s);
                    self.push(block, naga::Statement::Store { pointer: vector, value: whole }, s);
                }
            }
        }
    }

    /// The sampler expression `e` names: one known here, or an element of
    /// sampler global `g` picked at run time (`Err((g, index))`). `None`
    /// for an expression that is no sampler.
    pub(super) fn sampler_of<'e>(&self, e: &'e Expr) -> Option<Result<SamplerRef, (sema::GlobalId, &'e Expr)>> {
        match &e.kind {
            ExprKind::Global(g) if matches!(self.m.globals[*g], GlobalSlot::Sampler { .. }) => Some(Ok(SamplerRef { global: *g, elem: 0 })),
            ExprKind::Index(base, i) => match base.kind {
                ExprKind::Global(g) if matches!(self.m.globals[g], GlobalSlot::Sampler { .. }) => Some(match i.const_int(&self.m.p.consts) {
                    Some(k) => Ok(SamplerRef { global: g, elem: k.clamp(0, u32::MAX as i64) as u32 }),
                    None => Err((g, &**i)),
                }),
                _ => None,
            },
            ExprKind::Local(l) => match self.locals[*l] {
                LocalSlot::Sampler(r) => Some(Ok(r)),
                _ => None,
            },
            _ => None,
        }
    }

    /// The function a call of helper `fid` (without sampler parameters)
    /// reaches from here.
    pub(super) fn callee(&self, fid: usize) -> Handle<naga::Function> {
        match self.m.vertex_functions.get(fid) {
            Some(Some(h)) if self.vertex_lod => *h,
            // A one-entry module holds every function its entry point
            // reaches (`lower::build`), so a call never misses.
            _ => self.m.functions[fid].expect("the callee is lowered"),
        }
    }
}
