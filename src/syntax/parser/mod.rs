//! Recursive-descent parser for one selected top-level item.
//!
//! Line breaks end statements; they are skipped inside `()` and `[]` and
//! after a binary operator, `,` or `=`. An error inside a statement skips to
//! the end of that statement (a line break or `}` at the statement's own
//! depth), so one mistake gives one diagnostic. Nesting of expressions and
//! blocks is limited to [`MAX_DEPTH`], so no input can overflow the stack.
//!
//! The [`Parser`] and its token access and error recovery are here; what it
//! parses is split by kind: [`decls`] (items and types), [`stmts`] and
//! [`exprs`].

mod decls;
mod exprs;
mod stmts;

use super::ast::*;
use super::items::{ItemKind, RawItem};
use super::lexer::unescape;
use super::token::{Kw, Texts, TokKind, Token, P};
use crate::diag::{Diagnostic, Diagnostics};
use crate::source::Span;

/// The longest name a shader may declare, in characters (names are ASCII).
/// GLSL allows 1024; what the outputs build from a name must fit too.
pub const MAX_IDENT_LEN: usize = 256;

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
            let _ = p.constants(out);
        }
        ItemKind::Enum => {
            if let Ok(e) = p.enumeration() {
                out.push(Item::Enum(e));
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
fn share_among<N, T: Clone>(names: impl IntoIterator<Item = N>, shared: T, mut make: impl FnMut(N, T)) {
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
            if (t.span.end - t.span.start) as usize > MAX_IDENT_LEN {
                // Every name a shader declares comes through here.
                let msg = format!("this name is {} characters long; names in shader code are limited to {MAX_IDENT_LEN}", t.span.end - t.span.start);
                self.diags.push(
                    Diagnostic::error(msg, Span::new(t.span.start, t.span.start + 1))
                        .with_label("a name starts here")
                        .with_note("GLSL allows names of up to 1024 characters, and the outputs add suffixes to some names (`_block`, `_sampler`)"),
                );
            }
            return Ok(Ident { name: self.texts.name(t.span), span: t.span });
        }
        self.error_expected(t, what);
        Err(())
    }

    /// The lines of a `{ ... }` body whose `{` (`open`) was consumed: empty
    /// lines and `;` are skipped and `line` parses each of the others, which
    /// must end there (a line break, `;` or `}`; if not, `not_ended` reports
    /// the token and the rest of the line is skipped). An error inside a line
    /// skips to the next one, so one mistake gives one diagnostic. Returns the
    /// `}`'s span; at the end of the file, reports the unclosed `{`.
    fn braced_lines(
        &mut self,
        open: Token,
        mut line: impl FnMut(&mut Self) -> PResult<()>,
        mut not_ended: impl FnMut(&mut Self, Token),
    ) -> PResult<Span> {
        loop {
            let t = self.raw_peek();
            match t.kind {
                TokKind::Newline | TokKind::P(P::Semi) => {
                    self.pos += 1;
                    continue;
                }
                TokKind::P(P::RBrace) => {
                    self.bump();
                    return Ok(t.span);
                }
                TokKind::Eof => {
                    self.error_close(t, P::RBrace, open, "");
                    return Err(());
                }
                _ => {}
            }
            let start = self.pos;
            match line(self) {
                Ok(()) => {
                    let t = self.raw_peek();
                    if !ends_stmt(&t) {
                        not_ended(self, t);
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
            // Recovery stops in front of a token that starts a statement;
            // where a line that failed on its first token (a `var` where a
            // struct field belongs) would be tried again forever, skip it.
            if self.pos == start {
                self.pos += 1;
                self.recover(0);
            }
        }
    }

    /// `a, b, c`: one or more names, a line break allowed after each `,`
    /// where `nl_after_comma`.
    fn names(&mut self, what: &str, nl_after_comma: bool) -> PResult<Names> {
        let first = self.ident(what)?;
        let mut rest = Vec::new();
        while self.eat(P::Comma).is_some() {
            if nl_after_comma {
                self.skip_nl();
            }
            rest.push(self.ident(what)?);
        }
        Ok(Names { first, rest })
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
}

