//! Top-level splitting and reachability.
//!
//! The token stream of a whole daslang file is cut into top-level items by
//! balanced `()[]{}` without parsing them. Then the shader part is picked:
//! every global `var` with a shader qualifier (`@uniform`, `@in`, `@out`,
//! `@inout`, ...), every `def` with a stage annotation (`[vertex_program]`,
//! `[vulkan_vertex_shader]`, ...: `ast::stage_annotation`; filtered by the requested
//! entries), and the
//! `let` constants, functions and structs those reach by name. Nothing else
//! is parsed, so host code can hold anything.

use std::ops::Range;

use super::token::{Kw, Texts, TokKind, Token, P};
use crate::diag::{suggest, Diagnostic, Diagnostics};
use rustc_hash::FxHashMap;
use crate::source::{SourceMap, Span};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ItemKind {
    Def,
    Struct,
    Class,
    Var,
    Let,
    /// `enum Name { ... }`: parsed when a shader names it.
    Enum,
    /// `options`, `require`, `typedef`, ... : never parsed.
    Other,
}

#[derive(Clone, Debug)]
pub struct RawItem {
    pub kind: ItemKind,
    /// The `[...]` annotation groups before the item (empty when none).
    pub annots: Range<usize>,
    /// From the item's first token to its end, including the line break
    /// that ends a line item.
    pub body: Range<usize>,
    /// Token indices of the names the item declares, every other token
    /// from `names.start` (a list is `a, b, c`); see [`RawItem::names`].
    pub names: Range<usize>,
    /// The names a `let { ... }` / `var { ... }` block declares (empty for
    /// other items).
    pub block_names: Vec<usize>,
    /// A `var` with `@uniform`, `@in`, `@out` or `@inout` (or a qualifier
    /// only shaders have, which sema compiles or refuses by name:
    /// `@ssbo`, `@push_constant`, `@groupshared`).
    pub shader_global: bool,
    /// A `def` annotated `[vertex_program]`, `[fragment_program]` or
    /// `[compute_program]`.
    pub entry: bool,
    /// From a required module (`syntax::modules`): never a starting point
    /// of the selection, only reached by name (its globals too).
    pub from_module: bool,
}

impl RawItem {
    /// Token indices of the names the item declares.
    pub fn names(&self) -> impl Iterator<Item = usize> + '_ {
        self.names.clone().step_by(2).chain(self.block_names.iter().copied())
    }

    /// The first name's token index.
    pub fn first_name(&self) -> Option<usize> {
        if self.names.is_empty() {
            self.block_names.first().copied()
        } else {
            Some(self.names.start)
        }
    }

    /// All of the item's tokens, annotations included.
    pub fn range(&self) -> Range<usize> {
        if self.annots.is_empty() {
            self.body.clone()
        } else {
            self.annots.start..self.body.end
        }
    }
}

const MODIFIERS: &[&str] = &["public", "private", "static", "override", "abstract", "sealed", "template", "inscope", "shared", "unsafe"];

/// Whether a line break after `t` continues the item (after an operator,
/// `,`, `=`, an opener...). Tokens that commonly end host type names
/// (`>`, `&`, `?`) end the line.
fn continues(t: &Token) -> bool {
    match t.kind {
        TokKind::P(p) => !matches!(
            p,
            P::RParen
                | P::RBracket
                | P::RBrace
                | P::Semi
                | P::PlusPlus
                | P::MinusMinus
                | P::Question
                | P::Dot
                | P::Hash
                | P::Amp
                | P::Gt
                | P::Shr
                | P::Rotr
        ),
        _ => false,
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    /// One bracket group starting at the first token.
    Group,
    /// To the end of the line (at depth 0), through balanced brackets.
    Line,
    /// Like `Line`, but a `{ ... }` body may start on a later line; the
    /// item ends after the body's closing brace.
    Body,
}

/// Whether the tokens from `k` (a line start inside an unclosed bracket)
/// begin a new top-level function: `def`, or annotations then `def`. Used
/// to stop an item with a missing `}` from swallowing the rest of the file.
fn starts_new_def(toks: &[Token], mut k: usize) -> bool {
    let limit = (k + 64).min(toks.len());
    while k < limit {
        match toks[k].kind {
            TokKind::Kw(Kw::Def) => return true,
            TokKind::P(P::LBracket) => {
                let mut depth = 0usize;
                while k < limit {
                    match toks[k].kind {
                        TokKind::P(P::LBracket) => depth += 1,
                        TokKind::P(P::RBracket) => {
                            depth -= 1;
                            if depth == 0 {
                                break;
                            }
                        }
                        _ => {}
                    }
                    k += 1;
                }
                k += 1;
            }
            TokKind::Newline => k += 1,
            _ => return false,
        }
    }
    false
}

/// The end (exclusive) of the item starting at `start`. `stack` is scratch
/// space for the closers of open brackets.
fn scan(toks: &[Token], start: usize, mode: Mode, guard_defs: bool, stack: &mut Vec<P>) -> usize {
    let n = toks.len();
    stack.clear();
    let mut j = start;
    while j < n {
        // One dispatch per token: every token of the file passes here.
        match toks[j].kind {
            TokKind::P(P::LParen) => stack.push(P::RParen),
            TokKind::P(P::LBracket | P::QuestionBracket) => stack.push(P::RBracket),
            TokKind::P(P::LBrace) => stack.push(P::RBrace),
            TokKind::P(p @ (P::RParen | P::RBracket | P::RBrace)) => {
                if stack.is_empty() {
                    if p == P::RBrace || mode == Mode::Group {
                        return j; // closes something outside this item
                    }
                } else if let Some(pos) = stack.iter().rposition(|&c| c == p) {
                    stack.truncate(pos);
                    if stack.is_empty() && (mode == Mode::Group || (mode == Mode::Body && p == P::RBrace)) {
                        return j + 1;
                    }
                }
            }
            TokKind::Newline => {
                if stack.is_empty() {
                    if mode != Mode::Group && !(j > start && continues(&toks[j - 1])) {
                        if mode == Mode::Body {
                            // `def f(...) : T` with `{` on a later line.
                            let mut k = j + 1;
                            while k < n && toks[k].kind == TokKind::Newline {
                                k += 1;
                            }
                            if k < n && toks[k].is(P::LBrace) {
                                j = k;
                                continue;
                            }
                        }
                        return j + 1;
                    }
                } else if guard_defs && starts_new_def(toks, j + 1) {
                    return j + 1;
                }
            }
            _ => {}
        }
        j += 1;
    }
    n
}

/// Whether token `k` is a modifier word: one of [`MODIFIERS`] followed by a
/// name (`def private f`), a qualifier (`var private @in a`) or a block
/// (`let private { ... }`). Followed by anything else it is a name itself
/// (`var shared = 1`).
fn is_modifier(texts: &Texts, toks: &[Token], k: usize) -> bool {
    toks[k].kind == TokKind::Ident
        && toks.get(k + 1).is_some_and(|t| t.kind == TokKind::Ident || t.is(P::At) || t.is(P::LBrace))
        && MODIFIERS.contains(&texts.get(toks[k].span))
}

/// Splits a preprocessed token stream into top-level items.
pub fn split(toks: &[Token], map: &SourceMap) -> Vec<RawItem> {
    let texts = Texts::new(map);
    let mut items = Vec::new();
    let mut stack = Vec::new();
    let n = toks.len();
    let mut i = 0;
    while i < n {
        match toks[i].kind {
            TokKind::Newline | TokKind::P(P::Semi | P::RParen | P::RBracket | P::RBrace) => {
                i += 1;
                continue;
            }
            _ => {}
        }
        let astart = i;
        while i < n && toks[i].is(P::LBracket) {
            i = scan(toks, i, Mode::Group, true, &mut stack).max(i + 1);
            while i < n && toks[i].kind == TokKind::Newline {
                i += 1;
            }
        }
        let annots = astart..i;
        if i >= n {
            break;
        }
        // `[` `fragment_program` `]` may be written over several lines.
        let after_open = |a: usize| toks[..a].iter().rev().find(|t| t.kind != TokKind::Newline).is_some_and(|t| matches!(t.kind, TokKind::P(P::LBracket | P::Comma)));
        let entry = annots.clone().any(|a| {
            toks[a].kind == TokKind::Ident && after_open(a) && super::ast::stage_annotation(texts.get(toks[a].span)).is_some()
        });
        let kind = match toks[i].kind {
            TokKind::Kw(Kw::Def) => ItemKind::Def,
            // Whatever follows an entry point annotation is parsed as the
            // function it must be: a stray character before `def` (a
            // non-breaking space, a NUL, a BOM) is then a located error, not
            // host code that silently drops the entry point.
            _ if entry => ItemKind::Def,
            TokKind::Kw(Kw::Struct) => ItemKind::Struct,
            TokKind::Kw(Kw::Class) => ItemKind::Class,
            TokKind::Kw(Kw::Var) => ItemKind::Var,
            TokKind::Kw(Kw::Let) => ItemKind::Let,
            TokKind::Ident if texts.get(toks[i].span) == "enum" => ItemKind::Enum,
            _ => ItemKind::Other,
        };
        let end = match kind {
            ItemKind::Def => scan(toks, i, Mode::Body, true, &mut stack),
            ItemKind::Struct | ItemKind::Class | ItemKind::Enum => scan(toks, i, Mode::Body, false, &mut stack),
            _ => scan(toks, i, Mode::Line, true, &mut stack),
        }
        .max(i + 1);
        let mut item =
            RawItem { kind, annots, body: i..end, names: 0..0, block_names: Vec::new(), shader_global: false, entry: false, from_module: false };
        let mut k = i + 1;
        match kind {
            ItemKind::Def | ItemKind::Struct | ItemKind::Class | ItemKind::Enum => {
                while k < end && is_modifier(&texts, toks, k) {
                    k += 1;
                }
                if k < end && toks[k].kind == TokKind::Ident {
                    item.names = k..k + 1;
                }
                item.entry = kind == ItemKind::Def && entry;
            }
            ItemKind::Var | ItemKind::Let => {
                loop {
                    if k < end && is_modifier(&texts, toks, k) {
                        k += 1;
                    } else if k + 1 < end && toks[k].is(P::At) {
                        let q = &toks[k + 1];
                        if q.kind == TokKind::Kw(Kw::In)
                            || (q.kind == TokKind::Ident && matches!(texts.get(q.span), "uniform" | "out" | "inout" | "ssbo" | "push_constant" | "groupshared" | "constant_id"))
                        {
                            item.shader_global = kind == ItemKind::Var;
                        }
                        k += 2;
                        if k + 1 < end && toks[k].is(P::Eq) {
                            k += 2;
                        }
                    } else {
                        break;
                    }
                }
                if k < end && toks[k].is(P::LBrace) {
                    // A block: the names that start its lines (`NAME =` or
                    // `NAME :` at the block's own depth).
                    let mut depth = 0usize;
                    for m in k..end {
                        match toks[m].kind {
                            TokKind::P(P::LParen | P::LBracket | P::LBrace) => depth += 1,
                            TokKind::P(P::RParen | P::RBracket | P::RBrace) => depth = depth.saturating_sub(1),
                            TokKind::Ident if depth == 1 && toks.get(m + 1).is_some_and(|t| t.is(P::Eq) || t.is(P::Colon)) => {
                                let line_start = matches!(toks[m - 1].kind, TokKind::Newline | TokKind::P(P::LBrace | P::Semi));
                                if line_start {
                                    item.block_names.push(m);
                                }
                            }
                            _ => {}
                        }
                    }
                }
                let first = k;
                while k < end && toks[k].kind == TokKind::Ident {
                    item.names = first..k + 1;
                    if k + 2 < end && toks[k + 1].is(P::Comma) {
                        k += 2;
                    } else {
                        break;
                    }
                }
            }
            ItemKind::Other => {}
        }
        items.push(item);
        i = end;
    }
    items
}

/// A top-level name while selecting: the items that declare it, as a list
/// threaded through `Decls::links`, and the last item that declares it
/// locally (where a use of it does not pull in the top-level item).
#[derive(Clone, Copy)]
struct Decl {
    head: u32,
    local_in: u32,
}

const NONE: u32 = u32::MAX;

/// Top-level names and the items declaring them. At most one hash lookup
/// per name use, and no allocation per name or per item.
struct Decls<'m> {
    names: FxHashMap<&'m str, Decl>,
    /// (item, next link) for each declaration.
    links: Vec<(usize, u32)>,
    /// Bit `len % 64` is set for the length of every top-level name: most
    /// identifiers are ruled out by their token's length, without text or hash.
    lens: u64,
}

impl<'m> Decls<'m> {
    fn may_declare(&self, t: &Token) -> bool {
        self.lens & (1u64 << ((t.span.end - t.span.start) % 64)) != 0
    }

    fn add(&mut self, name: &'m str, item: usize) {
        self.lens |= 1u64 << (name.len() % 64);
        let d = self.names.entry(name).or_insert(Decl { head: NONE, local_in: NONE });
        self.links.push((item, d.head));
        d.head = (self.links.len() - 1) as u32;
    }

    /// Marks `name` as declared inside `item` (only top-level names matter).
    fn local(&mut self, name: &str, item: usize) {
        if let Some(d) = self.names.get_mut(name) {
            d.local_in = item as u32;
        }
    }
}

/// Marks the names declared inside an item (locals, loop variables,
/// parameters, its own names): a use of one of these in the item does not
/// pull in a top-level item.
fn mark_locals(toks: &[Token], item: &RawItem, i: usize, texts: &Texts, decls: &mut Decls) {
    let mut mark = |k: usize| {
        if decls.may_declare(&toks[k]) {
            decls.local(texts.get(toks[k].span), i);
        }
    };
    for k in item.names() {
        mark(k);
    }
    let r = item.body.clone();
    if matches!(item.kind, ItemKind::Struct | ItemKind::Class) {
        // Field names: `a, b : T`.
        for k in r {
            if toks[k].kind == TokKind::Ident && toks.get(k + 1).is_some_and(|t| t.is(P::Colon) || t.is(P::Comma)) {
                mark(k);
            }
        }
        return;
    }
    if item.kind != ItemKind::Def {
        return;
    }
    // Parameters: `def name(a, b : T; c : U)`.
    if let Some(name) = item.first_name() {
        if toks.get(name + 1).is_some_and(|t| t.is(P::LParen)) {
            let mut depth = 0usize;
            let mut k = name + 1;
            while k < r.end {
                match toks[k].kind {
                    TokKind::P(P::LParen | P::LBracket) => depth += 1,
                    TokKind::P(P::RParen | P::RBracket) => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    TokKind::Ident if depth == 1 && toks.get(k + 1).is_some_and(|t| t.is(P::Comma) || t.is(P::Colon)) => mark(k),
                    _ => {}
                }
                k += 1;
            }
        }
    }
    for k in r.clone() {
        match toks[k].kind {
            TokKind::Kw(Kw::Let | Kw::Var) => {
                let mut m = k + 1;
                while m < r.end && toks[m].kind == TokKind::Ident {
                    mark(m);
                    if m + 2 < r.end && toks[m + 1].is(P::Comma) {
                        m += 2;
                    } else {
                        break;
                    }
                }
            }
            TokKind::Kw(Kw::For) => {
                let mut m = k + 1;
                while m < r.end && m < k + 16 {
                    match toks[m].kind {
                        TokKind::Ident => mark(m),
                        TokKind::P(P::LParen | P::Comma) => {}
                        _ => break,
                    }
                    m += 1;
                }
            }
            _ => {}
        }
    }
}

/// The `name = "..."` argument of an entry point's annotation, if any.
fn entry_alias<'m>(toks: &[Token], item: &RawItem, texts: &Texts<'m>) -> Option<&'m str> {
    let a = item.annots.clone();
    for k in a.clone() {
        if toks[k].kind == TokKind::Ident
            && texts.get(toks[k].span) == "name"
            && k + 2 < a.end
            && toks[k + 1].is(P::Eq)
            && toks[k + 2].kind == TokKind::Str
        {
            let s = texts.get(toks[k + 2].span);
            return s.get(1..s.len().saturating_sub(1));
        }
    }
    None
}

/// Picks the items to parse: indices into `items`, in source order.
pub fn select(
    items: &[RawItem],
    toks: &[Token],
    map: &SourceMap,
    entries: &[String],
    root_span: Span,
    diags: &mut Diagnostics,
) -> Vec<usize> {
    let texts = Texts::new(map);
    let name_of = |item: &RawItem| item.first_name().map(|k| texts.get(toks[k].span)).unwrap_or("");
    let all_entries: Vec<usize> = (0..items.len()).filter(|&i| items[i].entry).collect();
    if all_entries.is_empty() {
        if !diags.has_errors() {
            diags.push(
                Diagnostic::error("no entry points: no function is annotated `[vertex_program]` or `[fragment_program]`", root_span)
                    .with_code(crate::diag::Code::NoEntryPoints)
                    .with_label("in this file")
                    .with_note("help: annotate a shader function, e.g. `[vertex_program]` on the line before `def main_vs {`")
                    .with_note("the Vulkan dialect's stages are `[vertex_shader]`, `[fragment_shader]`, `[compute_shader]` and their `[vulkan_*_shader]` forms"),
            );
        }
        return Vec::new();
    }
    let mut wanted: Vec<usize> = Vec::new();
    if entries.is_empty() {
        wanted = all_entries.clone();
    } else {
        for req in entries {
            let hits: Vec<usize> = all_entries
                .iter()
                .copied()
                .filter(|&i| name_of(&items[i]) == req || entry_alias(toks, &items[i], &texts) == Some(req.as_str()))
                .collect();
            if hits.is_empty() {
                let names: Vec<&str> = all_entries.iter().map(|&i| name_of(&items[i])).collect();
                let mut d = Diagnostic::error(format!("unknown entry point `{req}`"), root_span)
                    .with_label("requested with --entry")
                    .with_note(format!("available entry points: {}", names.join(", ")));
                if let Some(s) = suggest(req, names.iter().copied()) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                diags.push(d);
            }
            wanted.extend(hits);
        }
    }

    let mut decls = Decls { names: FxHashMap::with_capacity_and_hasher(items.len(), Default::default()), links: Vec::with_capacity(items.len()), lens: 0 };
    // The input's own top-level names hide a module's (`syntax::modules`).
    let own_names: rustc_hash::FxHashSet<&str> = match items.iter().any(|item| item.from_module) {
        true => items.iter().filter(|item| !item.from_module).flat_map(|item| item.names().map(|k| texts.get(toks[k].span))).collect(),
        false => Default::default(),
    };
    for (i, item) in items.iter().enumerate() {
        if item.from_module && item.first_name().is_some_and(|k| own_names.contains(texts.get(toks[k].span))) {
            continue;
        }
        match item.kind {
            ItemKind::Def | ItemKind::Struct | ItemKind::Class | ItemKind::Enum if !item.entry => {
                if let Some(k) = item.first_name() {
                    decls.add(texts.get(toks[k].span), i);
                }
            }
            // Constants, and module variables (a `var` without shader
            // qualifiers), are parsed when a shader names them.
            ItemKind::Let => {
                for k in item.names() {
                    decls.add(texts.get(toks[k].span), i);
                }
            }
            // Module variables (a shader's, or any of a required module's)
            // are found by name.
            ItemKind::Var if !item.shader_global || item.from_module => {
                for k in item.names() {
                    decls.add(texts.get(toks[k].span), i);
                }
            }
            _ => {}
        }
    }

    let mut selected = vec![false; items.len()];
    let mut work: Vec<usize> = Vec::new();
    for (i, item) in items.iter().enumerate() {
        if item.shader_global && !item.from_module {
            selected[i] = true;
            work.push(i);
        }
    }
    for i in wanted {
        if !selected[i] {
            selected[i] = true;
            work.push(i);
        }
    }
    while let Some(i) = work.pop() {
        let item = &items[i];
        mark_locals(toks, item, i, &texts, &mut decls);
        for k in item.range() {
            if toks[k].kind != TokKind::Ident || !decls.may_declare(&toks[k]) {
                continue;
            }
            // A field (`a.b`) is no top-level name; `module::name` is.
            if k > 0 && matches!(toks[k - 1].kind, TokKind::P(P::Dot | P::QuestionDot | P::Arrow)) {
                continue;
            }
            let Some(d) = decls.names.get(texts.get(toks[k].span)) else { continue };
            if d.local_in == i as u32 {
                continue;
            }
            let mut link = d.head;
            while link != NONE {
                let (t, next) = decls.links[link as usize];
                if !selected[t] {
                    selected[t] = true;
                    work.push(t);
                }
                link = next;
            }
        }
    }
    (0..items.len()).filter(|&i| selected[i]).collect()
}
