//! Items: annotations, functions and their headers, structs and fields,
//! shader globals with their qualifiers, `let` constants, and type
//! expressions.

use super::*;

impl<'m> Parser<'_, 'm> {
    // ---- items ----

    pub(super) fn annotations(&mut self) -> PResult<Vec<Annotation>> {
        let mut out = Vec::new();
        loop {
            self.skip_nl();
            let Some(open) = self.eat(P::LBracket) else { break };
            self.nl_skip += 1;
            loop {
                let name = self.ident("an annotation name")?;
                let mut args = Vec::new();
                let mut end = name.span;
                if let Some(po) = self.eat(P::LParen) {
                    if self.eat(P::RParen).is_none() {
                        loop {
                            let an = self.ident("an annotation argument name")?;
                            let value = if self.eat(P::Eq).is_some() {
                                let t = self.peek();
                                if t.kind == TokKind::Str {
                                    self.bump();
                                    let raw = self.text(&t);
                                    let body = raw.get(1..raw.len().saturating_sub(1)).unwrap_or("");
                                    Some(Expr { kind: ExprKind::Str(unescape(body)), span: t.span })
                                } else {
                                    Some(self.expr()?)
                                }
                            } else {
                                None
                            };
                            args.push(AnnotationArg { name: an, value });
                            if self.eat(P::Comma).is_some() {
                                continue;
                            }
                            break;
                        }
                        self.expect_close(P::RParen, po, "',' or ")?;
                    }
                    end = self.last;
                }
                out.push(Annotation { span: name.span.to(end), name, args });
                if self.eat(P::Comma).is_none() {
                    break;
                }
            }
            self.expect_close(P::RBracket, open, "',' or ")?;
            self.nl_skip -= 1;
        }
        Ok(out)
    }

    pub(super) fn function(&mut self) -> Option<FunctionDecl> {
        let start = self.raw_peek().span;
        let header = self.function_header();
        let (annotations, name, params, ret) = match header {
            Ok(h) => h,
            Err(()) => {
                // Still check the body, if one can be found.
                self.nl_skip = 0;
                self.open = 0;
                if let Some(k) = self.toks[self.pos.min(self.toks.len())..].iter().position(|t| t.is(P::LBrace)) {
                    self.pos += k;
                    let _ = self.block();
                }
                return None;
            }
        };
        // `def f(x : int) => x + 1`: a body of one returned expression.
        if let Some(arrow) = self.eat(P::FatArrow) {
            self.skip_nl();
            let value = self.expr().ok()?;
            let span = arrow.span.to(value.span);
            let ret_stmt = Stmt { kind: StmtKind::Return(Some(value)), span };
            let body = Block { stmts: vec![ret_stmt], span };
            self.expect_line_end("the function").ok()?;
            return Some(FunctionDecl { annotations, name, params, ret, span: start.to(span), body });
        }
        self.skip_nl();
        let body = self.block().ok()?;
        Some(FunctionDecl { annotations, name, params, ret, span: start.to(body.span), body })
    }

    /// Skips visibility and storage words after `def`, `struct`, `let` or
    /// `enum` (`def private f`): `private` and `public` are visibility only,
    /// which a shader has no use for; `shared` and `static` change nothing
    /// a shader can see either. Another daslang modifier is refused by name.
    pub(super) fn modifiers(&mut self) -> PResult<()> {
        loop {
            let t = self.peek();
            let next = self.toks.get(self.pos + 1).copied();
            if t.kind != TokKind::Ident || !next.is_some_and(|n| n.kind == TokKind::Ident) {
                return Ok(());
            }
            match self.text(&t) {
                "private" | "public" | "shared" | "static" => {
                    self.bump();
                }
                m @ ("override" | "abstract" | "sealed" | "template" | "inscope" | "unsafe") => {
                    let msg = format!("`{m}` is not supported in shader code");
                    self.err(t, msg, "a host-only modifier");
                    return Err(());
                }
                _ => return Ok(()),
            }
        }
    }

    #[allow(clippy::type_complexity)]
    pub(super) fn function_header(&mut self) -> PResult<(Vec<Annotation>, Ident, Vec<Param>, Option<TypeExpr>)> {
        let annotations = self.annotations()?;
        self.skip_nl();
        self.bump(); // `def`
        self.modifiers()?;
        let name = self.ident("a function name")?;
        let mut params = Vec::new();
        if let Some(po) = self.eat(P::LParen) {
            self.nl_skip += 1;
            if self.eat(P::RParen).is_none() {
                loop {
                    self.param_group(&mut params)?;
                    if self.eat(P::Semi).is_some() || self.eat(P::Comma).is_some() {
                        continue;
                    }
                    self.expect_close(P::RParen, po, "';' or ")?;
                    break;
                }
            }
            self.nl_skip -= 1;
        }
        let ret = if self.eat(P::Colon).is_some() || self.eat(P::Arrow).is_some() { Some(self.ty()?) } else { None };
        Ok((annotations, name, params, ret))
    }

    /// `[var] a, b : T [const] [&] [= default]`: one group of parameters
    /// sharing a type, appended to `params`.
    pub(super) fn param_group(&mut self, params: &mut Vec<Param>) -> PResult<()> {
        let mutable = self.peek().is_kw(Kw::Var) && {
            self.bump();
            true
        };
        let names = self.names("a parameter name", false)?;
        let t = self.peek();
        if !t.is(P::Colon) {
            let msg = format!("expected ':' and the parameter's type, found {}", self.describe(&t));
            self.err(t, msg, "expected ':'");
            return Err(());
        }
        self.bump();
        let ty = self.ty()?;
        let mut constant = None;
        let mut by_ref = false;
        loop {
            let t = self.peek();
            if t.kind == TokKind::Ident && self.text(&t) == "const" && constant.is_none() && !by_ref {
                constant = Some(self.bump().span);
            } else if t.is(P::Amp) && !by_ref {
                self.bump();
                by_ref = true;
            } else {
                break;
            }
        }
        let default = if self.eat(P::Eq).is_some() { Some(self.expr()?) } else { None };
        share_among(names, (ty, default), |n, (ty, default)| {
            params.push(Param { span: n.span.to(ty.span), name: n, ty, mutable, by_ref, constant, default })
        });
        Ok(())
    }

    pub(super) fn structure(&mut self) -> PResult<StructDecl> {
        let annotations = self.annotations()?;
        self.skip_nl();
        let kw = self.bump();
        if kw.is_kw(Kw::Class) {
            self.err(kw, "classes are not supported in shader code".into(), "used by a shader here");
            return Err(());
        }
        self.modifiers()?;
        let name = self.ident("a struct name")?;
        self.skip_nl();
        let open = self.expect(P::LBrace)?;
        let mut fields = Vec::new();
        let end = self.braced_lines(
            open,
            |p| {
                fields.extend(p.field()?);
                Ok(())
            },
            |p, t| {
                let msg = format!("expected newline after the field, found {}", p.describe(&t));
                p.err(t, msg, "expected the end of the line");
            },
        )?;
        Ok(StructDecl { span: kw.span.to(end), annotations, name, fields })
    }

    pub(super) fn field(&mut self) -> PResult<Vec<Field>> {
        let names = self.names("a field name", false)?;
        let ty = if self.peek().is(P::Eq) {
            None
        } else {
            self.expect(P::Colon)?;
            Some(self.ty()?)
        };
        let init = if self.eat(P::Eq).is_some() { Some(self.expr()?) } else { None };
        let mut fields = Vec::with_capacity(names.count());
        share_among(names, (ty, init), |n, (ty, init)| {
            let end = ty.as_ref().map(|t| t.span).or(init.as_ref().map(|e| e.span)).unwrap_or(n.span);
            fields.push(Field { span: n.span.to(end), name: n, ty, init })
        });
        Ok(fields)
    }

    /// `enum [private] Name [: base] { A; B = value }`: values on their own
    /// lines, or separated by `;` or `,`.
    pub(super) fn enumeration(&mut self) -> PResult<EnumDecl> {
        let kw = self.bump(); // `enum`
        self.modifiers()?;
        let name = self.ident("an enumeration name")?;
        let base = if self.eat(P::Colon).is_some() { Some(self.ident("a storage type such as `int` or `uint`")?) } else { None };
        self.skip_nl();
        let open = self.expect(P::LBrace)?;
        let mut values = Vec::new();
        let end = self.braced_lines(
            open,
            |p| loop {
                let n = p.ident("an enumeration value name")?;
                let v = if p.eat(P::Eq).is_some() { Some(p.expr()?) } else { None };
                values.push((n, v));
                if p.eat(P::Comma).is_none() {
                    return Ok(());
                }
                p.skip_nl();
                if p.raw_peek().is(P::RBrace) {
                    return Ok(());
                }
            },
            |p, t| {
                let msg = format!("expected newline after the enumeration value, found {}", p.describe(&t));
                p.err(t, msg, "expected the end of the line");
            },
        )?;
        Ok(EnumDecl { span: kw.span.to(end), name, base, values })
    }

    pub(super) fn qualifier(&mut self) -> PResult<Qualifier> {
        let at = self.bump();
        let t = self.peek();
        let name = match t.kind {
            TokKind::Ident => self.text(&t),
            TokKind::Kw(Kw::In) => "in",
            _ => {
                let msg = format!("expected a qualifier name after '@', found {}", self.describe(&t));
                self.err(t, msg, "expected a name such as `uniform`, `in`, `out`, `location`");
                return Err(());
            }
        };
        self.bump();
        let value = if self.peek().is(P::Eq) {
            self.bump();
            let v = self.peek();
            // `@format = r32f` or, as dasGlsl reads its string argument,
            // `@format = "r32f"`.
            if name == "format" && matches!(v.kind, TokKind::Ident | TokKind::Str) {
                self.bump();
                let inner = if v.kind == TokKind::Str { Span::new(v.span.start + 1, v.span.end.saturating_sub(1).max(v.span.start + 1)) } else { v.span };
                let id = Ident { name: self.texts.name(inner), span: v.span };
                return Ok(Qualifier { kind: QualifierKind::Format(id), span: at.span.to(v.span) });
            }
            if name == "format" {
                let msg = format!("expected a format name after `@format =`, found {}", self.describe(&v));
                self.err(v, msg, "expected a name such as `rgba8` or `\"r32f\"`");
                return Err(());
            }
            if v.kind != TokKind::Int {
                if matches!(name, "location" | "stage" | "set" | "binding" | "constant_id") {
                    let msg = format!("expected an integer after `@{name} =`, found {}", self.describe(&v));
                    self.err(v, msg, "expected an integer");
                    return Err(());
                }
                // Some other qualifier with a value: semantic analysis reports it.
                let e = self.expr()?;
                return Ok(Qualifier { kind: QualifierKind::Other(name.to_string()), span: at.span.to(e.span) });
            }
            self.bump();
            match self.text(&v).parse::<i64>() {
                Ok(n) => Some(n),
                Err(_) => {
                    let msg = format!("`{}` is not a valid value for `@{name}`", self.text(&v));
                    self.err(v, msg, "expected a small non-negative integer");
                    return Err(());
                }
            }
        } else {
            None
        };
        let span = at.span.to(self.last);
        let kind = match name {
            "uniform" => QualifierKind::Uniform,
            "in" => QualifierKind::In,
            "out" => QualifierKind::Out,
            "inout" => QualifierKind::InOut,
            "location" => QualifierKind::Location(value),
            "stage" => QualifierKind::Stage(value),
            // Bare `@format`: dasGlsl's default, rgba8.
            "format" if value.is_none() => QualifierKind::Format(Ident { name: "rgba8".into(), span: t.span }),
            "constant_id" => match value {
                Some(v) => QualifierKind::ConstantId(v),
                None => {
                    let msg = "`@constant_id` needs a number: `@constant_id = N`".to_string();
                    self.err(Token::new(TokKind::Ident, span), msg, "no value");
                    return Err(());
                }
            },
            "set" | "binding" => match value {
                Some(v) if name == "set" => QualifierKind::Set(v),
                Some(v) => QualifierKind::Binding(v),
                None => {
                    let msg = format!("`@{name}` needs a number: `@{name} = N`");
                    self.err(Token::new(TokKind::Ident, span), msg, "no value");
                    return Err(());
                }
            },
            other => QualifierKind::Other(other.to_string()),
        };
        Ok(Qualifier { kind, span })
    }

    /// Skips daslang's visibility and sharing modifiers after `var`/`let`
    /// (`private`, `public`, `shared`): they mean nothing to a shader.
    fn skip_modifiers(&mut self) {
        loop {
            let t = self.peek();
            let next = self.toks.get(self.pos + 1).copied().unwrap_or(self.eof);
            let modifier = t.kind == TokKind::Ident && matches!(self.text(&t), "private" | "public" | "shared");
            if modifier && (next.kind == TokKind::Ident || next.is(P::LBrace) || next.is(P::At)) {
                self.bump();
            } else {
                return;
            }
        }
    }

    /// The body of a `var { ... }` or `let { ... }` block: one declaration
    /// per line (or `;`), each parsed by `one`.
    fn decl_block(&mut self, mut one: impl FnMut(&mut Self) -> PResult<()>) -> PResult<()> {
        let open = self.bump(); // `{`
        loop {
            while self.raw_peek().kind == TokKind::Newline || self.raw_peek().is(P::Semi) {
                self.pos += 1;
            }
            let t = self.peek();
            if t.is(P::RBrace) {
                self.bump();
                return self.expect_line_end("the block");
            }
            if t.kind == TokKind::Eof {
                let msg = "this block is not closed: expected '}'".to_string();
                self.err(open, msg, "opened here");
                return Err(());
            }
            one(self)?;
            let end = self.raw_peek();
            if !matches!(end.kind, TokKind::Newline | TokKind::P(P::Semi | P::RBrace)) {
                let msg = format!("expected a new line or ';' after the declaration, found {}", self.describe(&end));
                self.err(end, msg, "expected the end of the declaration");
                return Err(());
            }
        }
    }

    /// `var` at top level: one global per name, appended to `out`; a
    /// `var { ... }` block declares one module variable per line.
    pub(super) fn global(&mut self, out: &mut Vec<Item>) -> PResult<()> {
        let kw = self.bump(); // `var`
        self.skip_modifiers();
        if self.peek().is(P::LBrace) {
            return self.decl_block(|p| {
                let start = p.peek().span;
                let name = p.ident("a variable name")?;
                let ty = if p.eat(P::Colon).is_some() { Some(p.ty()?) } else { None };
                let init = if p.eat(P::Eq).is_some() {
                    p.skip_nl();
                    Some(p.expr()?)
                } else {
                    None
                };
                if ty.is_none() && init.is_none() {
                    let t = p.peek();
                    let msg = format!("expected ':' and a type, or '=' and a value, for variable `{}`, found {}", name.name, p.describe(&t));
                    p.err(t, msg, "expected ': type' or '= value'");
                    return Err(());
                }
                let span = start.to(p.last);
                out.push(Item::Global(GlobalVar { qualifiers: Vec::new(), name, ty, init, span }));
                Ok(())
            });
        }
        let mut qualifiers = Vec::new();
        while self.peek().is(P::At) {
            qualifiers.push(self.qualifier()?);
        }
        let names = self.names("a variable name", true)?;
        let t = self.peek();
        let ty = if t.is(P::Colon) {
            self.bump();
            Some(self.ty()?)
        } else if qualifiers.is_empty() && t.is(P::Eq) {
            // A module variable: its type comes from its value.
            None
        } else {
            let msg = format!("expected ':' and a type for shader global `{}`, found {}", names.first.name, self.describe(&t));
            self.err(t, msg, "expected ': type'");
            return Err(());
        };
        let init = if self.eat(P::Eq).is_some() {
            self.skip_nl();
            Some(self.expr()?)
        } else {
            None
        };
        self.expect_line_end("the declaration")?;
        let span = kw.span.to(self.last);
        share_among(names, (qualifiers, ty, init), |name, (qualifiers, ty, init)| {
            out.push(Item::Global(GlobalVar { qualifiers, name, ty, init, span }))
        });
        Ok(())
    }

    /// `let NAME [: type] = value` at top level, or a `let { ... }` block
    /// of them, appended to `out`.
    pub(super) fn constants(&mut self, out: &mut Vec<Item>) -> PResult<()> {
        let kw = self.bump(); // `let`
        self.skip_modifiers();
        if self.peek().is(P::LBrace) {
            return self.decl_block(|p| {
                let start = p.peek().span;
                let c = p.constant_rest(start)?;
                out.push(Item::Const(c));
                Ok(())
            });
        }
        let c = self.constant_rest(kw.span)?;
        self.expect_line_end("the constant")?;
        out.push(Item::Const(c));
        Ok(())
    }

    /// `NAME [: type] = value` of a constant starting at `start`.
    fn constant_rest(&mut self, start: Span) -> PResult<ConstDecl> {
        let name = self.ident("a constant name")?;
        let ty = if self.eat(P::Colon).is_some() { Some(self.ty()?) } else { None };
        let t = self.peek();
        if !t.is(P::Eq) {
            let msg = format!("expected '=' and a value for constant `{}`, found {}", name.name, self.describe(&t));
            self.err(t, msg, "expected '='");
            return Err(());
        }
        self.bump();
        self.skip_nl();
        let value = self.expr()?;
        Ok(ConstDecl { span: start.to(self.last), name, ty, value })
    }

    // ---- types ----

    pub(super) fn ty(&mut self) -> PResult<TypeExpr> {
        let t = self.peek();
        if t.kind != TokKind::Ident {
            let msg = format!("expected a type, found {}", self.describe(&t));
            self.err(t, msg, "expected a type");
            return Err(());
        }
        self.bump();
        let mut ty = TypeExpr { kind: TypeExprKind::Named(Ident { name: self.texts.name(t.span), span: t.span }), span: t.span };
        // dasSpirv's `array<T>`: a run-time-sized array, as `T[]`.
        if self.peek().is(P::Lt) && self.text(&t) == "array" {
            self.bump();
            // Nested `array<array<...>>` counts towards the nesting limit.
            self.enter(t)?;
            let elem = self.ty();
            self.leave();
            let elem = elem?;
            let close = self.expect(P::Gt)?;
            ty = TypeExpr { span: t.span.to(close.span), kind: TypeExprKind::RuntimeArray(Box::new(elem)) };
        }
        let depth = self.depth;
        let r = self.array_suffixes(ty);
        self.depth = depth;
        r
    }

    /// `[N][M]...` after a type name; each is a level of nesting.
    pub(super) fn array_suffixes(&mut self, mut ty: TypeExpr) -> PResult<TypeExpr> {
        loop {
            let open = self.peek();
            if !open.is(P::LBracket) {
                return Ok(ty);
            }
            // `T[]`: a run-time-sized array (the last member of an `@ssbo`).
            if self.toks.get(self.pos + 1).is_some_and(|t| t.is(P::RBracket)) {
                self.bump();
                let close = self.bump();
                ty = TypeExpr { span: ty.span.to(close.span), kind: TypeExprKind::RuntimeArray(Box::new(ty)) };
                continue;
            }
            self.enter(open)?;
            let (size, close) = self.bracketed(open, P::RBracket)?;
            ty = TypeExpr { span: ty.span.to(close.span), kind: TypeExprKind::Array(Box::new(ty), Box::new(size)) };
        }
    }
}
