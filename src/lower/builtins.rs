//! Builtin function calls other than texture reads: the math library,
//! daslang's extra names (`saturate`, `rcp`, ...), comparisons, derivatives,
//! bit casts and `inverse`.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::FnBuilder;
use super::types::naga_scalar;
use crate::sema::builtins::Builtin;
use crate::sema::{Expr, Scalar, Ty};
use crate::source::Span;
use crate::syntax::ast::BinaryOp;

impl FnBuilder<'_, '_> {
    pub(super) fn builtin(&mut self, b: Builtin, args: &[Expr], ret: &Ty, s: Span, block: &mut Block) -> Handle<E> {
        use naga::MathFunction as Mf;
        if b.is_texture() {
            return self.texture(b, args, ret, s, block);
        }
        let mut hs: Vec<Handle<E>> = args.iter().map(|a| self.expr(a, block)).collect();
        match b {
            Builtin::Math(fun) => {
                // Scalars of a vector call are broadcast (min(v, 0.0), mix(a, b, t), step(0.5, v)).
                if matches!(ret, Ty::Vector(..)) && !matches!(fun, Mf::Cross | Mf::Refract) {
                    for (h, a) in hs.iter_mut().zip(args) {
                        *h = self.splat_to(*h, &a.ty, ret, s);
                    }
                }
                self.math(fun, &hs, s)
            }
            Builtin::Saturate => self.math(Mf::Saturate, &hs, s),
            Builtin::Rcp => {
                let one = self.literal(naga::Literal::F32(1.0), s);
                let one = self.splat_to(one, &Ty::Scalar(Scalar::Float), ret, s);
                self.append(E::Binary { op: naga::BinaryOperator::Divide, left: one, right: hs[0] }, s)
            }
            Builtin::Mod => self.binary(BinaryOp::Mod, hs[0], &args[0].ty, hs[1], &args[1].ty, s),
            Builtin::Any => self.append(E::Relational { fun: naga::RelationalFunction::Any, argument: hs[0] }, s),
            Builtin::All => self.append(E::Relational { fun: naga::RelationalFunction::All, argument: hs[0] }, s),
            Builtin::Not => self.append(E::Unary { op: naga::UnaryOperator::LogicalNot, expr: hs[0] }, s),
            Builtin::Compare(op) => {
                use naga::BinaryOperator as Bo;
                let bo = match op {
                    BinaryOp::Lt => Bo::Less,
                    BinaryOp::Le => Bo::LessEqual,
                    BinaryOp::Gt => Bo::Greater,
                    BinaryOp::Ge => Bo::GreaterEqual,
                    BinaryOp::Eq => Bo::Equal,
                    _ => Bo::NotEqual,
                };
                self.append(E::Binary { op: bo, left: hs[0], right: hs[1] }, s)
            }
            Builtin::Derivative(axis, ctrl) => self.append(E::Derivative { axis, ctrl, expr: hs[0] }, s),
            Builtin::Bitcast(to) => self.append(E::As { expr: hs[0], kind: naga_scalar(to).kind, convert: None }, s),
            Builtin::Inverse => {
                let Ty::Matrix(n, _) = *ret else { unreachable!("sema checks that `inverse` takes a square matrix") };
                let function = super::inverse::function(self.m, n);
                let result = self.append_plain(E::CallResult(function), s);
                self.push(block, Statement::Call { function, arguments: vec![hs[0]], result: Some(result) }, s);
                result
            }
            _ => unreachable!("texture builtins handled above"),
        }
    }
}
