//! Recursive-descent parser for one selected top-level item.
//!
//! Line breaks end statements; they are skipped inside `()` and `[]` and
//! after a binary operator, `,` or `=`. An error inside a statement skips to
//! the end of that statement (a line break or `}` at the statement's own
//! depth), so one mistake gives one diagnostic. Nesting of expressions and
//! blocks is limited to [`MAX_DEPTH`], so no input can overflow the stack.

use super::ast::*;
use super::items::{ItemKind, RawItem};
use super::token::{Kw, Texts, TokKind, Token, P};
use crate::diag::{Diagnostic, Diagnostics};
use crate::source::Span;

/// Deepest nesting of expressions and blocks together.
pub const MAX_DEPTH: u32 = 128;

type PResult<T> = Result<T, ()>;

pub struct Parser<'a, 'm> {
    toks: &'a [Token],
    pos: usize,
    texts: &'a Texts<'m>,
    diags: &'a mut Diagnostics,
    eof: Token,
    /// Greater than zero inside `()` / `[]`: line breaks are insignificant.
    nl_skip: u32,
    /// Brackets opened in the current statement and not closed yet.
    open: u32,
    depth: u32,
    depth_reported: bool,
    /// Span of the last token consumed.
    last: Span,
}

/// Parses one raw item into AST items appended to `out` (a shader global
/// with several names gives several). Errors are reported; the item is
/// dropped or kept partial.
pub(crate) fn parse_item(toks: &[Token], item: &RawItem, texts: &Texts, diags: &mut Diagnostics, out: &mut Vec<Item>) {
    let range = item.range();
    let slice = &toks[range.clone()];
    let end = slice.iter().rev().find(|t| t.kind != TokKind::Newline).map(|t| t.span.end).unwrap_or(0);
    let mut p = Parser {
        toks: slice,
        pos: 0,
        texts,
        diags,
        eof: Token::new(TokKind::Eof, Span::new(end, end)),
        nl_skip: 0,
        open: 0,
        depth: 0,
        depth_reported: false,
        last: Span::new(end, end),
    };
    match item.kind {
        ItemKind::Def => {
            if let Some(f) = p.function() {
                out.push(Item::Function(f));
            }
        }
        ItemKind::Struct | ItemKind::Class => {
            if let Ok(s) = p.structure() {
                out.push(Item::Struct(s));
            }
        }
        ItemKind::Var => {
            let _ = p.global(out);
        }
        ItemKind::Let => {
            if let Ok(c) = p.constant() {
                out.push(Item::Const(c));
            }
        }
        ItemKind::Other => {}
    }
}

fn binop(t: &Token) -> Option<(BinaryOp, u8)> {
    use BinaryOp::*;
    let TokKind::P(p) = t.kind else { return None };
    Some(match p {
        P::PipePipe => (Or, 1),
        P::CaretCaret => (Xor, 2),
        P::AmpAmp => (And, 3),
        P::Pipe => (BitOr, 4),
        P::Caret => (BitXor, 5),
        P::Amp => (BitAnd, 6),
        P::EqEq => (Eq, 7),
        P::BangEq => (Ne, 7),
        P::Lt => (Lt, 8),
        P::Le => (Le, 8),
        P::Gt => (Gt, 8),
        P::Ge => (Ge, 8),
        P::Shl => (Shl, 9),
        P::Shr => (Shr, 9),
        P::Plus => (Add, 10),
        P::Minus => (Sub, 10),
        P::Star => (Mul, 11),
        P::Slash => (Div, 11),
        P::Percent => (Mod, 11),
        _ => return None,
    })
}

fn assign_op(t: &Token) -> Option<AssignOp> {
    use AssignOp::*;
    let TokKind::P(p) = t.kind else { return None };
    Some(match p {
        P::Eq => Set,
        P::PlusEq => Add,
        P::MinusEq => Sub,
        P::StarEq => Mul,
        P::SlashEq => Div,
        P::PercentEq => Mod,
        P::AmpEq => BitAnd,
        P::PipeEq => BitOr,
        P::CaretEq => BitXor,
        P::ShlEq => Shl,
        P::ShrEq => Shr,
        _ => return None,
    })
}

/// Keywords that begin a statement and never occur inside an expression.
fn starts_stmt(t: &Token) -> bool {
    matches!(
        t.kind,
        TokKind::Kw(Kw::Let | Kw::Var | Kw::If | Kw::While | Kw::For | Kw::Return | Kw::Break | Kw::Continue)
    )
}

/// Calls `make` with each of `names` and the parts they share
/// (`a, b : float3` declares two of one type): copies for all but the last
/// name, which takes the parts themselves.
fn share_among<N, T: Clone>(names: Vec<N>, shared: T, mut make: impl FnMut(N, T)) {
    let mut names = names.into_iter().peekable();
    while let Some(n) = names.next() {
        if names.peek().is_some() {
            make(n, shared.clone());
        } else {
            make(n, shared);
            return;
        }
    }
}

fn ends_stmt(t: &Token) -> bool {
    matches!(t.kind, TokKind::Newline | TokKind::Eof | TokKind::P(P::Semi | P::RBrace))
}

impl<'m> Parser<'_, 'm> {
    // ---- token access ----

    fn raw_peek(&self) -> Token {
        self.toks.get(self.pos).copied().unwrap_or(self.eof)
    }

    fn peek(&mut self) -> Token {
        if self.nl_skip > 0 {
            self.skip_nl();
        }
        self.raw_peek()
    }

    fn skip_nl(&mut self) {
        while self.toks.get(self.pos).is_some_and(|t| t.kind == TokKind::Newline) {
            self.pos += 1;
        }
    }

    fn bump(&mut self) -> Token {
        let t = self.peek();
        if self.pos < self.toks.len() {
            self.pos += 1;
            self.last = t.span;
        }
        t
    }

    fn eat(&mut self, p: P) -> Option<Token> {
        if self.peek().is(p) {
            Some(self.bump())
        } else {
            None
        }
    }

    fn text(&self, t: &Token) -> &'m str {
        self.texts.get(t.span)
    }

    fn describe(&self, t: &Token) -> String {
        match t.kind {
            TokKind::Newline => "newline".into(),
            TokKind::Eof => "end of input".into(),
            TokKind::Ident => format!("identifier '{}'", self.text(t)),
            TokKind::Kw(k) => format!("keyword '{}'", k.as_str()),
            TokKind::Int | TokKind::Float => format!("number '{}'", self.text(t)),
            TokKind::Str => "string literal".into(),
            TokKind::Char => "character literal".into(),
            TokKind::P(p) => format!("'{}'", p.as_str()),
            TokKind::Error(e) => e.message().into(),
        }
    }

    /// Reports an error at `t`, unless `t` is a lexing error (already
    /// reported when the item was selected).
    fn err(&mut self, t: Token, msg: String, label: impl Into<String>) {
        if matches!(t.kind, TokKind::Error(_)) {
            return;
        }
        self.diags.push(Diagnostic::error(msg, t.span).with_label(label));
    }

    fn push(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    // Error reporting lives in small out-of-line functions: the recursive
    // functions stay lean, which keeps stack frames small in debug builds.

    /// `expected WHAT, found TOKEN`, labelled at the token.
    #[cold]
    #[inline(never)]
    fn error_expected(&mut self, t: Token, what: &str) {
        let msg = format!("expected {what}, found {}", self.describe(&t));
        self.err(t, msg, format!("expected {what}"));
    }

    /// `unexpected TOKEN`.
    #[cold]
    #[inline(never)]
    fn error_unexpected(&mut self, t: Token, label: &str) {
        let msg = format!("unexpected {}", self.describe(&t));
        self.err(t, msg, label);
    }

    /// A message with a label at `t`.
    #[cold]
    #[inline(never)]
    fn error_msg(&mut self, t: Token, msg: &str, label: &str) {
        self.err(t, msg.to_string(), label);
    }

    /// `expected ')'` for a bracket list, pointing back at the opener.
    #[cold]
    #[inline(never)]
    fn error_close(&mut self, t: Token, p: P, opener: Token, alt: &str) {
        if matches!(t.kind, TokKind::Error(_)) {
            return;
        }
        let msg = format!("expected {alt}'{}', found {}", p.as_str(), self.describe(&t));
        let d = Diagnostic::error(msg, t.span)
            .with_label(format!("expected {alt}'{}'", p.as_str()))
            .with_secondary(opener.span, format!("to close this '{}'", self.text(&opener)));
        self.push(d);
    }

    #[cold]
    #[inline(never)]
    fn error_depth(&mut self, at: Token) {
        if !self.depth_reported {
            self.depth_reported = true;
            self.push(
                Diagnostic::error(format!("nesting too deep (limit {MAX_DEPTH} nested expressions and blocks)"), at.span)
                    .with_label("the nesting limit is reached here")
                    .with_note("each `(`, block, unary operator, operator of a chain like `a + b + c`, `.field`, `[index]` and `elif` is one level")
                    .with_note("help: split the expression or the block into smaller parts"),
            );
        }
    }

    fn expect(&mut self, p: P) -> PResult<Token> {
        let t = self.peek();
        if t.is(p) {
            return Ok(self.bump());
        }
        self.error_expected(t, p.quoted());
        Err(())
    }

    fn expect_close(&mut self, p: P, opener: Token, alt: &str) -> PResult<Token> {
        let t = self.peek();
        if t.is(p) {
            return Ok(self.bump());
        }
        self.error_close(t, p, opener, alt);
        Err(())
    }

    fn ident(&mut self, what: &str) -> PResult<Ident> {
        let t = self.peek();
        if t.kind == TokKind::Ident {
            self.bump();
            return Ok(Ident { name: self.texts.name(t.span), span: t.span });
        }
        self.error_expected(t, what);
        Err(())
    }

    fn enter(&mut self, at: Token) -> PResult<()> {
        if self.depth >= MAX_DEPTH {
            self.error_depth(at);
            return Err(());
        }
        self.depth += 1;
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Skips the rest of a statement after an error: to a line break or `;`
    /// outside brackets, or up to (not past) a `}` that closes the block.
    /// `parens` is the number of `(`/`[` the statement left open. A line
    /// that starts with a statement keyword always starts a new statement
    /// (those never occur inside brackets), so an unclosed `(` does not
    /// swallow the statements after it.
    fn recover(&mut self, mut parens: u32) {
        let mut braces = 0u32;
        let mut line_start = self.pos == 0 || self.toks.get(self.pos - 1).is_some_and(|t| t.kind == TokKind::Newline);
        loop {
            let t = self.raw_peek();
            if line_start && braces == 0 && starts_stmt(&t) {
                return;
            }
            line_start = false;
            match t.kind {
                TokKind::Eof => return,
                TokKind::P(P::LParen | P::LBracket | P::QuestionBracket) => parens += 1,
                TokKind::P(P::RParen | P::RBracket) => parens = parens.saturating_sub(1),
                TokKind::P(P::LBrace) => braces += 1,
                TokKind::P(P::RBrace) => {
                    if braces == 0 {
                        return;
                    }
                    braces -= 1;
                }
                TokKind::Newline => {
                    if parens == 0 && braces == 0 {
                        self.pos += 1;
                        return;
                    }
                    line_start = true;
                }
                TokKind::P(P::Semi) if parens == 0 && braces == 0 => {
                    self.pos += 1;
                    return;
                }
                _ => {}
            }
            self.pos += 1;
        }
    }

    /// After a top-level declaration: the end of its line.
    fn expect_line_end(&mut self, what: &str) -> PResult<()> {
        let t = self.raw_peek();
        if matches!(t.kind, TokKind::Newline | TokKind::Eof | TokKind::P(P::Semi)) {
            return Ok(());
        }
        let msg = format!("expected newline after {what}, found {}", self.describe(&t));
        self.err(t, msg, "expected the end of the line");
        Err(())
    }

    // ---- items ----

    fn annotations(&mut self) -> PResult<Vec<Annotation>> {
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

    fn function(&mut self) -> Option<FunctionDecl> {
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
        self.skip_nl();
        let body = self.block().ok()?;
        Some(FunctionDecl { annotations, name, params, ret, span: start.to(body.span), body })
    }

    #[allow(clippy::type_complexity)]
    fn function_header(&mut self) -> PResult<(Vec<Annotation>, Ident, Vec<Param>, Option<TypeExpr>)> {
        let annotations = self.annotations()?;
        self.skip_nl();
        self.bump(); // `def`
        let name = self.ident("a function name")?;
        let mut params = Vec::new();
        if let Some(po) = self.eat(P::LParen) {
            self.nl_skip += 1;
            if self.eat(P::RParen).is_none() {
                loop {
                    if self.peek().is_kw(Kw::Var) {
                        self.bump();
                    }
                    let mut names = vec![self.ident("a parameter name")?];
                    while self.eat(P::Comma).is_some() {
                        names.push(self.ident("a parameter name")?);
                    }
                    let t = self.peek();
                    if !t.is(P::Colon) {
                        let msg = format!("expected ':' and the parameter's type, found {}", self.describe(&t));
                        self.err(t, msg, "expected ':'");
                        return Err(());
                    }
                    self.bump();
                    let ty = self.ty()?;
                    if let Some(eq) = self.eat(P::Eq) {
                        self.err(eq, "default parameter values are not supported in shader code".into(), "default value");
                        return Err(());
                    }
                    share_among(names, ty, |n, ty| params.push(Param { span: n.span.to(ty.span), name: n, ty }));
                    if self.eat(P::Semi).is_some() || self.eat(P::Comma).is_some() {
                        continue;
                    }
                    self.expect_close(P::RParen, po, "';' or ")?;
                    break;
                }
            }
            self.nl_skip -= 1;
        }
        let ret = if self.eat(P::Colon).is_some() { Some(self.ty()?) } else { None };
        Ok((annotations, name, params, ret))
    }

    fn structure(&mut self) -> PResult<StructDecl> {
        let annotations = self.annotations()?;
        self.skip_nl();
        let kw = self.bump();
        if kw.is_kw(Kw::Class) {
            self.err(kw, "classes are not supported in shader code".into(), "used by a shader here");
            return Err(());
        }
        let name = self.ident("a struct name")?;
        self.skip_nl();
        let open = self.expect(P::LBrace)?;
        let mut fields = Vec::new();
        let end;
        loop {
            let t = self.raw_peek();
            match t.kind {
                TokKind::Newline | TokKind::P(P::Semi) => {
                    self.pos += 1;
                    continue;
                }
                TokKind::P(P::RBrace) => {
                    self.bump();
                    end = t.span;
                    break;
                }
                TokKind::Eof => {
                    self.expect_close(P::RBrace, open, "")?;
                    return Err(());
                }
                _ => {}
            }
            match self.field() {
                Ok(fs) => {
                    fields.extend(fs);
                    let t = self.raw_peek();
                    if !ends_stmt(&t) {
                        let msg = format!("expected newline after the field, found {}", self.describe(&t));
                        self.err(t, msg, "expected the end of the line");
                        self.recover(0);
                    }
                }
                Err(()) => {
                    let extra = self.open;
                    self.open = 0;
                    self.nl_skip = 0;
                    self.recover(extra);
                }
            }
        }
        Ok(StructDecl { span: kw.span.to(end), annotations, name, fields })
    }

    fn field(&mut self) -> PResult<Vec<Field>> {
        let mut names = vec![self.ident("a field name")?];
        while self.eat(P::Comma).is_some() {
            names.push(self.ident("a field name")?);
        }
        self.expect(P::Colon)?;
        let ty = self.ty()?;
        if let Some(eq) = self.eat(P::Eq) {
            self.err(eq, "field initialisers are not supported in shader code".into(), "initialiser");
            return Err(());
        }
        let mut fields = Vec::with_capacity(names.len());
        share_among(names, ty, |n, ty| fields.push(Field { span: n.span.to(ty.span), name: n, ty }));
        Ok(fields)
    }

    fn qualifier(&mut self) -> PResult<Qualifier> {
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
            if v.kind != TokKind::Int {
                if matches!(name, "location" | "stage") {
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
            "stage" => match value {
                Some(v) => QualifierKind::Stage(v),
                None => {
                    let msg = "`@stage` needs a texture unit: `@stage = N`".to_string();
                    self.err(Token::new(TokKind::Ident, span), msg, "no value");
                    return Err(());
                }
            },
            other => QualifierKind::Other(other.to_string()),
        };
        Ok(Qualifier { kind, span })
    }

    /// `var` at top level: one global per name, appended to `out`.
    fn global(&mut self, out: &mut Vec<Item>) -> PResult<()> {
        let kw = self.bump(); // `var`
        let mut qualifiers = Vec::new();
        while self.peek().is(P::At) {
            qualifiers.push(self.qualifier()?);
        }
        let mut names = vec![self.ident("a variable name")?];
        while self.eat(P::Comma).is_some() {
            self.skip_nl();
            names.push(self.ident("a variable name")?);
        }
        let t = self.peek();
        if !t.is(P::Colon) {
            let msg = format!("expected ':' and a type for shader global `{}`, found {}", names[0].name, self.describe(&t));
            self.err(t, msg, "expected ': type'");
            return Err(());
        }
        self.bump();
        let ty = self.ty()?;
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

    fn constant(&mut self) -> PResult<ConstDecl> {
        let kw = self.bump(); // `let`
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
        self.expect_line_end("the constant")?;
        Ok(ConstDecl { span: kw.span.to(self.last), name, ty, value })
    }

    // ---- types ----

    fn ty(&mut self) -> PResult<TypeExpr> {
        let t = self.peek();
        if t.kind != TokKind::Ident {
            let msg = format!("expected a type, found {}", self.describe(&t));
            self.err(t, msg, "expected a type");
            return Err(());
        }
        self.bump();
        let ty = TypeExpr { kind: TypeExprKind::Named(Ident { name: self.texts.name(t.span), span: t.span }), span: t.span };
        let depth = self.depth;
        let r = self.array_suffixes(ty);
        self.depth = depth;
        r
    }

    /// `[N][M]...` after a type name; each is a level of nesting.
    fn array_suffixes(&mut self, mut ty: TypeExpr) -> PResult<TypeExpr> {
        loop {
            let open = self.peek();
            if !open.is(P::LBracket) {
                return Ok(ty);
            }
            self.enter(open)?;
            self.bump();
            self.nl_skip += 1;
            self.open += 1;
            let size = self.expr()?;
            let close = self.expect_close(P::RBracket, open, "")?;
            self.nl_skip -= 1;
            self.open -= 1;
            ty = TypeExpr { span: ty.span.to(close.span), kind: TypeExprKind::Array(Box::new(ty), Box::new(size)) };
        }
    }

    // ---- statements ----

    fn block(&mut self) -> PResult<Block> {
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
        let result = loop {
            let t = self.raw_peek();
            match t.kind {
                TokKind::Newline | TokKind::P(P::Semi) => {
                    self.pos += 1;
                    continue;
                }
                TokKind::P(P::RBrace) => {
                    self.bump();
                    break Ok(t.span);
                }
                TokKind::Eof => {
                    self.error_close(t, P::RBrace, open, "");
                    break Err(());
                }
                _ => {}
            }
            match self.stmt() {
                Ok(s) => {
                    stmts.push(s);
                    let t = self.raw_peek();
                    if !ends_stmt(&t) {
                        self.error_expected(t, "newline or ';' after the statement");
                        self.recover(0);
                    }
                }
                Err(()) => {
                    let extra = self.open;
                    self.open = 0;
                    self.nl_skip = 0;
                    self.recover(extra);
                }
            }
        };
        self.nl_skip = nl0;
        self.open = open0;
        self.leave();
        let end = result?;
        Ok(Block { stmts, span: open.span.to(end) })
    }

    #[cold]
    #[inline(never)]
    fn error_no_brace(&mut self, t: Token) {
        if matches!(t.kind, TokKind::Error(_)) {
            return;
        }
        let msg = format!("expected '{{', found {}", self.describe(&t));
        self.push(
            Diagnostic::error(msg, t.span)
                .with_label("expected '{'")
                .with_note("bodies of functions, `if`, `while` and `for` are enclosed in braces"),
        );
    }

    /// A block after `if`/`while`/`for`: a line break before `{` is allowed.
    fn body(&mut self) -> PResult<Block> {
        self.skip_nl();
        self.block()
    }

    fn stmt(&mut self) -> PResult<Stmt> {
        let t = self.peek();
        let kind = match t.kind {
            TokKind::Kw(Kw::Let | Kw::Var) => self.local()?,
            TokKind::Kw(Kw::If) => self.if_stmt()?,
            TokKind::Kw(Kw::While) => {
                self.bump();
                let cond = self.expr()?;
                let body = self.body()?;
                StmtKind::While { cond, body }
            }
            TokKind::Kw(Kw::For) => self.for_stmt()?,
            TokKind::Kw(Kw::Return) => {
                self.bump();
                if ends_stmt(&self.raw_peek()) {
                    StmtKind::Return(None)
                } else {
                    StmtKind::Return(Some(self.expr()?))
                }
            }
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
            _ => self.expr_stmt()?,
        };
        Ok(Stmt { kind, span: t.span.to(self.last) })
    }

    fn expr_stmt(&mut self) -> PResult<StmtKind> {
        let target = self.expr()?;
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
    fn error_unsupported(&mut self, t: Token, label: &str) {
        let msg = format!("'{}' is not supported in shader code", self.text(&t));
        self.err(t, msg, label);
    }

    fn local(&mut self) -> PResult<StmtKind> {
        let kw = self.bump();
        let mutable = kw.is_kw(Kw::Var);
        let mut names = vec![self.ident("a variable name")?];
        while self.eat(P::Comma).is_some() {
            self.skip_nl();
            names.push(self.ident("a variable name")?);
        }
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
            let msg = format!("expected ':' or '=' after `{} {}`, found {}", kw_text(mutable), names[0].name, self.describe(&t));
            self.err(t, msg, "a local needs a type or a value");
            return Err(());
        }
        Ok(StmtKind::Local { mutable, names, ty, init })
    }

    fn if_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `if`
        let cond = self.expr()?;
        let then = self.body()?;
        // Later stages nest each `elif` inside the previous one's `else`.
        let depth = self.depth;
        let r = self.elifs(cond, then);
        self.depth = depth;
        r
    }

    fn elifs(&mut self, cond: Expr, then: Block) -> PResult<StmtKind> {
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
                let b = self.body()?;
                elifs.push((c, b));
            } else if t.is_kw(Kw::Else) {
                self.bump();
                if self.peek().is_kw(Kw::If) {
                    self.bump();
                    let c = self.expr()?;
                    let b = self.body()?;
                    elifs.push((c, b));
                } else {
                    otherwise = Some(self.body()?);
                    break;
                }
            } else {
                self.pos = save;
                break;
            }
        }
        Ok(StmtKind::If { cond, then, elifs, otherwise })
    }

    fn for_stmt(&mut self) -> PResult<StmtKind> {
        self.bump(); // `for`
        let paren = self.eat(P::LParen);
        if paren.is_some() {
            self.nl_skip += 1;
            self.open += 1;
        }
        let var = self.ident("a loop variable name")?;
        let t = self.peek();
        if !t.is_kw(Kw::In) {
            self.error_expected(t, "'in'");
            return Err(());
        }
        self.bump();
        let iter = self.expr()?;
        if let Some(po) = paren {
            self.expect_close(P::RParen, po, "")?;
            self.nl_skip -= 1;
            self.open -= 1;
        }
        let body = self.body()?;
        Ok(StmtKind::For { var, iter, body })
    }

    // ---- expressions ----

    fn expr(&mut self) -> PResult<Expr> {
        let t = self.peek();
        self.enter(t)?;
        let r = self.ternary();
        self.leave();
        r
    }

    fn ternary(&mut self) -> PResult<Expr> {
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

    fn binary(&mut self, min: u8) -> PResult<Expr> {
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

    fn unary(&mut self) -> PResult<Expr> {
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
        self.enter(t)?;
        self.bump();
        let r = self.unary();
        self.leave();
        let e = r?;
        Ok(Expr { span: t.span.to(e.span), kind: ExprKind::Unary(op, Box::new(e)) })
    }

    fn postfix(&mut self) -> PResult<Expr> {
        let e = self.primary()?;
        // Like a chain of binary operators, each postfix operator is a level.
        let depth = self.depth;
        let r = self.postfix_ops(e);
        self.depth = depth;
        r
    }

    fn postfix_ops(&mut self, mut e: Expr) -> PResult<Expr> {
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

    fn field_access(&mut self, e: Expr) -> PResult<Expr> {
        self.bump();
        let name = self.ident("a field name or swizzle after '.'")?;
        Ok(Expr { span: e.span.to(name.span), kind: ExprKind::Field(Box::new(e), name) })
    }

    fn index(&mut self, e: Expr, open: Token) -> PResult<Expr> {
        self.bump();
        self.nl_skip += 1;
        self.open += 1;
        let idx = self.expr()?;
        let close = self.expect_close(P::RBracket, open, "")?;
        self.nl_skip -= 1;
        self.open -= 1;
        Ok(Expr { span: e.span.to(close.span), kind: ExprKind::Index(Box::new(e), Box::new(idx)) })
    }

    /// `( a, b, ... )` or `[ a, b, ... ]` after the opener was consumed.
    fn list(&mut self, opener: Token, close: P) -> PResult<(Vec<Expr>, Token)> {
        self.nl_skip += 1;
        self.open += 1;
        let mut items = Vec::new();
        let end = loop {
            if let Some(c) = self.eat(close) {
                break c;
            }
            items.push(self.expr()?);
            if self.eat(P::Comma).is_some() {
                continue;
            }
            break self.expect_close(close, opener, "',' or ")?;
        };
        self.nl_skip -= 1;
        self.open -= 1;
        Ok((items, end))
    }

    fn primary(&mut self) -> PResult<Expr> {
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

    #[cold]
    #[inline(never)]
    fn error_primary(&mut self, t: Token) {
        match t.kind {
            TokKind::Str | TokKind::Char => {
                let msg = format!("{}s are not supported in shader code", self.describe(&t));
                self.err(t, msg, "not supported here");
            }
            TokKind::Newline | TokKind::Eof | TokKind::Kw(_) | TokKind::P(P::RBrace) => self.error_expected(t, "an expression"),
            _ => self.error_unexpected(t, "expected an expression"),
        }
    }

    fn paren(&mut self, open: Token) -> PResult<Expr> {
        self.bump();
        self.nl_skip += 1;
        self.open += 1;
        let e = self.expr()?;
        let close = self.expect_close(P::RParen, open, "")?;
        self.nl_skip -= 1;
        self.open -= 1;
        Ok(Expr { kind: ExprKind::Paren(Box::new(e)), span: open.span.to(close.span) })
    }

    fn name_or_call(&mut self, t: Token) -> PResult<Expr> {
        self.bump();
        let name = Ident { name: self.texts.name(t.span), span: t.span };
        let next = self.peek();
        if next.is(P::Lt) && name.name == "fixed_array" {
            self.bump();
            let elem = self.ty()?;
            self.expect(P::Gt)?;
            let po = self.expect(P::LParen)?;
            let (items, end) = self.list(po, P::RParen)?;
            return Ok(Expr { kind: ExprKind::Array { elem: Some(elem), items }, span: t.span.to(end.span) });
        }
        if next.is(P::LParen) {
            self.bump();
            let (args, end) = self.list(next, P::RParen)?;
            return Ok(Expr { kind: ExprKind::Call { callee: name, args }, span: t.span.to(end.span) });
        }
        Ok(Expr { kind: ExprKind::Name(name), span: t.span })
    }

    #[inline(never)]
    fn int_lit(&mut self, t: Token) -> PResult<Expr> {
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
    fn float_lit(&mut self, t: Token) -> PResult<Expr> {
        let text = self.text(&t);
        let body = text.trim_end_matches(|c: char| c.is_ascii_alphabetic() || c == '_');
        let suffix = &text[body.len()..];
        match suffix {
            "" | "f" | "F" => {}
            "d" | "D" | "lf" | "LF" => return self.double_error(t),
            _ => {
                let msg = format!("unsupported suffix `{suffix}` on number `{text}`");
                let d = Diagnostic::error(msg, t.span).with_label("unsupported suffix").with_note("float literals take `f` or no suffix");
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

    fn double_error(&mut self, t: Token) -> PResult<Expr> {
        let msg = format!("double-precision literal `{}` is not supported in shader code", self.text(&t));
        let d = Diagnostic::error(msg, t.span)
            .with_label("double literal")
            .with_note("help: drop the `d` suffix to make it a float");
        self.push(d);
        Err(())
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

fn kw_text(mutable: bool) -> &'static str {
    if mutable {
        "var"
    } else {
        "let"
    }
}

/// A string literal's body with escapes resolved.
pub(crate) fn unescape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut it = s.chars();
    while let Some(c) = it.next() {
        if c == '\\' {
            match it.next() {
                Some('n') => out.push('\n'),
                Some('t') => out.push('\t'),
                Some('r') => out.push('\r'),
                Some('0') => out.push('\0'),
                Some(o) => out.push(o),
                None => {}
            }
        } else {
            out.push(c);
        }
    }
    out
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
