//! Builtin function calls other than texture reads: the math library,
//! daslang's extra names (`saturate`, `rcp`, ...), comparisons, derivatives,
//! bit casts and `inverse`.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::FnBuilder;
use super::interface::Flavor;
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
        if let Some(h) = self.compute_builtin(b, args, ret, s, block) {
            return h;
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
                let one = self.m.float_literal(1.0, args[0].ty.scalar().unwrap_or(Scalar::Float));
                let one = self.literal(one, s);
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
            Builtin::Mad => {
                // a * b + c; a scalar `b` scales a vector `a`.
                let ab = self.append(E::Binary { op: naga::BinaryOperator::Multiply, left: hs[0], right: hs[1] }, s);
                self.append(E::Binary { op: naga::BinaryOperator::Add, left: ab, right: hs[2] }, s)
            }
            Builtin::LengthSq => self.length_sq(hs[0], &args[0].ty, s),
            Builtin::DistanceSq | Builtin::InvDistanceSq => {
                let d = self.append(E::Binary { op: naga::BinaryOperator::Subtract, left: hs[0], right: hs[1] }, s);
                let sq = self.length_sq(d, &args[0].ty, s);
                if b == Builtin::DistanceSq {
                    sq
                } else {
                    self.reciprocal(sq, ret, s)
                }
            }
            Builtin::InvLength => {
                let l = self.math(Mf::Length, &hs, s);
                self.reciprocal(l, ret, s)
            }
            Builtin::InvLengthSq => {
                let sq = self.length_sq(hs[0], &args[0].ty, s);
                self.reciprocal(sq, ret, s)
            }
            Builtin::InvDistance => {
                let d = self.math(Mf::Distance, &hs, s);
                self.reciprocal(d, ret, s)
            }
            Builtin::ToInt(fun) => {
                let r = self.math(fun, &hs, s);
                self.convert(r, &args[0].ty, Scalar::Int, s)
            }
            Builtin::Hash => self.noise_hash(hs[0], None, s),
            Builtin::Noise => {
                let position = self.noise_position(hs[0], &args[0].ty, s);
                self.noise_hash(position, Some(hs[1]), s)
            }
            Builtin::Identity => {
                let Ty::Matrix(n, _) = *ret else { unreachable!("identity functions return square matrices") };
                let col_ty = self.m.ty(&Ty::Vector(Scalar::Float, n));
                let (zero, one) = (self.literal(naga::Literal::F32(0.0), s), self.literal(naga::Literal::F32(1.0), s));
                let cols = (0..n).map(|i| self.append(E::Compose { ty: col_ty, components: (0..n).map(|j| if i == j { one } else { zero }).collect() }, s)).collect();
                let ty = self.m.ty(ret);
                self.append(E::Compose { ty, components: cols }, s)
            }
            Builtin::Pack(fun) => match self.m.flavor {
                // GLSL 330 has none of them and ES 300 lacks some: the GL
                // modules compute them all, with the arithmetic WGSL defines.
                Flavor::Gl => self.pack_gl(fun, hs[0], s),
                Flavor::Gpu(_) => self.math(fun, &hs, s),
            },
            _ => unreachable!("texture builtins handled above"),
        }
    }

    /// `dot(x, x)` (`x * x` for a scalar).
    fn length_sq(&mut self, x: Handle<E>, ty: &Ty, s: Span) -> Handle<E> {
        match ty {
            Ty::Vector(..) => self.math(naga::MathFunction::Dot, &[x, x], s),
            _ => self.append(E::Binary { op: naga::BinaryOperator::Multiply, left: x, right: x }, s),
        }
    }

    /// `1.0 / x` of a float scalar of type `ty` (`float` or `half`).
    fn reciprocal(&mut self, x: Handle<E>, ty: &Ty, s: Span) -> Handle<E> {
        let one = self.m.float_literal(1.0, ty.scalar().unwrap_or(Scalar::Float));
        let one = self.literal(one, s);
        self.append(E::Binary { op: naga::BinaryOperator::Divide, left: one, right: x }, s)
    }

    /// The `uint` a noise position hashes: `x + 198491317 * y + 6542989 * z`
    /// in wrapping arithmetic (daslang's `uint_noise_2D`/`3D`), computed in
    /// `uint`, where every target wraps.
    fn noise_position(&mut self, p: Handle<E>, ty: &Ty, s: Span) -> Handle<E> {
        use naga::BinaryOperator as Bo;
        let bits = self.append(E::As { expr: p, kind: naga::ScalarKind::Uint, convert: None }, s);
        let Ty::Vector(_, n) = *ty else { return bits };
        let mut sum = self.append(E::AccessIndex { base: bits, index: 0 }, s);
        for (i, prime) in [198491317u32, 6542989].into_iter().enumerate().take(n as usize - 1) {
            let c = self.append(E::AccessIndex { base: bits, index: i as u32 + 1 }, s);
            let k = self.literal(naga::Literal::U32(prime), s);
            let term = self.append(E::Binary { op: Bo::Multiply, left: k, right: c }, s);
            sum = self.append(E::Binary { op: Bo::Add, left: sum, right: term }, s);
        }
        sum
    }

    /// Squirrel Eiserloh's noise hash of `m` (with `seed` added after the
    /// first multiply, for `uint_noise_*`), as daslang computes it.
    fn noise_hash(&mut self, m: Handle<E>, seed: Option<Handle<E>>, s: Span) -> Handle<E> {
        use naga::BinaryOperator as Bo;
        let bin = |this: &mut Self, op: Bo, left: Handle<E>, k: u32| {
            let right = this.literal(naga::Literal::U32(k), s);
            this.append(E::Binary { op, left, right }, s)
        };
        let mut m = bin(self, Bo::Multiply, m, 0x68E3_1DA4);
        if let Some(seed) = seed {
            m = self.append(E::Binary { op: Bo::Add, left: m, right: seed }, s);
        }
        let t = bin(self, Bo::ShiftRight, m, 8);
        m = self.append(E::Binary { op: Bo::ExclusiveOr, left: m, right: t }, s);
        m = bin(self, Bo::Add, m, 0xB529_7A4D);
        let t = bin(self, Bo::ShiftLeft, m, 8);
        m = self.append(E::Binary { op: Bo::ExclusiveOr, left: m, right: t }, s);
        m = bin(self, Bo::Multiply, m, 0x1B56_C4E9);
        let t = bin(self, Bo::ShiftRight, m, 8);
        self.append(E::Binary { op: Bo::ExclusiveOr, left: m, right: t }, s)
    }
}
