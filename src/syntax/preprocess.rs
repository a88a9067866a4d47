//! The token-based preprocessor.
//!
//! Each file is lexed once. A line whose first token is `#` is a directive:
//! `#include "file"`, `#define NAME [value]`, `#undef`, `#ifdef`, `#ifndef`,
//! `#else`, `#endif`. Other lines pass through, with defined identifiers
//! replaced by their value tokens (which keep the spans of the `#define`'s
//! text). `-D` definitions are `#define` lines in a virtual file named
//! `<command-line>`, so their tokens have spans too. Every included file is
//! added to the [`SourceMap`] with the span of its `#include` directive, so
//! diagnostics show the include chain.

use std::path::{Path, PathBuf};
use std::rc::Rc;

use super::lexer::lex;
use super::lexer::unescape;
use super::token::{TokKind, Token, P};
use super::ParseOptions;
use crate::diag::{Diagnostic, Diagnostics};
use rustc_hash::FxHashMap;
use crate::source::{FileId, SourceMap, Span};

/// Deepest `#include` nesting.
pub const MAX_INCLUDE_DEPTH: usize = 64;
/// Largest single source file.
pub const MAX_FILE_SIZE: usize = 16 * 1024 * 1024;
/// Largest total of all files read (an include may be read many times).
pub const MAX_TOTAL_SIZE: usize = 64 * 1024 * 1024;
/// Most tokens after preprocessing (bounds macro expansion).
/// 4 Mi tokens (48 MiB) is far beyond any real shader and keeps an
/// exponential `#define` bomb to about a second in a release build.
pub const MAX_TOKENS: usize = 4 * 1024 * 1024;
/// Most `#include` directives followed in one compilation.
pub const MAX_INCLUDES: usize = 4096;
/// Deepest macro-within-macro expansion.
const MAX_EXPANSION_DEPTH: usize = 64;

struct Macro {
    value: Rc<[Token]>,
    /// Unique per `#define`, so the macros being expanded are a list of
    /// numbers rather than of names.
    id: usize,
}

#[derive(Clone, Copy)]
struct Cond {
    /// The `#ifdef`/`#ifndef` directive.
    span: Span,
    /// Whether the enclosing region is live.
    parent_active: bool,
    /// Whether the current branch's condition holds.
    taking: bool,
    else_span: Option<Span>,
}

impl Cond {
    fn active(&self) -> bool {
        self.parent_active && self.taking
    }
}

struct Pp<'a> {
    map: &'a mut SourceMap,
    opts: &'a ParseOptions,
    diags: &'a mut Diagnostics,
    defines: FxHashMap<String, Macro>,
    out: Vec<Token>,
    root: FileId,
    /// Canonical paths of the files being processed, outermost first, with
    /// the display name of each.
    stack: Vec<(PathBuf, String)>,
    /// Canonical directories includes may come from. This and the root's
    /// entry in `stack` are made on the first `#include` (they cost file
    /// system calls, and most programs include nothing).
    allowed: Option<super::boundary::Boundary>,
    total_size: usize,
    includes: usize,
    overflowed: bool,
    /// `#define`s seen so far (the next macro's id).
    macros_defined: usize,
    /// Paths an `#include` looked for and did not find as a file before
    /// the one it took: a file appearing there would change the unit.
    probed: Vec<PathBuf>,
    /// Bit `len % 64` is set for the length of every name ever defined: a
    /// cheap first test before looking an identifier up in `defines`.
    macro_lens: u64,
}

/// Preprocesses the root file (already in the map) and returns the token
/// stream of the whole translation unit, ending in a `Newline`.
pub fn preprocess(map: &mut SourceMap, root: FileId, opts: &ParseOptions, diags: &mut Diagnostics) -> Vec<Token> {
    preprocess_probing(map, root, opts, diags).0
}

/// [`preprocess`], and the paths its `#include`s found no file at before
/// the one each took (or at all).
pub fn preprocess_probing(map: &mut SourceMap, root: FileId, opts: &ParseOptions, diags: &mut Diagnostics) -> (Vec<Token>, Vec<PathBuf>) {
    let total_size = map.file(root).text.len();
    let mut pp = Pp {
        map,
        opts,
        diags,
        defines: FxHashMap::default(),
        out: Vec::with_capacity(total_size / 4 + 16),
        root,
        stack: Vec::new(),
        allowed: None,
        total_size,
        includes: 0,
        overflowed: false,
        macros_defined: 0,
        macro_lens: 0,
        probed: Vec::new(),
    };
    if !opts.defines.is_empty() {
        let mut text = String::new();
        for (name, value) in &opts.defines {
            let clean = |s: &str| s.replace(['\n', '\r'], " ");
            match value {
                Some(v) => text.push_str(&format!("#define {} {}\n", clean(name), clean(v))),
                None => text.push_str(&format!("#define {} 1\n", clean(name))),
            }
        }
        let id = pp.map.add("<command-line>", None, text, None);
        pp.file(id, 0);
        // Only definitions come from the command line; drop its newlines.
        pp.out.clear();
    }
    pp.file(root, 0);
    (pp.out, pp.probed)
}

/// The directory of a path, `.` for a bare file name.
fn parent_dir(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

fn is_newline(t: &Token) -> bool {
    t.kind == TokKind::Newline
}

impl Pp<'_> {
    fn push_out(&mut self, t: Token) {
        if self.out.len() >= MAX_TOKENS {
            if !self.overflowed {
                self.overflowed = true;
                self.diags.push(
                    Diagnostic::error(format!("the program is too large after preprocessing (limit {MAX_TOKENS} tokens)"), t.span)
                        .with_label("limit reached here")
                        .with_note("a #define that expands to several copies of another can grow exponentially"),
                );
            }
            return;
        }
        if t.kind == TokKind::Newline && matches!(self.out.last(), Some(l) if l.kind == TokKind::Newline) {
            return;
        }
        self.out.push(t);
    }

    fn text(&self, t: &Token) -> &str {
        self.map.slice(t.span)
    }

    /// Pushes a run of a file's tokens (no two newlines in a row, as the
    /// lexer makes them) in one copy, or one by one near the token limit.
    fn push_run(&mut self, mut run: &[Token]) {
        if run.first().is_some_and(is_newline) && self.out.last().is_some_and(is_newline) {
            run = &run[1..];
        }
        if self.out.len() + run.len() <= MAX_TOKENS {
            self.out.extend_from_slice(run);
        } else {
            for &t in run {
                self.push_out(t);
            }
        }
    }

    /// Whether `t` names a macro. Most identifiers are rejected by their
    /// length alone, without slicing the text or hashing it.
    fn is_macro(&self, t: &Token) -> bool {
        let len = t.span.end - t.span.start;
        self.macro_lens & (1u64 << (len % 64)) != 0 && self.defines.contains_key(self.map.slice(t.span))
    }

    fn file(&mut self, id: FileId, depth: usize) {
        let mut toks = Vec::new();
        {
            let f = self.map.file(id);
            // Typical code has a token every 3 to 5 bytes.
            toks.reserve(f.text.len() / 4 + 16);
            lex(&f.text, f.base, &mut toks);
        }
        let end_span = {
            let s = self.map.file(id).span();
            Span::new(s.end, s.end)
        };
        let mut conds: Vec<Cond> = Vec::new();
        let mut i = 0;
        let n = toks.len();
        let mut line_start = true;
        // Whether the current region is live; it changes only at directives.
        let mut active = true;
        // Tokens from `run` to `i` are live and not pushed yet: they are
        // copied in one go up to the next directive or macro name.
        let mut run = 0;
        while i < n {
            let t = toks[i];
            if line_start && t.is(P::Hash) {
                if active {
                    self.push_run(&toks[run..i]);
                }
                let mut j = i + 1;
                while j < n && !is_newline(&toks[j]) {
                    j += 1;
                }
                self.directive(&toks[i..j], &mut conds, id, depth);
                active = conds.last().is_none_or(Cond::active);
                i = j;
                run = j;
                continue;
            }
            line_start = is_newline(&t);
            if active && t.kind == TokKind::Ident && self.is_macro(&t) {
                self.push_run(&toks[run..i]);
                self.expand(t, &mut Vec::new());
                run = i + 1;
            }
            i += 1;
        }
        if active {
            self.push_run(&toks[run..n]);
        }
        for c in conds.iter().rev() {
            let what = self.map.slice(c.span).to_string();
            self.diags.push(
                Diagnostic::error(format!("unterminated `{what}`"), c.span)
                    .with_label("this conditional has no matching #endif")
                    .with_secondary(end_span, "the file ends here")
                    .with_note("add `#endif` before the end of the file"),
            );
        }
        self.push_out(Token::new(TokKind::Newline, end_span));
    }

    /// Pushes `t`, or the expansion of the macro it names. `active` holds
    /// the ids of the macros being expanded (a macro is not expanded inside
    /// itself).
    fn expand(&mut self, t: Token, active: &mut Vec<usize>) {
        let (id, value) = match self.defines.get(self.map.slice(t.span)) {
            Some(m) if !active.contains(&m.id) => (m.id, m.value.clone()),
            _ => {
                self.push_out(t);
                return;
            }
        };
        if active.len() >= MAX_EXPANSION_DEPTH {
            let msg = format!("macro expansion nested too deeply (limit {MAX_EXPANSION_DEPTH})");
            self.diags.push(Diagnostic::error(msg, t.span).with_label("while expanding this"));
            return;
        }
        active.push(id);
        for v in value.iter() {
            if v.kind == TokKind::Ident {
                self.expand(*v, active);
            } else {
                self.push_out(*v);
            }
            if self.overflowed {
                break;
            }
        }
        active.pop();
    }

    fn directive(&mut self, line: &[Token], conds: &mut Vec<Cond>, file: FileId, depth: usize) {
        let span = line[0].span.to(line[line.len() - 1].span);
        let Some(name_tok) = line.get(1) else {
            return; // a lone `#` is a null directive
        };
        let name = self.text(name_tok).to_string();
        let active = conds.last().is_none_or(Cond::active);
        let args = &line[2..];
        let head = line[0].span.to(name_tok.span);
        match name.as_str() {
            "ifdef" | "ifndef" => {
                let mut taking = false;
                if active {
                    if let Some(id) = self.one_ident(args, &name, head) {
                        taking = self.defines.contains_key(self.text(&id)) == (name == "ifdef");
                    }
                }
                conds.push(Cond { span: head, parent_active: active, taking, else_span: None });
            }
            // Not supported, but counted so that nesting in skipped text stays right.
            "if" => {
                if active {
                    self.diags.push(
                        Diagnostic::error("`#if` is not supported", head)
                            .with_label("unsupported directive")
                            .with_note("help: use `#ifdef NAME` or `#ifndef NAME`"),
                    );
                }
                conds.push(Cond { span: head, parent_active: active, taking: false, else_span: None });
            }
            "else" => match conds.last_mut() {
                None => self.stray(head, "#else"),
                Some(c) => {
                    if let Some(prev) = c.else_span {
                        self.diags.push(
                            Diagnostic::error("`#else` after `#else`", head)
                                .with_label("second #else")
                                .with_secondary(prev, "first #else here")
                                .with_secondary(c.span, "for this conditional"),
                        );
                    } else {
                        c.else_span = Some(head);
                        c.taking = !c.taking;
                        if c.parent_active {
                            self.no_args(args, "#else");
                        }
                    }
                }
            },
            "endif" => match conds.pop() {
                None => self.stray(head, "#endif"),
                Some(c) => {
                    if c.parent_active {
                        self.no_args(args, "#endif");
                    }
                }
            },
            _ if !active => {}
            "define" => {
                let Some(id) = args.first() else {
                    self.diags.push(Diagnostic::error("expected a macro name after `#define`", head).with_label("no name"));
                    return;
                };
                if id.kind != TokKind::Ident {
                    let what = self.text(id).to_string();
                    self.diags.push(
                        Diagnostic::error(format!("`{what}` is not a valid macro name"), id.span)
                            .with_label("expected an identifier")
                            .with_note("a macro name is a letter or `_` followed by letters, digits and `_`; keywords cannot be defined"),
                    );
                    return;
                }
                let key = self.text(id).to_string();
                self.macro_lens |= 1u64 << (key.len() % 64);
                self.macros_defined += 1;
                self.defines.insert(key, Macro { value: args[1..].into(), id: self.macros_defined });
            }
            "undef" => {
                if let Some(id) = self.one_ident(args, "undef", head) {
                    let key = self.text(&id).to_string();
                    self.defines.remove(&key);
                }
            }
            "include" => self.include(args, span, head, file, depth),
            _ => {
                let msg = if name == "elif" {
                    format!("`#{name}` is not supported")
                } else {
                    format!("unknown preprocessor directive `#{name}`")
                };
                self.diags.push(
                    Diagnostic::error(msg, head)
                        .with_label("unknown directive")
                        .with_note("the directives are #include, #define, #undef, #ifdef, #ifndef, #else and #endif"),
                );
            }
        }
    }

    fn stray(&mut self, span: Span, what: &str) {
        self.diags.push(
            Diagnostic::error(format!("`{what}` without a matching `#ifdef` or `#ifndef`"), span)
                .with_label(format!("stray {what}")),
        );
    }

    fn no_args(&mut self, args: &[Token], what: &str) {
        if let Some(first) = args.first() {
            let span = first.span.to(args[args.len() - 1].span);
            self.diags.push(Diagnostic::error(format!("unexpected text after `{what}`"), span).with_label("expected the end of the line"));
        }
    }

    fn one_ident(&mut self, args: &[Token], what: &str, head: Span) -> Option<Token> {
        match args.first() {
            Some(t) if t.kind == TokKind::Ident => {
                if args.len() > 1 {
                    let what = format!("#{what} {}", self.text(t));
                    self.no_args(&args[1..], &what);
                }
                Some(*t)
            }
            Some(t) => {
                let msg = format!("expected a macro name after `#{what}`, found `{}`", self.text(t));
                self.diags.push(Diagnostic::error(msg, t.span).with_label("expected an identifier"));
                None
            }
            None => {
                self.diags.push(Diagnostic::error(format!("expected a macro name after `#{what}`"), head).with_label("no name"));
                None
            }
        }
    }

    /// Makes the canonical directories includes may come from, on first use,
    /// along with the root file's entry at the bottom of the include stack.
    fn init_include_roots(&mut self) {
        if self.allowed.is_none() {
            let root = self.map.file(self.root);
            let root_dir = root.path.as_deref().map(parent_dir).unwrap_or_else(|| PathBuf::from("."));
            let allowed = super::boundary::Boundary::new(std::iter::once(&root_dir).chain(self.opts.include_dirs.iter()));
            if let Some(c) = root.path.as_deref().and_then(|p| std::fs::canonicalize(p).ok()) {
                self.stack.insert(0, (c, root.name.clone()));
            }
            self.allowed = Some(allowed);
        }
    }

    fn include(&mut self, args: &[Token], span: Span, head: Span, file: FileId, depth: usize) {
        let target = match args.first() {
            Some(t) if t.kind == TokKind::Str => *t,
            Some(t) => {
                let msg = format!("expected a file name in double quotes after `#include`, found `{}`", self.text(t));
                self.diags.push(Diagnostic::error(msg, t.span).with_label("expected \"file\""));
                return;
            }
            None => {
                self.diags.push(
                    Diagnostic::error("expected a file name in double quotes after `#include`", head).with_label("no file name"),
                );
                return;
            }
        };
        if args.len() > 1 {
            self.no_args(&args[1..], "#include \"...\"");
        }
        let raw = self.text(&target);
        let name = unescape(raw.get(1..raw.len().saturating_sub(1)).unwrap_or(""));
        if name.is_empty() {
            self.diags.push(Diagnostic::error("empty file name in `#include`", target.span).with_label("empty"));
            return;
        }
        self.includes += 1;
        if self.includes > MAX_INCLUDES {
            if self.includes == MAX_INCLUDES + 1 {
                let msg = format!("too many `#include`s (limit {MAX_INCLUDES})");
                self.diags.push(Diagnostic::error(msg, span).with_label("limit reached at this include"));
            }
            return;
        }
        if depth + 1 > MAX_INCLUDE_DEPTH {
            self.diags.push(
                Diagnostic::error(format!("`#include` nested too deeply (limit {MAX_INCLUDE_DEPTH})"), span)
                    .with_label("this include exceeds the nesting limit"),
            );
            return;
        }

        // Resolve: the including file's directory, then each -I directory.
        let mut searched = Vec::new();
        let mut problems = Vec::new();
        let name_path = Path::new(&name);
        let mut dirs: Vec<PathBuf> = Vec::new();
        if name_path.is_absolute() {
            dirs.push(PathBuf::new());
        } else {
            if let Some(p) = &self.map.file(file).path {
                dirs.push(parent_dir(p));
            }
            dirs.extend(self.opts.include_dirs.iter().cloned());
        }
        let mut found = None;
        for d in dirs {
            let cand = if d.as_os_str().is_empty() { name_path.to_path_buf() } else { d.join(name_path) };
            if super::overlay::holds(&cand) {
                found = Some(cand);
                break;
            }
            match std::fs::metadata(&cand) {
                Ok(m) if m.is_file() => {
                    found = Some(cand);
                    break;
                }
                Ok(_) => problems.push(format!("`{}` is not a file", cand.display())),
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                Err(e) => problems.push(format!("`{}`: {e}", cand.display())),
            }
            searched.push(cand);
        }
        self.probed.extend(searched.iter().cloned());
        let Some(path) = found else {
            let mut d = Diagnostic::error(format!("cannot find include file `{name}`"), target.span).with_label("not found");
            for p in &searched {
                d = d.with_note(format!("searched `{}`", p.display()));
            }
            for p in problems {
                d = d.with_note(p);
            }
            if self.opts.include_dirs.is_empty() && !name_path.is_absolute() {
                d = d.with_note("help: add a directory to search with `-I DIR`");
            }
            self.diags.push(d);
            return;
        };
        let canon = match std::fs::canonicalize(&path) {
            Ok(c) => c,
            // A text only the overlay has is known by its normalized path.
            Err(_) if super::overlay::holds(&path) => super::overlay::normalize(&path),
            Err(e) => {
                let msg = format!("cannot resolve include file `{}`: {e}", path.display());
                self.diags.push(Diagnostic::error(msg, target.span).with_label("cannot resolve"));
                return;
            }
        };
        self.init_include_roots();
        let allowed = self.allowed.as_ref().map(|b| (b.contains(&path, &canon), b.dirs()));
        if let Some((false, dirs)) = allowed.filter(|_| !self.opts.allow_outside_includes) {
            let mut d = Diagnostic::error(
                format!("`#include \"{name}\"` reaches outside the input's directory and the include directories"),
                target.span,
            )
            .with_label("outside the allowed directories")
            .with_note(format!("it resolves to `{}`", canon.display()));
            for a in dirs {
                d = d.with_note(format!("allowed: `{}`", a.display()));
            }
            d = d.with_note("help: add its directory with `-I DIR`, or pass `--allow-outside-includes` to permit it");
            self.diags.push(d);
            return;
        }
        if let Some(pos) = self.stack.iter().position(|(p, _)| *p == canon) {
            let mut chain: Vec<String> = self.stack[pos..].iter().map(|(_, n)| n.clone()).collect();
            chain.push(self.stack[pos].1.clone());
            let d = Diagnostic::error(format!("include cycle: `{}` includes itself", self.stack[pos].1), target.span)
                .with_label("this include closes the cycle")
                .with_note(format!("cycle: {}", chain.join(" -> ")));
            self.diags.push(d);
            return;
        }
        let bytes = match super::read_bounded(&path, MAX_FILE_SIZE) {
            Ok(b) => b,
            Err(super::ReadError::TooLarge(len)) => {
                let msg = format!("include file `{}` is too large ({len} bytes; limit {MAX_FILE_SIZE})", path.display());
                self.diags.push(Diagnostic::error(msg, target.span).with_label("too large"));
                return;
            }
            Err(super::ReadError::NotAFile(what)) => {
                let msg = format!("cannot read include file `{}`: it is {what}, not a regular file", path.display());
                self.diags.push(Diagnostic::error(msg, target.span).with_label("unreadable"));
                return;
            }
            Err(super::ReadError::Io(e)) => {
                let msg = format!("cannot read include file `{}`: {e}", path.display());
                self.diags.push(Diagnostic::error(msg, target.span).with_label("unreadable"));
                return;
            }
        };
        self.total_size += bytes.len();
        if self.total_size > MAX_TOTAL_SIZE {
            let msg = format!("too much source text read through includes (limit {MAX_TOTAL_SIZE} bytes)");
            self.diags.push(Diagnostic::error(msg, target.span).with_label("limit reached at this include"));
            return;
        }
        let text = match String::from_utf8(bytes) {
            Ok(t) => t,
            Err(e) => {
                let msg = format!("include file `{}` is not UTF-8 text", path.display());
                let note = super::invalid_utf8_at(e.as_bytes(), e.utf8_error().valid_up_to());
                self.diags.push(Diagnostic::error(msg, target.span).with_label("not UTF-8").with_note(note));
                return;
            }
        };
        let display = path.display().to_string();
        let id = self.map.add(display.clone(), Some(path), text, Some(span));
        self.stack.push((canon, display));
        self.file(id, depth + 1);
        self.stack.pop();
    }
}
