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
    for (i, l) in f.locals[..f.params].iter().enumerate() {
        let sampler = matches!(l.ty, Ty::Sampler(_)).then(|| *samplers.next().expect("one sampler per sampler parameter"));
        b.add_param(i, sampler);
    }
    let mut body = b.block(&f.body);
    let ret = (f.ret != Ty::Void).then(|| naga::FunctionResult { ty: b.m.ty(&f.ret), binding: None });
    if ret.is_none() {
        naga::proc::ensure_block_returns(&mut body);
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


impl FnBuilder<'_, '_> {
    /// A call of helper `fid`: the function it reaches from here and its
    /// argument values. A helper with sampler parameters is specialised
    /// for the samplers given (lowered on its first such call); those
    /// arguments are not passed.
    pub(super) fn call(&mut self, fid: usize, args: &[Expr], block: &mut Block) -> (Handle<naga::Function>, Vec<Handle<E>>) {
        let mut samplers = Vec::new();
        let mut values = Vec::with_capacity(args.len());
        for a in args {
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
        (function, values)
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
