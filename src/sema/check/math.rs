//! daslang's math module beyond the signature table: its constants
//! (`PI`, `FLT_EPSILON`, ...) and `sincos`, which writes two of its
//! arguments; and GLSL 1.x's texture function names (`texture2D`).

use super::*;

impl<'a, 'd> Checker<'a, 'd> {
    /// A constant of daslang's `math` or `builtin` module (`PI`,
    /// `FLT_EPSILON`, `INT_MAX`, ...) as a literal, or the error for one no
    /// shader type holds (`DBL_PI`).
    pub(super) fn builtin_constant(&mut self, id: &ast::Ident) -> Option<Expr> {
        let span = id.span;
        if let Some((value, ty)) = builtins::constant(&id.name) {
            let kind = match value {
                ConstValue::Float(v) => ExprKind::Float(v),
                ConstValue::Int(v) => ExprKind::Int(v),
                ConstValue::Uint(v) => ExprKind::Uint(v),
                _ => unreachable!("builtin constants are scalars"),
            };
            return Some(Expr { kind, ty, span });
        }
        let (_, why) = builtins::UNSUPPORTED_CONSTANTS.iter().find(|(n, _)| *n == id.name.as_str())?;
        self.diags.push(Diagnostic::error(format!("`{}` is not available in umbrac shaders", id.name), span).with_note(format!("help: {why}")));
        Some(err_expr(span))
    }

    /// `sincos(x, s, c)` as a statement: `s = sin(x)` and `c = cos(x)`,
    /// with `x` evaluated once (into a hidden `let`). `s` and `c` are
    /// assignable places, as daslang's `float&` parameters want.
    pub(super) fn check_sincos(&mut self, cx: &mut FnCtx<'a>, args: &'a [ast::Expr], span: Span, out: &mut Vec<Stmt>) {
        if args.len() != 3 {
            let d = Diagnostic::error(format!("wrong number of arguments: `sincos` takes 3 but {} were given", args.len()), span)
                .with_note("expected: sincos(x : float; s : float&; c : float&), which sets s = sin(x) and c = cos(x)");
            self.diags.push(d);
            return;
        }
        let x = self.check_expr(cx, &args[0]);
        let s = self.check_place(cx, &args[1]);
        let c = self.check_place(cx, &args[2]);
        let mut ok = true;
        for e in [&x, &s, &c] {
            if !e.ty.is_error() && e.ty != FLOAT {
                let d = Diagnostic::error(format!("type mismatch: the arguments of `sincos` are `float`, found `{}`", self.show(&e.ty)), e.span)
                    .with_note("expected: sincos(x : float; s : float&; c : float&)");
                self.diags.push(d);
                ok = false;
            }
            ok &= !e.ty.is_error();
        }
        if !ok {
            return;
        }
        let local = cx.locals.len();
        cx.locals.push(Local { name: ast::Name::new("sincos_x"), ty: FLOAT, mutable: false, by_ref: false, span: x.span });
        let xspan = x.span;
        out.push(Stmt::Local { local, init: Some(x), span });
        let arg = || Expr { kind: ExprKind::Local(local), ty: FLOAT, span: xspan };
        for (place, fun) in [(s, naga::MathFunction::Sin), (c, naga::MathFunction::Cos)] {
            let value = Expr { kind: ExprKind::Builtin(Builtin::Math(fun), vec![arg()]), ty: FLOAT, span };
            out.push(Stmt::Assign { target: place, op: None, value, span });
        }
    }

    /// `texture2D(s, uv)` and the other GLSL 1.x names: the modern call,
    /// with a warning saying so; the sampler must be of the type the old
    /// name was for.
    pub(super) fn check_legacy_texture_call(&mut self, cx: &mut FnCtx<'a>, callee: &ast::Ident, (b, kind, now): (Builtin, SamplerKind, &str), xs: Vec<Expr>, span: Span) -> Expr {
        let name = callee.name.as_str();
        if let Some(first) = xs.first().filter(|x| matches!(x.ty, Ty::Sampler(k) if k != kind)) {
            let d = Diagnostic::error(format!("type mismatch: `{name}` samples a `{}`, but this is a `{}`", kind.name(), self.show(&first.ty)), first.span)
                .with_note(format!("help: call `{now}(...)`, which takes every sampler type"));
            self.diags.push(d);
            return err_expr(span);
        }
        let d = Diagnostic::warning(format!("`{name}` is GLSL 1.x's name for `{now}`"), callee.span)
            .with_label(format!("compiled as `{now}`"))
            .with_note(format!("help: write `{now}(...)`"));
        self.diags.push(d);
        self.check_texture_call(cx, b, name, xs, span)
    }
}
