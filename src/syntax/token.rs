//! Tokens: small `Copy` values carrying a kind and a global [`Span`].
//!
//! A token holds no text. Its text is `map.slice(token.span)`, which also
//! works for tokens substituted by a `#define` (they keep the span of the
//! define's value) and for `-D` values (they live in the `<command-line>`
//! virtual file).

use std::cell::{Cell, RefCell};
use std::fmt;
use std::rc::Rc;


use crate::source::{SourceMap, Span};

/// The keywords the front end needs to recognise. Every other daslang
/// keyword lexes as an identifier; shader code never uses them and host
/// code is only split, not parsed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kw {
    Def,
    Var,
    Let,
    Struct,
    Class,
    If,
    Elif,
    Else,
    While,
    For,
    In,
    Return,
    Break,
    Continue,
    True,
    False,
}

impl Kw {
    pub fn from_name(s: &str) -> Option<Kw> {
        Kw::from_bytes(s.as_bytes())
    }

    /// Like [`Kw::from_name`], on the lexer's bytes.
    pub fn from_bytes(s: &[u8]) -> Option<Kw> {
        Some(match s {
            b"def" => Kw::Def,
            b"var" => Kw::Var,
            b"let" => Kw::Let,
            b"struct" => Kw::Struct,
            b"class" => Kw::Class,
            b"if" => Kw::If,
            b"elif" => Kw::Elif,
            b"else" => Kw::Else,
            b"while" => Kw::While,
            b"for" => Kw::For,
            b"in" => Kw::In,
            b"return" => Kw::Return,
            b"break" => Kw::Break,
            b"continue" => Kw::Continue,
            b"true" => Kw::True,
            b"false" => Kw::False,
            _ => return None,
        })
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Kw::Def => "def",
            Kw::Var => "var",
            Kw::Let => "let",
            Kw::Struct => "struct",
            Kw::Class => "class",
            Kw::If => "if",
            Kw::Elif => "elif",
            Kw::Else => "else",
            Kw::While => "while",
            Kw::For => "for",
            Kw::In => "in",
            Kw::Return => "return",
            Kw::Break => "break",
            Kw::Continue => "continue",
            Kw::True => "true",
            Kw::False => "false",
        }
    }
}

/// Punctuation, including the host-only operators, so that host code
/// splits cleanly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum P {
    LParen,
    RParen,
    LBracket,
    RBracket,
    LBrace,
    RBrace,
    Comma,
    Semi,
    Colon,
    ColonColon,
    ColonEq,
    Dot,
    DotDot,
    Ellipsis,
    Question,
    QuestionDot,
    QuestionBracket,
    QuestionQuestion,
    At,
    AtAt,
    Hash,
    Dollar,
    Eq,
    EqEq,
    FatArrow,
    Bang,
    BangEq,
    Lt,
    Le,
    Gt,
    Ge,
    Shl,
    Shr,
    ShlEq,
    ShrEq,
    Rotl,
    Rotr,
    RotlEq,
    RotrEq,
    LArrow,
    LPipe,
    RPipe,
    Plus,
    PlusEq,
    PlusPlus,
    Minus,
    MinusEq,
    MinusMinus,
    Arrow,
    Star,
    StarEq,
    Slash,
    SlashEq,
    Percent,
    PercentEq,
    Amp,
    AmpAmp,
    AmpEq,
    AmpAmpEq,
    Pipe,
    PipePipe,
    PipeEq,
    PipePipeEq,
    Caret,
    CaretCaret,
    CaretEq,
    CaretCaretEq,
    Tilde,
}

impl P {
    pub fn as_str(self) -> &'static str {
        use P::*;
        match self {
            LParen => "(",
            RParen => ")",
            LBracket => "[",
            RBracket => "]",
            LBrace => "{",
            RBrace => "}",
            Comma => ",",
            Semi => ";",
            Colon => ":",
            ColonColon => "::",
            ColonEq => ":=",
            Dot => ".",
            DotDot => "..",
            Ellipsis => "...",
            Question => "?",
            QuestionDot => "?.",
            QuestionBracket => "?[",
            QuestionQuestion => "??",
            At => "@",
            AtAt => "@@",
            Hash => "#",
            Dollar => "$",
            Eq => "=",
            EqEq => "==",
            FatArrow => "=>",
            Bang => "!",
            BangEq => "!=",
            Lt => "<",
            Le => "<=",
            Gt => ">",
            Ge => ">=",
            Shl => "<<",
            Shr => ">>",
            ShlEq => "<<=",
            ShrEq => ">>=",
            Rotl => "<<<",
            Rotr => ">>>",
            RotlEq => "<<<=",
            RotrEq => ">>>=",
            LArrow => "<-",
            LPipe => "<|",
            RPipe => "|>",
            Plus => "+",
            PlusEq => "+=",
            PlusPlus => "++",
            Minus => "-",
            MinusEq => "-=",
            MinusMinus => "--",
            Arrow => "->",
            Star => "*",
            StarEq => "*=",
            Slash => "/",
            SlashEq => "/=",
            Percent => "%",
            PercentEq => "%=",
            Amp => "&",
            AmpAmp => "&&",
            AmpEq => "&=",
            AmpAmpEq => "&&=",
            Pipe => "|",
            PipePipe => "||",
            PipeEq => "|=",
            PipePipeEq => "||=",
            Caret => "^",
            CaretCaret => "^^",
            CaretEq => "^=",
            CaretCaretEq => "^^=",
            Tilde => "~",
        }
    }

    /// The token in single quotes, for messages: `')'`.
    pub fn quoted(self) -> &'static str {
        use P::*;
        match self {
            LParen => "'('",
            RParen => "')'",
            LBracket => "'['",
            RBracket => "']'",
            LBrace => "'{'",
            RBrace => "'}'",
            Comma => "','",
            Colon => "':'",
            Lt => "'<'",
            Gt => "'>'",
            Eq => "'='",
            _ => "a different token",
        }
    }

    /// Tokens after which a line break does not end a statement or an item:
    /// binary and assignment operators, `,`, `=`, `:` and openers.
    pub fn continues_line(self) -> bool {
        use P::*;
        !matches!(self, RParen | RBracket | RBrace | Semi | PlusPlus | MinusMinus | Question | Dot | Hash)
    }
}

/// Why a piece of text is not a token. Reported only when the token lies
/// inside an item that is parsed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LexError {
    /// A character that is not part of daslang's syntax.
    BadChar,
    UnterminatedString,
    UnterminatedChar,
    UnterminatedComment,
}

impl LexError {
    pub fn message(self) -> &'static str {
        match self {
            LexError::BadChar => "unexpected character",
            LexError::UnterminatedString => "unterminated string literal",
            LexError::UnterminatedChar => "unterminated character literal",
            LexError::UnterminatedComment => "unterminated block comment",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokKind {
    Ident,
    Kw(Kw),
    /// Decimal or hex integer, possibly with a suffix (`1u`, `0xffu`).
    Int,
    /// A literal with a fraction or an exponent, possibly with a suffix.
    Float,
    Str,
    Char,
    P(P),
    /// One or more line breaks (statement terminator).
    Newline,
    Error(LexError),
    /// End of the token range being parsed.
    Eof,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    pub kind: TokKind,
    pub span: Span,
}

impl Token {
    pub const fn new(kind: TokKind, span: Span) -> Self {
        Token { kind, span }
    }

    pub fn is(&self, p: P) -> bool {
        self.kind == TokKind::P(p)
    }

    pub fn is_kw(&self, k: Kw) -> bool {
        self.kind == TokKind::Kw(k)
    }
}

/// Token text by span: `map.slice(span)` with the file of the last lookup
/// remembered. Tokens come in long runs from one file, and this skips the
/// search for the file that `SourceMap::slice` does on every call.
pub(crate) struct Texts<'m> {
    map: &'m SourceMap,
    /// Global offsets of the start and end of the last file hit, and its text.
    last: Cell<(u32, u32, &'m str)>,
    /// Shared copies of the texts of files that names were taken from, by
    /// global offset of the file's start.
    shared: RefCell<Vec<(u32, Rc<str>)>>,
}

impl<'m> Texts<'m> {
    pub fn new(map: &'m SourceMap) -> Self {
        Texts { map, last: Cell::new((1, 0, "")), shared: RefCell::new(Vec::new()) }
    }

    /// The text of `span` as a [`Name`] that shares its file's text.
    pub fn name(&self, span: Span) -> Name {
        // The file of the last name first: names come in long runs from one file.
        if let Some((base, text)) = self.shared.borrow().last() {
            if let Some(name) = Self::name_in(*base, text, span) {
                return name;
            }
        }
        self.name_slow(span)
    }

    /// `span` as a range of `text` (which starts at global offset `base`), if it lies within it.
    #[inline]
    fn name_in(base: u32, text: &Rc<str>, span: Span) -> Option<Name> {
        let start = span.start.checked_sub(base)?;
        let end = span.end.checked_sub(base)?;
        let ok = start <= end && text.is_char_boundary(start as usize) && text.is_char_boundary(end as usize);
        ok.then(|| Name::in_text(text.clone(), start, end))
    }

    #[cold]
    fn name_slow(&self, span: Span) -> Name {
        let text = self.get(span);
        // `get` made span's file the last one hit.
        let (base, _, file) = self.last.get();
        let mut shared = self.shared.borrow_mut();
        let k = match shared.iter().position(|(b, _)| *b == base) {
            Some(k) => k,
            None => {
                shared.push((base, file.into()));
                shared.len() - 1
            }
        };
        let last = shared.len() - 1;
        shared.swap(k, last);
        let (base, rc) = &shared[last];
        Self::name_in(*base, rc, span).unwrap_or_else(|| Name::new(text))
    }

    /// The same text as `map.slice(span)`.
    #[inline]
    pub fn get(&self, span: Span) -> &'m str {
        let (base, end, text) = self.last.get();
        if base <= span.start && span.start <= span.end && span.end <= end {
            return text.get((span.start - base) as usize..(span.end - base) as usize).unwrap_or("");
        }
        self.get_slow(span)
    }

    #[cold]
    fn get_slow(&self, span: Span) -> &'m str {
        if let Some(id) = self.map.file_of(span.start) {
            let f = self.map.file(id);
            self.last.set((f.base, f.base + f.text.len() as u32, &f.text));
        }
        self.map.slice(span)
    }
}

/// An identifier's text: a range of a shared copy of its source file's
/// text, so the parser allocates nothing per name (one copy per file per
/// parse) and cloning one is a reference count. Reads as a `&str` (`Deref`,
/// [`Name::as_str`]).
#[derive(Clone)]
pub struct Name {
    text: Rc<str>,
    start: u32,
    end: u32,
}

impl Name {
    /// A name with its own copy of `s`.
    pub fn new(s: &str) -> Name {
        Name { text: s.into(), start: 0, end: s.len() as u32 }
    }

    /// `text[start..end]`, which must lie on character boundaries.
    pub(crate) fn in_text(text: Rc<str>, start: u32, end: u32) -> Name {
        debug_assert!(text.get(start as usize..end as usize).is_some());
        Name { text, start, end }
    }

    pub fn as_str(&self) -> &str {
        &self.text[self.start as usize..self.end as usize]
    }
}

impl std::ops::Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl From<&str> for Name {
    fn from(s: &str) -> Name {
        Name::new(s)
    }
}

impl PartialEq for Name {
    fn eq(&self, other: &Name) -> bool {
        self.as_str() == other.as_str()
    }
}

impl Eq for Name {}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        self.as_str() == other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}
