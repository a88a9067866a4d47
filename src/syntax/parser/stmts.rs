//! Statements: blocks, `let`/`var`, assignments, `if`/`elif`/`else`,
//! `while`, `for ... in ...`, `with`, `return`, `break`, `continue`, and
//! the postfix `if` of a one-statement condition (`return x if (c)`).

use super::*;

impl<'m> Parser<'_, 'm> {
    // ---- statements ----

    pub(super) fn block(&mut self) -> PResult<Block> {
        let open = self.peek();
        if !open.is(P::LBrace) {
            self.error_no_brace(open);
            return Err(());
        }
        self.enter(open)?;
        self.bump();
        let (nl0, open0) = (self.nl_skip, self.open);
        self.nl_skip = 0;
        self.open = 0;
        let mut stmts = Vec::new();
        let result = self.braced_lines(
            open,
            |p| {
                stmts.push(p.stmt()?);
                Ok(())
            },
            |p, t| {
                if !p.refuse_host_construct(t) {
                    p.error_expected(t, "newline or ';' after the statement")
                }
            },
        );
        self.nl_skip = nl0;
        self.open = open0;
        self.leave();
        let end = result?;
        Ok(Block { stmts, span: open.span.to(end) })
    }

    #[cold]
    #[inline(never)]
    pub(super) fn error_no_brace(&mut self, t: Token) {
        if matches!(t.kind, TokKind::Error(_)) {
            return;
        }
        // The end of the item: the header's line ended without `{`, which
        // is how daslang's older syntax starts an indented body.
        let found = if t.kind == TokKind::Eof { "the end of the line".to_string() } else { self.describe(&t) };
        let msg = format!("expected '{{', found {found}");
        self.push(
            Diagnostic::error(msg, t.span)
                .with_label("expected '{'")
                .with_note("bodies of functions, `if`, `while` and `for` are enclosed in braces")
                .with_note("a body given by indentation alone is daslang's older syntax (files without `options gen2`), which umbrac does not read: enclose it in `{ }`")
                .with_note("help: daslang converts a whole file of the older syntax: `daslang utils/gen1-to-gen2/main.das -- -i FILE`"),
        );
    }

    /// A block after `if`/`while`/`for`: a line break before `{` is allowed.
    pub(super) fn body(&mut self) -> PResult<Block> {
        self.skip_nl();
        self.block()
    }

    /// The body of `if`/`elif`/`else`/`while`/`for`: a block, or (gen2's
    /// one-liner) one simple statement on the same line:
    /// `if (c) return x`, `else x = 1`, `while (c) i++`.
    pub(super) fn body_or_line(&mut self) -> PResult<Block> {
        let t = self.raw_peek();
        if matches!(t.kind, TokKind::Newline | TokKind::P(P::LBrace) | TokKind::Eof) {
            return self.body();
        }
        let kind = match t.kind {
            TokKind::Kw(Kw::Return) => self.return_stmt()?,
            TokKind::Kw(Kw::Break) => {
                self.bump();
                StmtKind::Break
            }
            TokKind::Kw(Kw::Continue) => {
                self.bump();
                StmtKind::Continue
            }
            TokKind::Kw(Kw::Let | Kw::Var | Kw::If | Kw::Elif | Kw::Else | Kw::While | Kw::For) => {
                self.error_one_liner(t);
                return Err(());
            }
            _ => self.expr_stmt()?,
        };
        let stmt = Stmt { kind, span: t.span.to(self.last) };
        Ok(Block { span: stmt.span, stmts: vec![stmt] })
    }

    /// `return [value]`: no value before the end of the statement, a
    /// postfix `if` or a one-line `if`'s `else`.
    fn return_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `return`
        let p = self.raw_peek();
        if ends_stmt(&p) || p.is_kw(Kw::If) || p.is_kw(Kw::Else) {
            Ok(StmtKind::Return(None))
        } else {
            Ok(StmtKind::Return(Some(self.expr()?)))
        }
    }

    #[cold]
    #[inline(never)]
    fn error_one_liner(&mut self, t: Token) {
        let msg = format!("{} cannot stand alone as a one-line body", self.describe(&t));
        let d = Diagnostic::error(msg, t.span)
            .with_label("enclose it in `{ }`")
            .with_note("a body without braces is one expression, assignment, `return`, `break` or `continue` on the same line (daslang's gen2 one-liner)");
        self.push(d);
    }

    #[inline(always)]
    pub(super) fn stmt(&mut self) -> PResult<Stmt> {
        let t = self.peek();
        let kind = match t.kind {
            TokKind::Kw(Kw::Let | Kw::Var) => self.local()?,
            TokKind::Kw(Kw::If) => self.if_stmt()?,
            TokKind::Kw(Kw::While) => {
                self.bump();
                let cond = self.expr()?;
                let body = self.body_or_line()?;
                StmtKind::While { cond, body }
            }
            TokKind::Kw(Kw::For) => self.for_stmt()?,
            TokKind::Kw(Kw::Return) => self.return_stmt()?,
            TokKind::Kw(Kw::Break) => {
                self.bump();
                StmtKind::Break
            }
            TokKind::Kw(Kw::Continue) => {
                self.bump();
                StmtKind::Continue
            }
            TokKind::P(P::LBrace) => StmtKind::Block(self.block()?),
            TokKind::Kw(Kw::Elif) => {
                self.error_msg(t, "`elif` without a preceding `if`", "no `if` before this");
                return Err(());
            }
            TokKind::Kw(Kw::Else) => {
                self.error_msg(t, "`else` without a preceding `if`", "no `if` before this");
                return Err(());
            }
            TokKind::Ident if t.span.end - t.span.start == 4 && self.toks.get(self.pos + 1).is_some_and(|n| n.is(P::LParen)) && self.text(&t) == "with" => self.with_stmt()?,
            // `unsafe { ... }`: daslang's permission (for `reinterpret`);
            // the statements themselves.
            TokKind::Ident if self.toks.get(self.pos + 1).is_some_and(|n| n.is(P::LBrace)) && self.text(&t) == "unsafe" => {
                self.bump();
                StmtKind::Block(self.block()?)
            }
            // `f($ { ... })`: the block as the only argument.
            TokKind::Ident if self.toks.get(self.pos + 1).is_some_and(|n| n.is(P::LParen)) && self.toks.get(self.pos + 2).is_some_and(|n| n.is(P::Dollar)) => self.block_arg_call(t)?,
            _ => self.expr_stmt()?,
        };
        if self.raw_peek().is_kw(Kw::If) {
            return self.postfix_if(t, kind);
        }
        Ok(Stmt { kind, span: t.span.to(self.last) })
    }

    /// `stmt if (cond) [else stmt]` after a `return`, `break`, `continue`
    /// or call statement (daslang's postfix condition): the statement runs
    /// where `cond` holds, the `else` one where it does not.
    #[inline(never)]
    pub(super) fn postfix_if(&mut self, first: Token, then: StmtKind) -> PResult<Stmt> {
        let if_kw = self.raw_peek();
        if !matches!(then, StmtKind::Return(_) | StmtKind::Break | StmtKind::Continue | StmtKind::Expr(Expr { kind: ExprKind::Call { .. }, .. })) {
            self.error_msg(if_kw, "a postfix `if` follows a `return`, `break`, `continue` or call", "after another statement");
            return Err(());
        }
        let then = Stmt { kind: then, span: first.span.to(self.last) };
        self.bump();
        let cond = self.expr()?;
        let otherwise = if self.raw_peek().is_kw(Kw::Else) {
            self.bump();
            let s = self.stmt()?;
            if !matches!(s.kind, StmtKind::Return(_) | StmtKind::Break | StmtKind::Continue | StmtKind::Expr(_)) {
                self.error_msg(Token::new(TokKind::Ident, s.span), "the `else` of a postfix `if` takes a `return`, `break`, `continue` or call", "not one of those");
                return Err(());
            }
            Some(Block { span: s.span, stmts: vec![s] })
        } else {
            None
        };
        let span = first.span.to(self.last);
        let then = Block { span: then.span, stmts: vec![then] };
        Ok(Stmt { kind: StmtKind::If { cond, then, elifs: Vec::new(), otherwise }, span })
    }

    /// `with (subject) { ... }`.
    #[inline(never)]
    pub(super) fn with_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `with`
        let open = self.peek();
        let (subject, _) = self.bracketed(open, P::RParen)?;
        let body = self.body()?;
        Ok(StmtKind::With { subject, body })
    }

    /// `f($ { ... })`.
    #[inline(never)]
    fn block_arg_call(&mut self, name: Token) -> PResult<StmtKind> {
        self.bump(); // the name
        let open = self.bump(); // `(`
        self.bump(); // `$`
        let body = self.body()?;
        self.expect_close(P::RParen, open, "")?;
        Ok(StmtKind::CallBlock { callee: Ident { name: self.texts.name(name.span), span: name.span }, args: Vec::new(), body })
    }

    pub(super) fn expr_stmt(&mut self) -> PResult<StmtKind> {
        let target = self.expr()?;
        // `f(args) $ { ... }` or `f(args) <| $ { ... }`: daslang's block
        // argument, passed last.
        let next = self.raw_peek();
        let piped = next.is(P::LPipe) && self.toks.get(self.pos + 1).is_some_and(|n| n.is(P::Dollar));
        if next.is(P::Dollar) || piped {
            let ExprKind::Call { callee, args } = target.kind else {
                self.error_msg(next, "a block argument follows a call: `f() $ { ... }`", "after something that is not a call");
                return Err(());
            };
            self.bump();
            if piped {
                self.bump();
            }
            let body = self.body()?;
            return Ok(StmtKind::CallBlock { callee, args, body });
        }
        let op_tok = self.peek();
        if let Some(op) = assign_op(&op_tok) {
            self.bump();
            self.skip_nl();
            let value = self.expr()?;
            Ok(StmtKind::Assign { target, op, value })
        } else if matches!(
            op_tok.kind,
            TokKind::P(P::ColonEq | P::LArrow | P::AmpAmpEq | P::PipePipeEq | P::CaretCaretEq | P::RotlEq | P::RotrEq)
        ) {
            self.error_unsupported(op_tok, "unsupported assignment");
            Err(())
        } else {
            Ok(StmtKind::Expr(target))
        }
    }

    /// `'X' is not supported in shader code`.
    #[cold]
    #[inline(never)]
    pub(super) fn error_unsupported(&mut self, t: Token, label: &str) {
        let msg = format!("'{}' is not supported in shader code", self.text(&t));
        self.err(t, msg, label);
    }

    pub(super) fn local(&mut self) -> PResult<StmtKind> {
        let kw = self.bump();
        let mutable = kw.is_kw(Kw::Var);
        let names = self.names("a variable name", true)?;
        let ty = if self.eat(P::Colon).is_some() { Some(self.ty()?) } else { None };
        let t = self.peek();
        let init = if t.is(P::Eq) {
            self.bump();
            self.skip_nl();
            Some(self.expr()?)
        } else if matches!(t.kind, TokKind::P(P::ColonEq | P::LArrow)) {
            self.error_unsupported(t, "use '=' here");
            return Err(());
        } else {
            None
        };
        if ty.is_none() && init.is_none() {
            let t = self.peek();
            let msg = format!("expected ':' or '=' after `{} {}`, found {}", kw_text(mutable), names.first.name, self.describe(&t));
            self.err(t, msg, "a local needs a type or a value");
            return Err(());
        }
        Ok(StmtKind::Local { mutable, names, ty, init })
    }

    pub(super) fn if_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `if`
        let cond = self.expr()?;
        let then = self.body_or_line()?;
        // Later stages nest each `elif` inside the previous one's `else`.
        let depth = self.depth;
        let r = self.elifs(cond, then);
        self.depth = depth;
        r
    }

    pub(super) fn elifs(&mut self, cond: Expr, then: Block) -> PResult<StmtKind> {
        let mut elifs = Vec::new();
        let mut otherwise = None;
        loop {
            let save = self.pos;
            self.skip_nl();
            let t = self.raw_peek();
            if t.is_kw(Kw::Elif) || t.is_kw(Kw::Else) {
                self.enter(t)?;
            }
            if t.is_kw(Kw::Elif) {
                self.bump();
                let c = self.expr()?;
                let b = self.body_or_line()?;
                elifs.push((c, b));
            } else if t.is_kw(Kw::Else) {
                self.bump();
                if self.peek().is_kw(Kw::If) {
                    self.bump();
                    let c = self.expr()?;
                    let b = self.body_or_line()?;
                    elifs.push((c, b));
                } else {
                    otherwise = Some(self.body_or_line()?);
                    break;
                }
            } else {
                self.pos = save;
                break;
            }
        }
        Ok(StmtKind::If { cond, then, elifs, otherwise })
    }

    pub(super) fn for_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `for`
        let paren = self.eat(P::LParen);
        if paren.is_some() {
            self.nl_skip += 1;
            self.open += 1;
        }
        let mut vars = vec![self.ident("a loop variable name")?];
        while self.eat(P::Comma).is_some() {
            vars.push(self.ident("a loop variable name")?);
        }
        let t = self.peek();
        if !t.is_kw(Kw::In) {
            self.error_expected(t, if vars.len() == 1 { "'in'" } else { "',' or 'in'" });
            return Err(());
        }
        self.bump();
        let mut iters = vec![self.expr()?];
        while self.eat(P::Comma).is_some() {
            iters.push(self.expr()?);
        }
        if let Some(po) = paren {
            self.expect_close(P::RParen, po, "")?;
            self.nl_skip -= 1;
            self.open -= 1;
        }
        let body = self.body_or_line()?;
        Ok(StmtKind::For { vars, iters, body })
    }
}

fn kw_text(mutable: bool) -> &'static str {
    if mutable {
        "var"
    } else {
        "let"
    }
}
