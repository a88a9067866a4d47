//! Subgroup operations (dasSpirv's `spirv_builtins`: `subgroupAdd`,
//! `subgroupBroadcast`, `subgroupShuffle`, `subgroupElect`, ... and
//! the scans and bitwise reductions naga has too) and `nonuniformEXT`.
//! Typed here; refused for the targets without subgroups
//! (`targets::subgroup_used`) and in vertex entry points.

use super::*;
use crate::sema::builtins::{Gather, SubgroupFn};
use naga::{CollectiveOperation as C, SubgroupOperation as O};

/// The subgroup builtin a name calls, if any.
pub(super) fn subgroup_builtin(name: &str) -> Option<Builtin> {
    let f = match name {
        "nonuniformEXT" => return Some(Builtin::NonUniform),
        "subgroupElect" => SubgroupFn::Elect,
        "subgroupBallot" => SubgroupFn::Ballot,
        "subgroupAll" => SubgroupFn::Collective(C::Reduce, O::All),
        "subgroupAny" => SubgroupFn::Collective(C::Reduce, O::Any),
        "subgroupAdd" => SubgroupFn::Collective(C::Reduce, O::Add),
        "subgroupMul" => SubgroupFn::Collective(C::Reduce, O::Mul),
        "subgroupMin" => SubgroupFn::Collective(C::Reduce, O::Min),
        "subgroupMax" => SubgroupFn::Collective(C::Reduce, O::Max),
        "subgroupAnd" => SubgroupFn::Collective(C::Reduce, O::And),
        "subgroupOr" => SubgroupFn::Collective(C::Reduce, O::Or),
        "subgroupXor" => SubgroupFn::Collective(C::Reduce, O::Xor),
        "subgroupInclusiveAdd" => SubgroupFn::Collective(C::InclusiveScan, O::Add),
        "subgroupInclusiveMul" => SubgroupFn::Collective(C::InclusiveScan, O::Mul),
        "subgroupExclusiveAdd" => SubgroupFn::Collective(C::ExclusiveScan, O::Add),
        "subgroupExclusiveMul" => SubgroupFn::Collective(C::ExclusiveScan, O::Mul),
        "subgroupBroadcastFirst" => SubgroupFn::Gather(Gather::BroadcastFirst),
        "subgroupBroadcast" => SubgroupFn::Gather(Gather::Broadcast),
        "subgroupShuffle" => SubgroupFn::Gather(Gather::Shuffle),
        "subgroupShuffleXor" => SubgroupFn::Gather(Gather::ShuffleXor),
        "subgroupShuffleUp" => SubgroupFn::Gather(Gather::ShuffleUp),
        "subgroupShuffleDown" => SubgroupFn::Gather(Gather::ShuffleDown),
        _ => return None,
    };
    Some(Builtin::Subgroup(f))
}

/// Subgroup operations dasSpirv declares that no target of umbrac's
/// can express, with why.
pub(super) const UNSUPPORTED_SUBGROUP: &[(&str, &str)] = &[(
    "subgroupClusteredAdd",
    "naga's IR has no clustered subgroup operations, so no target umbrac writes (WGSL has none; SPIR-V's GroupNonUniformClustered is not reachable through naga)",
)];

/// A 32-bit `int`, `uint` or `float` scalar or vector (what a subgroup
/// value may be in every target that has subgroups).
fn is_lane_value(ty: &Ty) -> bool {
    matches!(ty.scalar(), Some(Scalar::Int | Scalar::Uint | Scalar::Float)) && matches!(ty, Ty::Scalar(_) | Ty::Vector(..))
}

impl<'a, 'd> Checker<'a, 'd> {
    pub(super) fn check_subgroup_call(&mut self, cx: &mut FnCtx<'a>, b: Builtin, name: &str, mut xs: Vec<Expr>, span: Span) -> Expr {
        let Builtin::Subgroup(f) = b else {
            // `nonuniformEXT(i)`: an `int` or `uint`, as it is.
            if xs.len() != 1 || !matches!(xs[0].ty, Ty::Scalar(Scalar::Int | Scalar::Uint) | Ty::Error) {
                let d = Diagnostic::error(format!("`{name}` takes one `int` or `uint` index"), span).with_note("expected `nonuniformEXT(index)`");
                self.diags.push(d);
                return err_expr(span);
            }
            let ty = xs[0].ty.clone();
            return Expr { kind: ExprKind::Builtin(b, xs), ty, span };
        };
        self.subgroup_used(&format!("`{name}`"), span);
        cx.subgroup_op.get_or_insert(span);
        let (sig, n) = match f {
            SubgroupFn::Elect => ("()", 0),
            SubgroupFn::Ballot | SubgroupFn::Collective(_, O::All | O::Any) => ("(bool)", 1),
            SubgroupFn::Collective(_, O::And | O::Or | O::Xor) => ("(intN or uintN)", 1),
            SubgroupFn::Collective(..) | SubgroupFn::Gather(Gather::BroadcastFirst) => ("(T), T an int, uint or float scalar or vector", 1),
            SubgroupFn::Gather(Gather::Broadcast) => ("(T, lane : uint), the lane a constant", 2),
            SubgroupFn::Gather(_) => ("(T, uint)", 2),
        };
        if xs.len() != n {
            let d = Diagnostic::error(format!("wrong number of arguments: `{name}` takes {n}"), span).with_note(format!("expected `{name}{sig}`"));
            self.diags.push(d);
            return err_expr(span);
        }
        if xs.iter().any(|x| x.ty == Ty::Error) {
            return err_expr(span);
        }
        let value_ok = match f {
            SubgroupFn::Elect => true,
            SubgroupFn::Ballot | SubgroupFn::Collective(_, O::All | O::Any) => xs[0].ty == BOOL,
            SubgroupFn::Collective(_, O::And | O::Or | O::Xor) => matches!(xs[0].ty.scalar(), Some(Scalar::Int | Scalar::Uint)) && is_lane_value(&xs[0].ty),
            _ => is_lane_value(&xs[0].ty),
        };
        if !value_ok {
            let d = Diagnostic::error(format!("`{name}` does not take a `{}`", self.show(&xs[0].ty)), xs[0].span).with_note(format!("expected `{name}{sig}`"));
            self.diags.push(d);
            return err_expr(span);
        }
        if let Some(x) = xs.get_mut(1) {
            // A non-negative `int` literal converts (`subgroupShuffleXor(v, 1)`).
            let value = self.literal_value(x);
            match (&value, &x.ty) {
                (Some(ConstValue::Int(k)), _) if *k >= 0 => *x = Expr { kind: ExprKind::Uint(*k as u64), ty: UINT, span: x.span },
                (Some(ConstValue::Uint(k)), _) => *x = Expr { kind: ExprKind::Uint(*k), ty: UINT, span: x.span },
                (_, Ty::Scalar(Scalar::Uint)) if f != SubgroupFn::Gather(Gather::Broadcast) => {}
                _ => {
                    let what = if f == SubgroupFn::Gather(Gather::Broadcast) { "a constant `uint` lane" } else { "a `uint`" };
                    let d = Diagnostic::error(format!("`{name}` takes {what} as its second argument"), x.span)
                        .with_label(format!("this is `{}`", self.show(&x.ty)))
                        .with_note(format!("expected `{name}{sig}`"));
                    let d = if f == SubgroupFn::Gather(Gather::Broadcast) {
                        d.with_note("help: `subgroupShuffle(v, lane)` reads a lane chosen at run time")
                    } else {
                        d
                    };
                    self.diags.push(d);
                    return err_expr(span);
                }
            }
        }
        let ty = match f {
            SubgroupFn::Elect | SubgroupFn::Collective(_, O::All | O::Any) => BOOL,
            SubgroupFn::Ballot => Ty::Vector(Scalar::Uint, 4),
            _ => xs[0].ty.clone(),
        };
        Expr { kind: ExprKind::Builtin(b, xs), ty, span }
    }
}
