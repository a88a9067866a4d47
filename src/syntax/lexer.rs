//! The lexer: one pass over a file's bytes, producing [`Token`]s with
//! global spans.
//!
//! It never fails: text that is not daslang becomes an `Error` token, which
//! is reported only if it lies inside an item that is parsed (host code may
//! contain anything). A BOM, CR, tabs and NUL bytes are handled; comments
//! (`//`, nestable `/* */`) are dropped; line breaks become one `Newline`
//! token per run of blank lines.

use super::token::{Kw, LexError, TokKind, Token, P};
use crate::source::Span;

/// Longest string interpolation scan before a string is taken as plain text.
const INTERP_BUDGET: usize = 4096;

/// Lexes `text`, whose first byte has global offset `base`, appending to `out`.
pub fn lex(text: &str, base: u32, out: &mut Vec<Token>) {
    Lexer { b: text.as_bytes(), text, base, i: 0, out, multiline_strings: true }.run()
}

struct Lexer<'a> {
    b: &'a [u8],
    text: &'a str,
    base: u32,
    i: usize,
    out: &'a mut Vec<Token>,
    /// Cleared once a string fails to find its closing quote before the end
    /// of the file, so later ones stop at the end of their line (keeps
    /// lexing linear).
    multiline_strings: bool,
}

fn is_ident_start(c: u8) -> bool {
    c.is_ascii_alphabetic() || c == b'_'
}

/// Letters, digits and `_`, by table: identifiers are most of the bytes
/// the lexer looks at.
static IDENT_CHAR: [bool; 256] = {
    let mut t = [false; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        t[c] = b.is_ascii_alphanumeric() || b == b'_';
        c += 1;
    }
    t
};

fn is_ident_char(c: u8) -> bool {
    IDENT_CHAR[c as usize]
}

impl<'a> Lexer<'a> {
    fn at(&self, i: usize) -> u8 {
        self.b.get(i).copied().unwrap_or(0)
    }

    fn push(&mut self, kind: TokKind, start: usize, end: usize) {
        self.out.push(Token::new(kind, Span::new(self.base + start as u32, self.base + end as u32)));
    }

    fn run(&mut self) {
        if self.text.starts_with('\u{feff}') {
            self.i = 3;
        }
        let b = self.b;
        let n = b.len();
        // The position lives in a local on the hot paths; the rarer scanners
        // read and advance `self.i`.
        let mut i = self.i;
        loop {
            // Blanks between tokens, without a dispatch of their own.
            while i < n && matches!(b[i], b' ' | b'\t') {
                i += 1;
            }
            if i >= n {
                break;
            }
            let c = b[i];
            let start = i;
            match c {
                b'\r' | 0x0b | 0x0c => i += 1,
                b'\n' => {
                    i += 1;
                    if !matches!(self.out.last(), Some(t) if t.kind == TokKind::Newline) {
                        self.push(TokKind::Newline, start, start + 1);
                    }
                }
                b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                    i += 1;
                    while i < n && is_ident_char(b[i]) {
                        i += 1;
                    }
                    // Keywords are lower case.
                    let kind = match c.is_ascii_lowercase().then(|| Kw::from_bytes(&b[start..i])).flatten() {
                        Some(k) => TokKind::Kw(k),
                        None => TokKind::Ident,
                    };
                    self.push(kind, start, i);
                }
                // Brackets and separators, the most common punctuation,
                // have no longer forms.
                b'(' | b')' | b'[' | b']' | b'{' | b'}' | b',' | b';' => {
                    let p = match c {
                        b'(' => P::LParen,
                        b')' => P::RParen,
                        b'[' => P::LBracket,
                        b']' => P::RBracket,
                        b'{' => P::LBrace,
                        b'}' => P::RBrace,
                        b',' => P::Comma,
                        _ => P::Semi,
                    };
                    i += 1;
                    self.push(TokKind::P(p), start, i);
                }
                b'/' if self.at(start + 1) == b'/' => {
                    // `str::find` with a char uses memchr.
                    i = match self.text[start..].find('\n') {
                        Some(k) => start + k,
                        None => n,
                    };
                }
                _ => {
                    self.i = i;
                    match c {
                        b'/' if self.at(start + 1) == b'*' => self.block_comment(),
                        b'0'..=b'9' => self.number(),
                        b'.' if self.at(start + 1).is_ascii_digit() => self.number(),
                        b'"' => self.string(),
                        b'\'' => self.char_lit(),
                        _ => match self.punct() {
                            Some((p, len)) => {
                                self.i += len;
                                self.push(TokKind::P(p), start, start + len);
                            }
                            None => self.bad_chars(),
                        },
                    }
                    i = self.i;
                }
            }
        }
        self.i = i;
    }

    /// A run of characters that are not daslang, as one error token ending
    /// on a char boundary.
    fn bad_chars(&mut self) {
        let start = self.i;
        let mut j = start;
        while j < self.b.len() {
            let c = self.b[j];
            let is_bad = !(c.is_ascii_whitespace()
                || is_ident_char(c)
                || matches!(c, b'"' | b'\'' | b'.' | b'/')
                || (c.is_ascii() && self.punct_at(j).is_some()));
            if !is_bad {
                break;
            }
            // advance by one char
            let len = self.text[j..].chars().next().map(char::len_utf8).unwrap_or(1);
            j += len;
        }
        if j == start {
            j = start + 1;
        }
        self.i = j;
        self.push(TokKind::Error(LexError::BadChar), start, j);
    }

    fn block_comment(&mut self) {
        let start = self.i;
        let n = self.b.len();
        let mut depth = 0usize;
        let mut j = start;
        while j < n {
            if self.b[j] == b'/' && self.at(j + 1) == b'*' {
                depth += 1;
                j += 2;
            } else if self.b[j] == b'*' && self.at(j + 1) == b'/' {
                depth -= 1;
                j += 2;
                if depth == 0 {
                    self.i = j;
                    return;
                }
            } else {
                j += 1;
            }
        }
        self.i = n;
        self.push(TokKind::Error(LexError::UnterminatedComment), start, start + 2);
    }

    fn number(&mut self) {
        let start = self.i;
        let n = self.b.len();
        let mut j = start;
        let mut float = false;
        if self.b[j] == b'0' && matches!(self.at(j + 1), b'x' | b'X') {
            j += 2;
            while j < n && self.b[j].is_ascii_hexdigit() {
                j += 1;
            }
        } else {
            while j < n && self.b[j].is_ascii_digit() {
                j += 1;
            }
            // A fraction: `1.5`, `1.`, `.5`; not `1..2` and not `1.x`.
            if self.at(j) == b'.' && self.at(j + 1) != b'.' && !is_ident_start(self.at(j + 1)) {
                float = true;
                j += 1;
                while j < n && self.b[j].is_ascii_digit() {
                    j += 1;
                }
            }
            if matches!(self.at(j), b'e' | b'E') {
                let k = if matches!(self.at(j + 1), b'+' | b'-') { j + 2 } else { j + 1 };
                if self.at(k).is_ascii_digit() {
                    float = true;
                    j = k;
                    while j < n && self.b[j].is_ascii_digit() {
                        j += 1;
                    }
                }
            }
        }
        // Suffix (`u`, `f`, `d`, `ul`, ...), checked by the parser.
        while j < n && is_ident_char(self.b[j]) {
            j += 1;
        }
        self.i = j;
        self.push(if float { TokKind::Float } else { TokKind::Int }, start, j);
    }

    /// A string literal. daslang strings may span lines and may hold
    /// `{expr}` interpolations with strings of their own inside.
    fn string(&mut self) {
        let start = self.i;
        let mut budget = INTERP_BUDGET;
        let end = match self.scan_string(start + 1, true, &mut budget, 0) {
            Some(e) => Some(e),
            None => self.scan_string(start + 1, false, &mut 0, 0),
        };
        match end {
            Some(e) => {
                self.i = e;
                self.push(TokKind::Str, start, e);
            }
            None => {
                // No closing quote: an error token to the end of the line.
                self.multiline_strings = false;
                let mut j = start + 1;
                while j < self.b.len() && self.b[j] != b'\n' {
                    j += 1;
                }
                self.i = j;
                self.push(TokKind::Error(LexError::UnterminatedString), start, j);
            }
        }
    }

    /// Scans a string body from `i` (just after the opening quote); returns
    /// the index after the closing quote.
    fn scan_string(&self, mut i: usize, interp: bool, budget: &mut usize, depth: u32) -> Option<usize> {
        let n = self.b.len();
        while i < n {
            match self.b[i] {
                b'\\' => i += 2,
                b'"' => return Some(i + 1),
                b'\n' if interp || !self.multiline_strings => return None,
                b'{' if interp => {
                    if depth >= 8 {
                        return None;
                    }
                    i = self.scan_interp(i + 1, budget, depth + 1)?
                }
                _ => i += 1,
            }
            if interp {
                if *budget == 0 {
                    return None;
                }
                *budget -= 1;
            }
        }
        None
    }

    /// Scans an interpolation `{ ... }` from just after the `{`.
    fn scan_interp(&self, mut i: usize, budget: &mut usize, depth: u32) -> Option<usize> {
        let n = self.b.len();
        let mut braces = 1usize;
        while i < n {
            if *budget == 0 {
                return None;
            }
            *budget -= 1;
            match self.b[i] {
                b'"' => i = self.scan_string(i + 1, true, budget, depth)?,
                b'{' => {
                    braces += 1;
                    i += 1;
                }
                b'}' => {
                    braces -= 1;
                    i += 1;
                    if braces == 0 {
                        return Some(i);
                    }
                }
                b'\n' => return None,
                _ => i += 1,
            }
        }
        None
    }

    fn char_lit(&mut self) {
        let start = self.i;
        let n = self.b.len();
        let mut j = start + 1;
        while j < n {
            match self.b[j] {
                b'\\' => j += 2,
                b'\'' => {
                    self.i = j + 1;
                    self.push(TokKind::Char, start, j + 1);
                    return;
                }
                b'\n' => break,
                _ => j += 1,
            }
        }
        self.i = start + 1;
        self.push(TokKind::Error(LexError::UnterminatedChar), start, start + 1);
    }

    fn punct(&self) -> Option<(P, usize)> {
        self.punct_at(self.i)
    }

    /// The longest punctuation token at `i`, with its length.
    fn punct_at(&self, i: usize) -> Option<(P, usize)> {
        use P::*;
        let c0 = self.at(i);
        let c1 = self.at(i + 1);
        let c2 = self.at(i + 2);
        let c3 = self.at(i + 3);
        Some(match c0 {
            b'(' => (LParen, 1),
            b')' => (RParen, 1),
            b'[' => (LBracket, 1),
            b']' => (RBracket, 1),
            b'{' => (LBrace, 1),
            b'}' => (RBrace, 1),
            b',' => (Comma, 1),
            b';' => (Semi, 1),
            b'~' => (Tilde, 1),
            b'#' => (Hash, 1),
            b'$' => (Dollar, 1),
            b':' => match c1 {
                b':' => (ColonColon, 2),
                b'=' => (ColonEq, 2),
                _ => (Colon, 1),
            },
            b'.' => match (c1, c2) {
                (b'.', b'.') => (Ellipsis, 3),
                (b'.', _) => (DotDot, 2),
                _ => (Dot, 1),
            },
            b'?' => match c1 {
                b'.' if !c2.is_ascii_digit() => (QuestionDot, 2),
                b'[' => (QuestionBracket, 2),
                b'?' => (QuestionQuestion, 2),
                _ => (Question, 1),
            },
            b'@' => match c1 {
                b'@' => (AtAt, 2),
                _ => (At, 1),
            },
            b'=' => match c1 {
                b'=' => (EqEq, 2),
                b'>' => (FatArrow, 2),
                _ => (Eq, 1),
            },
            b'!' => match c1 {
                b'=' => (BangEq, 2),
                _ => (Bang, 1),
            },
            b'<' => match (c1, c2, c3) {
                (b'<', b'<', b'=') => (RotlEq, 4),
                (b'<', b'<', _) => (Rotl, 3),
                (b'<', b'=', _) => (ShlEq, 3),
                (b'<', _, _) => (Shl, 2),
                (b'=', _, _) => (Le, 2),
                (b'-', _, _) => (LArrow, 2),
                (b'|', _, _) => (LPipe, 2),
                _ => (Lt, 1),
            },
            b'>' => match (c1, c2, c3) {
                (b'>', b'>', b'=') => (RotrEq, 4),
                (b'>', b'>', _) => (Rotr, 3),
                (b'>', b'=', _) => (ShrEq, 3),
                (b'>', _, _) => (Shr, 2),
                (b'=', _, _) => (Ge, 2),
                _ => (Gt, 1),
            },
            b'+' => match c1 {
                b'+' => (PlusPlus, 2),
                b'=' => (PlusEq, 2),
                _ => (Plus, 1),
            },
            b'-' => match c1 {
                b'-' => (MinusMinus, 2),
                b'=' => (MinusEq, 2),
                b'>' => (Arrow, 2),
                _ => (Minus, 1),
            },
            b'*' => match c1 {
                b'=' => (StarEq, 2),
                _ => (Star, 1),
            },
            b'/' => match c1 {
                b'=' => (SlashEq, 2),
                _ => (Slash, 1),
            },
            b'%' => match c1 {
                b'=' => (PercentEq, 2),
                _ => (Percent, 1),
            },
            b'&' => match (c1, c2) {
                (b'&', b'=') => (AmpAmpEq, 3),
                (b'&', _) => (AmpAmp, 2),
                (b'=', _) => (AmpEq, 2),
                _ => (Amp, 1),
            },
            b'|' => match (c1, c2) {
                (b'|', b'=') => (PipePipeEq, 3),
                (b'|', _) => (PipePipe, 2),
                (b'=', _) => (PipeEq, 2),
                (b'>', _) => (RPipe, 2),
                _ => (Pipe, 1),
            },
            b'^' => match (c1, c2) {
                (b'^', b'=') => (CaretCaretEq, 3),
                (b'^', _) => (CaretCaret, 2),
                (b'=', _) => (CaretEq, 2),
                _ => (Caret, 1),
            },
            _ => return None,
        })
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
    use super::*;

    fn kinds(s: &str) -> Vec<TokKind> {
        let mut v = Vec::new();
        lex(s, 0, &mut v);
        v.into_iter().map(|t| t.kind).collect()
    }

    fn texts(s: &str) -> Vec<&str> {
        let mut v = Vec::new();
        lex(s, 0, &mut v);
        v.into_iter().map(|t| &s[t.span.start as usize..t.span.end as usize]).collect()
    }

    #[test]
    fn numbers() {
        assert_eq!(texts("1.0 1. .5 1e-3 2.5e+2 3f 4u 0xffu 1..2 1.0d"), [
            "1.0", "1.", ".5", "1e-3", "2.5e+2", "3f", "4u", "0xffu", "1", "..", "2", "1.0d"
        ]);
        assert_eq!(kinds("1. .5 7 0x1"), [TokKind::Float, TokKind::Float, TokKind::Int, TokKind::Int]);
    }

    #[test]
    fn punctuation_longest_match() {
        assert_eq!(texts("a<<=b >>= @@f := <- ?? ?. ?[ -> :: ^^ $ ++ -- += ..."), [
            "a", "<<=", "b", ">>=", "@@", "f", ":=", "<-", "??", "?.", "?[", "->", "::", "^^", "$", "++", "--", "+=", "..."
        ]);
        assert_eq!(texts("c?.5:1.0"), ["c", "?", ".5", ":", "1.0"]);
    }

    #[test]
    fn comments_newlines_and_odd_bytes() {
        let s = "\u{feff}a /* x /* nested */ y */ b // c\r\n\r\n\tc\0d";
        assert_eq!(texts(s), ["a", "b", "\n", "c", "\0", "d"]);
        assert_eq!(kinds("é"), [TokKind::Error(LexError::BadChar)]);
        assert_eq!(kinds("/* open"), [TokKind::Error(LexError::UnterminatedComment)]);
    }

    #[test]
    fn strings() {
        assert_eq!(texts(r#"print("a {f("x")} \" b") x"#), ["print", "(", r#""a {f("x")} \" b""#, ")", "x"]);
        assert_eq!(texts("\"open\nx"), ["\"open", "\n", "x"]);
        assert_eq!(texts("\"{\" x"), ["\"{\"", "x"]);
        assert_eq!(texts("'{' x"), ["'{'", "x"]);
    }
}
