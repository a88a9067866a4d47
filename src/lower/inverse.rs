//! `inverse(m)` as helper functions in naga IR. WGSL has no matrix
//! inverse (naga's WGSL writer refuses `MathFunction::Inverse`), so every
//! target gets the same closed-form inverse built from cross and dot
//! products: one function per matrix size a module uses, and the same
//! arithmetic, so the same results, on every target. A singular matrix
//! gives inf/NaN components, as GLSL leaves it undefined.

use naga::{Expression as E, Handle, Statement};

use super::module::ModuleBuilder;
use crate::sema::{Scalar, Ty};

/// Straight-line code in one function: arguments and literals first (they
/// need no emitting), then one emitted range.
struct Body<'a, 'p> {
    m: &'a mut ModuleBuilder<'p>,
    func: naga::Function,
    emitter: naga::proc::Emitter,
}

impl Body<'_, '_> {
    fn expr(&mut self, e: E) -> Handle<E> {
        self.func.expressions.append(e, naga::Span::UNDEFINED)
    }
    fn column(&mut self, m: Handle<E>, i: u32) -> Handle<E> {
        self.expr(E::AccessIndex { base: m, index: i })
    }
    fn xyz(&mut self, v: Handle<E>) -> Handle<E> {
        use naga::SwizzleComponent::{X, Y, Z};
        self.expr(E::Swizzle { size: naga::VectorSize::Tri, vector: v, pattern: [X, Y, Z, X] })
    }
    fn math(&mut self, fun: naga::MathFunction, a: Handle<E>, b: Option<Handle<E>>) -> Handle<E> {
        self.expr(E::Math { fun, arg: a, arg1: b, arg2: None, arg3: None })
    }
    fn cross(&mut self, a: Handle<E>, b: Handle<E>) -> Handle<E> {
        self.math(naga::MathFunction::Cross, a, Some(b))
    }
    fn dot(&mut self, a: Handle<E>, b: Handle<E>) -> Handle<E> {
        self.math(naga::MathFunction::Dot, a, Some(b))
    }
    fn bin(&mut self, op: naga::BinaryOperator, left: Handle<E>, right: Handle<E>) -> Handle<E> {
        self.expr(E::Binary { op, left, right })
    }
    fn mul(&mut self, a: Handle<E>, b: Handle<E>) -> Handle<E> {
        self.bin(naga::BinaryOperator::Multiply, a, b)
    }
    fn sub(&mut self, a: Handle<E>, b: Handle<E>) -> Handle<E> {
        self.bin(naga::BinaryOperator::Subtract, a, b)
    }
    fn add(&mut self, a: Handle<E>, b: Handle<E>) -> Handle<E> {
        self.bin(naga::BinaryOperator::Add, a, b)
    }
    /// `a * k - b * l`.
    fn scaled_difference(&mut self, a: Handle<E>, k: Handle<E>, b: Handle<E>, l: Handle<E>) -> Handle<E> {
        let (ak, bl) = (self.mul(a, k), self.mul(b, l));
        self.sub(ak, bl)
    }
    /// `cross(a, b) op v * k`.
    fn cross_then(&mut self, a: Handle<E>, b: Handle<E>, op: naga::BinaryOperator, v: Handle<E>, k: Handle<E>) -> Handle<E> {
        let (ab, vk) = (self.cross(a, b), self.mul(v, k));
        self.bin(op, ab, vk)
    }
    fn neg(&mut self, a: Handle<E>) -> Handle<E> {
        self.expr(E::Unary { op: naga::UnaryOperator::Negate, expr: a })
    }
    fn compose(&mut self, ty: &Ty, components: Vec<Handle<E>>) -> Handle<E> {
        let ty = self.m.ty(ty);
        self.expr(E::Compose { ty, components })
    }
}

/// The module's `inverse_NxN` function for `n` x `n` matrices (2-4),
/// built on first use.
pub fn function(m: &mut ModuleBuilder<'_>, n: u8) -> Handle<naga::Function> {
    let slot = usize::from(n - 2);
    if let Some(h) = m.inverse_functions[slot] {
        return h;
    }
    let mat = Ty::Matrix(n, n);
    let mat_ty = m.ty(&mat);
    let mut func = naga::Function { name: Some(format!("inverse_{n}x{n}")), ..Default::default() };
    func.arguments.push(naga::FunctionArgument { name: Some("m".into()), ty: mat_ty, binding: None });
    func.result = Some(naga::FunctionResult { ty: mat_ty, binding: None });
    let mut b = Body { m, func, emitter: Default::default() };
    let arg = b.expr(E::FunctionArgument(0));
    let one = b.expr(E::Literal(naga::Literal::F32(1.0)));
    b.emitter.start(&b.func.expressions);
    let result = match n {
        2 => inverse_2x2(&mut b, arg, one),
        3 => inverse_3x3(&mut b, arg, one),
        _ => inverse_4x4(&mut b, arg, one),
    };
    let mut func = b.func;
    if let Some((emit, span)) = b.emitter.finish(&func.expressions) {
        func.body.push(emit, span);
    }
    func.body.push(Statement::Return { value: Some(result) }, naga::Span::UNDEFINED);
    let h = b.m.module.functions.append(func, naga::Span::UNDEFINED);
    b.m.inverse_functions[slot] = Some(h);
    h
}

/// Columns (a, b) and (c, d): the inverse's columns are (d, -b) and
/// (-c, a) over the determinant ad - cb.
fn inverse_2x2(f: &mut Body, m: Handle<E>, one: Handle<E>) -> Handle<E> {
    let (c0, c1) = (f.column(m, 0), f.column(m, 1));
    let (x0, y0, x1, y1) = (f.column(c0, 0), f.column(c0, 1), f.column(c1, 0), f.column(c1, 1));
    let det = f.scaled_difference(x0, y1, x1, y0);
    let (ny0, nx1) = (f.neg(y0), f.neg(x1));
    let f2 = Ty::Vector(Scalar::Float, 2);
    let k0 = f.compose(&f2, vec![y1, ny0]);
    let k1 = f.compose(&f2, vec![nx1, x0]);
    let adj = f.compose(&Ty::Matrix(2, 2), vec![k0, k1]);
    let inv_det = f.bin(naga::BinaryOperator::Divide, one, det);
    f.mul(adj, inv_det)
}

/// Columns a, b, c: the inverse's rows are b x c, c x a and a x b over the
/// determinant a . (b x c).
fn inverse_3x3(f: &mut Body, m: Handle<E>, one: Handle<E>) -> Handle<E> {
    let (c0, c1, c2) = (f.column(m, 0), f.column(m, 1), f.column(m, 2));
    let r0 = f.cross(c1, c2);
    let r1 = f.cross(c2, c0);
    let r2 = f.cross(c0, c1);
    let det = f.dot(c0, r0);
    let rows = f.compose(&Ty::Matrix(3, 3), vec![r0, r1, r2]);
    let adj = f.math(naga::MathFunction::Transpose, rows, None);
    let inv_det = f.bin(naga::BinaryOperator::Divide, one, det);
    f.mul(adj, inv_det)
}

/// Columns (a, x), (b, y), (c, z), (d, w) with a-d their first three
/// components: with s = a x b, t = c x d, u = y a - x b and v = w c - z d,
/// the determinant is s . v + t . u, and the inverse's rows are
/// (b x v + y t, -b . t), (v x a - x t, a . t), (d x u + w s, -d . s) and
/// (u x c - z s, c . s) over it (the 4x4 inverse as four 3D cross
/// products, as in Lengyel's "Foundations of Game Engine Development").
fn inverse_4x4(f: &mut Body, m: Handle<E>, one: Handle<E>) -> Handle<E> {
    let cols: Vec<Handle<E>> = (0..4).map(|i| f.column(m, i)).collect();
    let [a, b, c, d] = [0, 1, 2, 3].map(|i| f.xyz(cols[i]));
    let [x, y, z, w] = [0, 1, 2, 3].map(|i| f.column(cols[i], 3));
    let s = f.cross(a, b);
    let t = f.cross(c, d);
    let u = f.scaled_difference(a, y, b, x);
    let v = f.scaled_difference(c, w, d, z);
    let det = {
        let sv = f.dot(s, v);
        let tu = f.dot(t, u);
        f.add(sv, tu)
    };
    let inv_det = f.bin(naga::BinaryOperator::Divide, one, det);
    let (s, t, u, v) = (f.mul(s, inv_det), f.mul(t, inv_det), f.mul(u, inv_det), f.mul(v, inv_det));
    use naga::BinaryOperator::{Add, Subtract};
    let r0 = f.cross_then(b, v, Add, t, y);
    let r1 = f.cross_then(v, a, Subtract, t, x);
    let r2 = f.cross_then(d, u, Add, s, w);
    let r3 = f.cross_then(u, c, Subtract, s, z);
    let (bt, ds) = (f.dot(b, t), f.dot(d, s));
    let (e0, e1, e2, e3) = (f.neg(bt), f.dot(a, t), f.neg(ds), f.dot(c, s));
    let f4 = Ty::Vector(Scalar::Float, 4);
    let rows = [(r0, e0), (r1, e1), (r2, e2), (r3, e3)].map(|(r, e)| f.compose(&f4, vec![r, e]));
    let rows = f.compose(&Ty::Matrix(4, 4), rows.to_vec());
    f.math(naga::MathFunction::Transpose, rows, None)
}
