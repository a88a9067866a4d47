//! Expressions: precedence climbing over binary operators, unary and
//! postfix operators, pipes (`x |> f(y)`), calls (with `name = value`
//! arguments), constructors, indexing, fields, literals.

use super::*;

impl<'m> Parser<'_, 'm> {
    // ---- expressions ----

    pub(super) fn expr(&mut self) -> PResult<Expr> {
        let t = self.peek();
        self.enter(t)?;
        let r = self.ternary();
        self.leave();
        r
    }

    pub(super) fn ternary(&mut self) -> PResult<Expr> {
        let cond = self.binary(1)?;
        if self.peek().is(P::Question) {
            self.bump();
            self.skip_nl();
            let a = self.expr()?;
            self.expect(P::Colon)?;
            self.skip_nl();
            let b = self.expr()?;
            return Ok(Expr { span: cond.span.to(b.span), kind: ExprKind::Ternary(Box::new(cond), Box::new(a), Box::new(b)) });
        }
        Ok(cond)
    }

    pub(super) fn binary(&mut self, min: u8) -> PResult<Expr> {
        let mut lhs = self.unary()?;
        // `a + b + c` parses in a loop but builds a left-deep tree, which
        // later stages walk recursively: each operator counts as one level.
        let mut levels = 0;
        let r = loop {
            let t = self.peek();
            let Some((op, prec)) = binop(&t) else { break Ok(lhs) };
            if prec < min {
                break Ok(lhs);
            }
            if self.enter(t).is_err() {
                break Err(());
            }
            levels += 1;
            self.bump();
            self.skip_nl();
            match self.binary(prec + 1) {
                Ok(rhs) => lhs = Expr { span: lhs.span.to(rhs.span), kind: ExprKind::Binary(op, Box::new((lhs, rhs))) },
                Err(()) => break Err(()),
            }
        };
        self.depth -= levels;
        r
    }

    pub(super) fn unary(&mut self) -> PResult<Expr> {
        let t = self.peek();
        let op = match t.kind {
            TokKind::P(P::Minus) => UnaryOp::Neg,
            TokKind::P(P::Plus) => UnaryOp::Plus,
            TokKind::P(P::Bang) => UnaryOp::Not,
            TokKind::P(P::Tilde) => UnaryOp::BitNot,
            TokKind::P(P::PlusPlus) => UnaryOp::PreInc,
            TokKind::P(P::MinusMinus) => UnaryOp::PreDec,
            _ => return self.postfix(),
        };
        // Two levels: every output writes the operand in parentheses
        // (`-(-(a))`), and WGSL's parsers count both (tint: at most 127).
        self.enter(t)?;
        if let Err(()) = self.enter(t) {
            self.leave();
            return Err(());
        }
        self.bump();
        let r = self.unary();
        self.leave();
        self.leave();
        let e = r?;
        Ok(Expr { span: t.span.to(e.span), kind: ExprKind::Unary(op, Box::new(e)) })
    }

    pub(super) fn postfix(&mut self) -> PResult<Expr> {
        let e = self.primary()?;
        // Like a chain of binary operators, each postfix operator is a level.
        let depth = self.depth;
        let r = match self.postfix_ops(e) {
            Ok(e) if matches!(self.peek().kind, TokKind::P(P::RPipe | P::LPipe)) => self.pipes(e),
            r => r,
        };
        self.depth = depth;
        r
    }

    /// `x |> f(y)` is `f(x, y)` and `f(y) <| x` is `f(y, x)`: daslang's
    /// pipes, binding tighter than every operator but the postfix ones and
    /// chaining left to right (`x |> f() |> g()` is `g(f(x))`). A bare name
    /// is a call of no other arguments (`x |> normalize`).
    #[inline(never)]
    pub(super) fn pipes(&mut self, mut e: Expr) -> PResult<Expr> {
        loop {
            let t = self.peek();
            let forward = match t.kind {
                TokKind::P(P::RPipe) => true,
                // `f() <| $ { ... }`: a block argument, the statement's.
                TokKind::P(P::LPipe) if self.toks.get(self.pos + 1).is_some_and(|n| n.is(P::Dollar)) => return Ok(e),
                TokKind::P(P::LPipe) => false,
                _ => return Ok(e),
            };
            self.enter(t)?;
            self.bump();
            self.skip_nl();
            let rhs = self.primary().and_then(|p| self.postfix_ops(p))?;
            let (call, arg) = if forward { (rhs, e) } else { (e, rhs) };
            let span = call.span.to(arg.span);
            let (callee, mut args) = match call.kind {
                ExprKind::Call { callee, args } => (callee, args),
                ExprKind::Name(callee) => (callee, Vec::new()),
                _ => {
                    self.error_pipe(forward, call.span);
                    return Err(());
                }
            };
            if forward {
                args.insert(0, arg);
            } else {
                args.push(arg);
            }
            e = Expr { kind: ExprKind::Call { callee, args }, span: span.to(t.span) };
        }
    }

    #[inline(always)]
    pub(super) fn postfix_ops(&mut self, mut e: Expr) -> PResult<Expr> {
        loop {
            let t = self.peek();
            if matches!(t.kind, TokKind::P(P::Dot | P::LBracket | P::PlusPlus | P::MinusMinus)) {
                self.enter(t)?;
            }
            e = match t.kind {
                TokKind::P(P::Dot) => self.field_access(e)?,
                TokKind::P(P::LBracket) => self.index(e, t)?,
                TokKind::P(P::PlusPlus) | TokKind::P(P::MinusMinus) => {
                    self.bump();
                    let op = if t.is(P::PlusPlus) { UnaryOp::PostInc } else { UnaryOp::PostDec };
                    Expr { span: e.span.to(t.span), kind: ExprKind::Unary(op, Box::new(e)) }
                }
                TokKind::P(P::LParen) => {
                    self.error_msg(t, "only a function or type name can be called", "call of an expression");
                    return Err(());
                }
                _ => return Ok(e),
            };
        }
    }

    pub(super) fn field_access(&mut self, e: Expr) -> PResult<Expr> {
        self.bump();
        let name = self.ident("a field name or swizzle after '.'")?;
        Ok(Expr { span: e.span.to(name.span), kind: ExprKind::Field(Box::new(e), name) })
    }

    pub(super) fn index(&mut self, e: Expr, open: Token) -> PResult<Expr> {
        let (idx, close) = self.bracketed(open, P::RBracket)?;
        Ok(Expr { span: e.span.to(close.span), kind: ExprKind::Index(Box::new(e), Box::new(idx)) })
    }

    /// One expression between `open` (the next token) and its `close`, line
    /// breaks insignificant inside: `(e)`, `a[i]`, `T[N]`. Returns the closer
    /// too, for the span.
    pub(super) fn bracketed(&mut self, open: Token, close: P) -> PResult<(Expr, Token)> {
        self.bump();
        self.nl_skip += 1;
        self.open += 1;
        let e = self.expr()?;
        let end = self.expect_close(close, open, "")?;
        self.nl_skip -= 1;
        self.open -= 1;
        Ok((e, end))
    }

    /// `( a, b, ... )` or `[ a, b, ... ]` after the opener was consumed.
    pub(super) fn list(&mut self, opener: Token, close: P) -> PResult<(Vec<Expr>, Token)> {
        self.separated(opener, close, |p| p.expr())
    }

    /// Items parsed by `item`, separated by commas, up to `close` (a
    /// trailing comma allowed), with newlines inside the brackets skipped.
    #[inline(always)]
    fn separated(&mut self, opener: Token, close: P, mut item: impl FnMut(&mut Self) -> PResult<Expr>) -> PResult<(Vec<Expr>, Token)> {
        self.nl_skip += 1;
        self.open += 1;
        let mut items = Vec::new();
        let end = loop {
            if let Some(c) = self.eat(close) {
                break c;
            }
            items.push(item(self)?);
            if self.eat(P::Comma).is_some() {
                continue;
            }
            break self.expect_close(close, opener, "',' or ")?;
        };
        self.nl_skip -= 1;
        self.open -= 1;
        Ok((items, end))
    }

    /// `name = value, ...]` after a `[`: the arguments of a call by
    /// parameter name.
    #[cold]
    #[inline(never)]
    fn named_values(&mut self, opener: Token) -> PResult<(Vec<Expr>, Token)> {
        self.separated(opener, P::RBracket, |p| {
            let t = p.peek();
            if !p.named_at(p.pos) {
                p.err(t, "expected `name = value`: a call by parameter name names every argument".to_string(), "expected `name = value`");
                return Err(());
            }
            p.named_item(t)
        })
    }

    /// Whether the tokens at `pos` are `name =`.
    fn named_at(&self, pos: usize) -> bool {
        self.toks.get(pos).is_some_and(|t| t.kind == TokKind::Ident) && self.toks.get(pos + 1).is_some_and(|n| n.is(P::Eq))
    }

    /// `name = value`, with `name` the next token `t`.
    fn named_item(&mut self, t: Token) -> PResult<Expr> {
        self.bump();
        self.bump(); // `=`
        let value = self.expr()?;
        let name = Ident { name: self.texts.name(t.span), span: t.span };
        Ok(Expr { span: t.span.to(value.span), kind: ExprKind::Named(name, Box::new(value)) })
    }

    #[cold]
    #[inline(never)]
    pub(super) fn error_pipe(&mut self, forward: bool, at: Span) {
        let d = Diagnostic::error(format!("`{}` needs a function call on its {} side", t_text(forward), if forward { "right" } else { "left" }), at)
            .with_label("not a call")
            .with_note("help: write `x |> f(y)` for `f(x, y)`, or `f(y) <| x` for `f(y, x)`");
        self.push(d);
    }

    /// The arguments of a call after its `(`: expressions, or `name =
    /// value` (struct fields by name). Out of line, as `list` is: it keeps
    /// `primary` small enough to be inlined into the operator parsers.
    #[inline(never)]
    pub(super) fn call_args(&mut self, opener: Token) -> PResult<(Vec<Expr>, Token)> {
        self.separated(opener, P::RParen, |p| {
            let t = p.peek();
            // `f([a = 1, b = 2])`: daslang's call by parameter name, one
            // bracketed list of `name = value` (an array of them, which the
            // checker reads as the call's arguments).
            if t.is(P::LBracket) && p.named_at(p.pos + 1) {
                p.bump();
                let (values, close) = p.named_values(t)?;
                Ok(Expr { span: t.span.to(close.span), kind: ExprKind::Array { elem: None, items: values } })
            } else if p.named_at(p.pos) {
                p.named_item(t)
            } else {
                p.expr()
            }
        })
    }

    #[inline(always)]
    pub(super) fn primary(&mut self) -> PResult<Expr> {
        let t = self.peek();
        match t.kind {
            TokKind::Int => {
                self.bump();
                self.int_lit(t)
            }
            TokKind::Float => {
                self.bump();
                self.float_lit(t)
            }
            TokKind::Kw(Kw::True) | TokKind::Kw(Kw::False) => {
                self.bump();
                Ok(Expr { kind: ExprKind::Bool(t.is_kw(Kw::True)), span: t.span })
            }
            TokKind::Ident if self.host_construct(&t).is_some() => {
                self.refuse_host_construct(t);
                Err(())
            }
            TokKind::Ident => self.name_or_call(t),
            TokKind::P(P::LParen) => self.paren(t),
            TokKind::P(P::LBracket) => {
                self.bump();
                let (items, end) = self.list(t, P::RBracket)?;
                Ok(Expr { kind: ExprKind::Array { elem: None, items }, span: t.span.to(end.span) })
            }
            _ => {
                self.error_primary(t);
                Err(())
            }
        }
    }

    /// daslang host constructs its shader emitters refuse (glsl_internal.das),
    /// at `t`: what each is and what to write instead. A word counts only
    /// where no shader code could continue with it (`cast<`, `new T`).
    pub(super) fn host_construct(&self, t: &Token) -> Option<(&'static str, &'static str, &'static str)> {
        let next = self.toks.get(self.pos + 1).map(|n| n.kind);
        let word_then = |what| t.kind == TokKind::Ident && matches!(next, Some(TokKind::Ident | TokKind::P(P::Lt | P::LBrace))) && self.text(t) == what;
        Some(match t.kind {
            TokKind::P(P::QuestionQuestion) => ("??", "null coalescing", "shader values are never null: test a condition with `?:`"),
            TokKind::P(P::QuestionDot) => ("?.", "safe navigation", "shader values are never null: read the field with `.`"),
            TokKind::P(P::QuestionBracket) => ("?[", "a safe index", "index with `[]`; the targets clamp indices to the bounds"),
            TokKind::P(P::At | P::AtAt) => ("@", "a lambda or function address", "call a function by name"),
            TokKind::P(P::Dollar) => ("$", "a block", "blocks are host code; a shader takes one only in `unroll() $ { for ... }`, a statement of its own"),
            TokKind::Ident if matches!(next, Some(TokKind::Ident | TokKind::P(P::LParen))) && matches!(self.text(t), "is" | "as") => {
                if self.text(t) == "is" { ("is", "a type or variant test", "shaders have no variants: use an enumeration and `==`") } else { ("as", "a variant cast", "shaders have no variants: use an enumeration and `==`") }
            }
            _ if word_then("cast") || word_then("upcast") => ("cast", "daslang's type cast", "convert with a constructor: `int(x)`, `float3(v)`; `reinterpret<T>(x)` for the bits"),
            _ if word_then("new") => ("new", "heap allocation", "shaders have no heap: use a local `var`"),
            _ if word_then("delete") => ("delete", "freeing memory", "shaders have no heap"),
            _ if word_then("typeinfo") => ("typeinfo", "reflection", "reflection is host code: pass the value in"),
            _ if word_then("yield") => ("yield", "a generator", "shaders have no generators: return a value"),
            _ if word_then("try") => ("try", "`try`/`recover`", "shaders have no exceptions"),
            _ if word_then("goto") || word_then("label") => ("goto", "`goto`/`label`", "use `if`, `break` and `continue`"),
            _ => return None,
        })
    }

    /// Reports a [`Self::host_construct`] at `t`; whether `t` is one.
    #[cold]
    #[inline(never)]
    pub(super) fn refuse_host_construct(&mut self, t: Token) -> bool {
        let Some((text, what, help)) = self.host_construct(&t) else { return false };
        let text = if t.kind == TokKind::Ident { self.text(&t) } else { text };
        let d = Diagnostic::error(format!("`{text}` ({what}) is not supported in shader code"), t.span)
            .with_label(format!("daslang's {what}"))
            .with_note("daslang's shader emitters refuse it too: it is host code")
            .with_note(format!("help: {help}"));
        self.push(d);
        true
    }

    #[cold]
    #[inline(never)]
    pub(super) fn error_primary(&mut self, t: Token) {
        if self.refuse_host_construct(t) {
            return;
        }
        match t.kind {
            TokKind::Str | TokKind::Char => {
                let msg = format!("{}s are not supported in shader code", self.describe(&t));
                self.err(t, msg, "not supported here");
            }
            TokKind::Newline | TokKind::Eof | TokKind::Kw(_) | TokKind::P(P::RBrace) => self.error_expected(t, "an expression"),
            _ => self.error_unexpected(t, "expected an expression"),
        }
    }

    pub(super) fn paren(&mut self, open: Token) -> PResult<Expr> {
        let (e, close) = self.bracketed(open, P::RParen)?;
        Ok(Expr { kind: ExprKind::Paren(Box::new(e)), span: open.span.to(close.span) })
    }

    pub(super) fn name_or_call(&mut self, t: Token) -> PResult<Expr> {
        self.bump();
        let mut name = Ident { name: self.texts.name(t.span), span: t.span };
        let mut next = self.peek();
        // `module::name` (`math::sin`, `_::helper`): every module's names
        // are in one namespace (`syntax::modules`), so the qualifier goes.
        if next.is(P::ColonColon) {
            self.bump();
            let n = self.peek();
            if n.kind != TokKind::Ident {
                self.error_expected(n, "a name after `::`");
                return Err(());
            }
            self.bump();
            name = Ident { name: self.texts.name(n.span), span: n.span };
            next = self.peek();
        }
        if next.is(P::Lt) && name.name == "fixed_array" {
            self.bump();
            let elem = self.ty()?;
            self.expect(P::Gt)?;
            let po = self.expect(P::LParen)?;
            let (items, end) = self.list(po, P::RParen)?;
            return Ok(Expr { kind: ExprKind::Array { elem: Some(elem), items }, span: t.span.to(end.span) });
        }
        if next.is(P::LParen) && name.name == "fixed_array" {
            return self.untyped_fixed_array(t, next);
        }
        if next.is(P::Lt) && name.name == "reinterpret" {
            return self.reinterpret(t);
        }
        if next.is(P::LParen) {
            self.bump();
            let (args, end) = self.call_args(next)?;
            return Ok(Expr { kind: ExprKind::Call { callee: name, args }, span: t.span.to(end.span) });
        }
        Ok(Expr { kind: ExprKind::Name(name), span: t.span })
    }

    /// `reinterpret<T>(x)`: a type name between the angle brackets, one
    /// value in the parentheses.
    #[inline(never)]
    pub(super) fn reinterpret(&mut self, t: Token) -> PResult<Expr> {
        self.bump(); // `<`
        let ty = self.ident("a type name")?;
        self.expect(P::Gt)?;
        let po = self.peek();
        if !po.is(P::LParen) {
            self.error_expected(po, "'('");
            return Err(());
        }
        let (value, end) = self.bracketed(po, P::RParen)?;
        Ok(Expr { kind: ExprKind::Reinterpret(ty, Box::new(value)), span: t.span.to(end.span) })
    }

    /// `fixed_array(a, b)`: the element type is the values'.
    #[inline(never)]
    pub(super) fn untyped_fixed_array(&mut self, t: Token, open: Token) -> PResult<Expr> {
        self.bump();
        let (items, end) = self.list(open, P::RParen)?;
        Ok(Expr { kind: ExprKind::Array { elem: None, items }, span: t.span.to(end.span) })
    }

    #[inline(never)]
    pub(super) fn int_lit(&mut self, t: Token) -> PResult<Expr> {
        let text = self.text(&t);
        let (digits, suffix, radix) = if let Some(h) = text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
            let k = h.find(|c: char| !c.is_ascii_hexdigit()).unwrap_or(h.len());
            (&h[..k], &h[k..], 16)
        } else {
            let k = text.find(|c: char| !c.is_ascii_digit()).unwrap_or(text.len());
            (&text[..k], &text[k..], 10)
        };
        if digits.is_empty() {
            self.err(t, format!("hexadecimal literal `{text}` has no digits"), "no digits");
            return Err(());
        }
        let value = match u64::from_str_radix(digits, radix) {
            Ok(v) => v,
            Err(_) => {
                self.err(t, format!("integer literal `{text}` is too large"), "too large");
                return Err(());
            }
        };
        let kind = match suffix {
            "" => ExprKind::Int(value, IntSuffix::None),
            "u" | "U" => ExprKind::Int(value, IntSuffix::Unsigned),
            // Rounded once, straight to f32.
            "f" | "F" if radix == 10 => ExprKind::Float(value as f32 as f64),
            "h" | "H" if radix == 10 => return self.half_lit(t, digits),
            "d" | "D" | "lf" | "LF" if radix == 10 => return self.double_error(t),
            _ => {
                let msg = format!("unsupported suffix `{suffix}` on integer literal `{text}`");
                let d = Diagnostic::error(msg, t.span).with_label("unsupported suffix").with_note("integer literals take `u` (uint) or no suffix (int)");
                self.push(d);
                return Err(());
            }
        };
        Ok(Expr { kind, span: t.span })
    }

    #[inline(never)]
    pub(super) fn float_lit(&mut self, t: Token) -> PResult<Expr> {
        let text = self.text(&t);
        let body = text.trim_end_matches(|c: char| c.is_ascii_alphabetic() || c == '_');
        let suffix = &text[body.len()..];
        match suffix {
            "" | "f" | "F" => {}
            "h" | "H" => return self.half_lit(t, body),
            "d" | "D" | "lf" | "LF" => return self.double_error(t),
            _ => {
                let msg = format!("unsupported suffix `{suffix}` on number `{text}`");
                let d = Diagnostic::error(msg, t.span).with_label("unsupported suffix").with_note("float literals take `f` (float), `h` (half) or no suffix");
                self.push(d);
                return Err(());
            }
        }
        // Parsed straight to f32 (correctly rounded once; through f64 a
        // decimal near an f32 midpoint would round twice) and kept exactly.
        match short_decimal(body).map_or_else(|| body.parse::<f32>(), Ok) {
            Ok(v) if v.is_infinite() => {
                self.err(t, "float literal is out of range for `float`".to_string(), "too large for `float` (largest 3.4028235e38)");
                Err(())
            }
            Ok(v) => Ok(Expr { kind: ExprKind::Float(v as f64), span: t.span }),
            Err(_) => {
                self.err(t, format!("invalid number `{text}`"), "invalid number");
                Err(())
            }
        }
    }

    /// `1.5h`, `2h`: the decimal `digits`, rounded once to binary16 (from
    /// its correctly rounded f64, which is within half an f64 ulp: a
    /// second rounding to binary16 can only differ for a decimal of more
    /// than 17 digits lying that close to a binary16 midpoint).
    #[inline(never)]
    pub(super) fn half_lit(&mut self, t: Token, digits: &str) -> PResult<Expr> {
        let text = self.text(&t);
        match digits.parse::<f64>() {
            Ok(v) => {
                let h = half::f16::from_f64(v);
                if h.is_infinite() {
                    self.err(t, format!("`{text}` is out of range for `half`"), "too large for `half` (largest 65504)");
                    return Err(());
                }
                Ok(Expr { kind: ExprKind::Half(h.to_f64()), span: t.span })
            }
            Err(_) => {
                self.err(t, format!("invalid number `{text}`"), "invalid number");
                Err(())
            }
        }
    }

    pub(super) fn double_error(&mut self, t: Token) -> PResult<Expr> {
        let msg = format!("double-precision literal `{}` is not supported in shader code", self.text(&t));
        let d = Diagnostic::error(msg, t.span)
            .with_label("double literal")
            .with_note("help: drop the `d` suffix to make it a float");
        self.push(d);
        Err(())
    }
}

fn t_text(forward: bool) -> &'static str {
    if forward {
        "|>"
    } else {
        "<|"
    }
}

/// Powers of ten that are exact in f32 (5^10 < 2^24).
const POW10: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];

/// `digits[.digits]` with fewer than 2^24 as its digits and at most ten
/// after the point, as f32: the digits and the power of ten are both exact
/// in f32, so one division rounds the decimal correctly, to the same value
/// as `str::parse` (Clinger's fast path), without its general machinery.
/// `None` for anything else (exponents, long mantissas).
fn short_decimal(s: &str) -> Option<f32> {
    let (mut m, mut digits, mut frac, mut point) = (0u32, 0usize, 0usize, false);
    for &c in s.as_bytes() {
        match c {
            b'0'..=b'9' => {
                m = m.checked_mul(10)?.checked_add((c - b'0') as u32)?;
                digits += 1;
                frac += point as usize;
            }
            b'.' if !point => point = true,
            _ => return None,
        }
    }
    (digits > 0 && m < 1 << 24 && frac < POW10.len()).then(|| m as f32 / POW10[frac])
}

#[cfg(test)]
mod tests {
    use super::short_decimal;

    /// The fast path gives exactly what `str::parse` gives, where it applies.
    #[test]
    fn short_decimals_round_like_parse() {
        let mut n = 0;
        let mut check = |s: &str| {
            if let Some(v) = short_decimal(s) {
                assert_eq!(v.to_bits(), s.parse::<f32>().unwrap().to_bits(), "{s}");
                n += 1;
            }
        };
        for m in (0..1u32 << 24).step_by(9973).chain([1, 5, 16777215, 16777214, 8388609, 8388607, 9999999, 1234567]) {
            let digits = m.to_string();
            for frac in 0..=10usize {
                let s = if frac == 0 {
                    format!("{digits}.")
                } else if frac >= digits.len() {
                    format!(".{}{digits}", "0".repeat(frac - digits.len()))
                } else {
                    format!("{}.{}", &digits[..digits.len() - frac], &digits[digits.len() - frac..])
                };
                check(&s);
                check(&format!("0{s}"));
            }
        }
        for s in ["1.0", "0.5", "100.0", "0.0", "1.", ".5", "3.14159", "0.1", "0.3", "2.5", "1024.0", "0.0001"] {
            check(s);
        }
        assert!(n > 10_000);
        for s in ["", ".", "1e3", "1.0.0", "16777216.0", "0.00000000001", "1_0", "x"] {
            assert!(short_decimal(s).is_none() || s.parse::<f32>().is_ok(), "{s}");
        }
        assert_eq!(short_decimal("16777216.0"), None);
        assert_eq!(short_decimal("."), None);
    }
}
