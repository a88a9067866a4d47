//! The front end's text stages: preprocessing, lexing and parsing.
//!
//! `parse` reads the root file (already in the `SourceMap`), runs the
//! preprocessor (which lexes each file once and adds every `#include`d file
//! to the map), splits the token stream into top-level items, keeps the
//! shader globals and the entry points with everything they reach, and
//! parses those into the [`ast::Program`]. Host code is skipped without
//! being parsed, and nothing in it is ever reported.
//!
//! - [`token`]: token kinds (no text; text is `map.slice(span)`)
//! - [`lexer`]: bytes to tokens, never failing
//! - [`preprocess`]: `#include`, `#define`, `#ifdef` ... on tokens
//! - [`items`]: top-level splitting and reachability
//! - [`modules`]: `require`d daslang modules, read as far as shaders reach
//! - [`parser`]: recursive descent over one selected item

pub mod ast;
mod boundary;
pub mod items;
pub mod lexer;
mod module_roots;
pub mod modules;
pub mod parser;
pub mod preprocess;
pub mod token;
pub mod overlay;

use std::path::{Path, PathBuf};

use crate::diag::{Diagnostic, Diagnostics};
use crate::source::{FileId, SourceMap, Span};

pub use boundary::normalize;
pub use parser::{MAX_DEPTH, MAX_IDENT_LEN};
pub use preprocess::{MAX_FILE_SIZE, MAX_INCLUDE_DEPTH};

#[derive(Clone, Debug, Default)]
pub struct ParseOptions {
    pub defines: Vec<(String, Option<String>)>,
    pub include_dirs: Vec<PathBuf>,
    /// Entry points to keep; empty keeps all.
    pub entries: Vec<String>,
    pub allow_outside_includes: bool,
    /// `--daslib DIR`: daslang's `daslib` directory, for `require daslib/...`
    /// (a list, so that it is empty when not given).
    pub daslib: Vec<PathBuf>,
    /// `--daslang-root DIR`: a daslang tree or install (`syntax::module_roots`).
    pub daslang_root: Option<PathBuf>,
    /// `--module PREFIX=DIR`.
    pub module_dirs: Vec<(String, PathBuf)>,
}

/// Reads a source file as UTF-8 text (at most [`MAX_FILE_SIZE`] bytes).
pub fn read_source(path: &Path) -> Result<String, Diagnostic> {
    let bytes = match read_bounded(path, MAX_FILE_SIZE) {
        Ok(b) => b,
        Err(ReadError::TooLarge(len)) => return Err(too_large(path, len)),
        Err(ReadError::NotAFile(what)) => {
            return Err(Diagnostic::error_nowhere(format!("cannot read `{}`: it is {what}, not a regular file", path.display())));
        }
        Err(ReadError::Io(e)) => return Err(Diagnostic::error_nowhere(format!("cannot read `{}`: {e}", path.display()))),
    };
    String::from_utf8(bytes).map_err(|e| {
        let at = invalid_utf8_at(e.as_bytes(), e.utf8_error().valid_up_to());
        Diagnostic::error_nowhere(format!("`{}` is not UTF-8 text: {at}", path.display()))
            .with_note("help: save the file as UTF-8")
    })
}

/// Where the first invalid byte of `bytes` is, for diagnostics:
/// `invalid byte 0xFF at line 3, column 7 (byte offset 41)`. The column
/// counts characters, like every other column umbrac reports.
pub(crate) fn invalid_utf8_at(bytes: &[u8], valid_up_to: usize) -> String {
    let valid_up_to = valid_up_to.min(bytes.len());
    let before = &bytes[..valid_up_to];
    let line_start = before.iter().rposition(|&b| b == b'\n').map_or(0, |k| k + 1);
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    // Everything before `valid_up_to` is valid UTF-8.
    let column = std::str::from_utf8(&before[line_start..]).map_or(0, |s| s.chars().count()) + 1;
    let byte = bytes.get(valid_up_to).copied().unwrap_or(0);
    format!("invalid byte 0x{byte:02X} at line {line}, column {column} (byte offset {valid_up_to})")
}

/// Why [`read_bounded`] read nothing.
#[derive(Debug)]
pub(crate) enum ReadError {
    /// More than the limit: the size, or the limit + 1 where reading stopped.
    TooLarge(u64),
    /// A FIFO, a device, a socket or a directory: opening a FIFO blocks
    /// until someone writes, and `/dev/zero` never ends.
    NotAFile(&'static str),
    Io(std::io::Error),
}

/// Reads a regular file of at most `limit` bytes. What the path is is
/// checked before it is opened (a FIFO would block the open), and at most
/// `limit + 1` bytes are read whatever the file claims, so a file that
/// grows while it is read cannot exhaust memory either.
pub(crate) fn read_bounded(path: &Path, limit: usize) -> Result<Vec<u8>, ReadError> {
    use std::io::Read;
    // An editor's unsaved text stands for the file (`crate::workspace`).
    if let Some(text) = overlay::text_of(path) {
        if text.len() > limit {
            return Err(ReadError::TooLarge(text.len() as u64));
        }
        return Ok(text.into_bytes());
    }
    let meta = std::fs::metadata(path).map_err(ReadError::Io)?;
    if !meta.is_file() {
        return Err(ReadError::NotAFile(file_kind(&meta)));
    }
    if meta.len() > limit as u64 {
        return Err(ReadError::TooLarge(meta.len()));
    }
    let file = std::fs::File::open(path).map_err(ReadError::Io)?;
    // The path may have been replaced between the two looks.
    let opened = file.metadata().map_err(ReadError::Io)?;
    if !opened.is_file() {
        return Err(ReadError::NotAFile(file_kind(&opened)));
    }
    let mut bytes = Vec::with_capacity(opened.len().min(limit as u64) as usize);
    file.take(limit as u64 + 1).read_to_end(&mut bytes).map_err(ReadError::Io)?;
    if bytes.len() > limit {
        return Err(ReadError::TooLarge(bytes.len() as u64));
    }
    Ok(bytes)
}

/// What a path that is not a regular file is, for messages.
fn file_kind(meta: &std::fs::Metadata) -> &'static str {
    if meta.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

fn too_large(path: &Path, len: u64) -> Diagnostic {
    Diagnostic::error_nowhere(format!("`{}` is too large: {len} bytes (limit {MAX_FILE_SIZE} bytes)", path.display()))
}

/// Preprocesses, splits and parses the root file and what it includes.
pub fn parse(map: &mut SourceMap, root: FileId, opts: &ParseOptions, diags: &mut Diagnostics) -> ast::Program {
    if !root_fits(map, root, diags) {
        return ast::Program::default();
    }
    let unit = preprocess_unit(map, root, opts, diags);
    parse_unit(map, root, unit, opts, diags)
}

/// Whether the root file is small enough to preprocess; if not, the error
/// is pushed to `diags` (as [`parse`] does).
pub fn root_fits(map: &SourceMap, root: FileId, diags: &mut Diagnostics) -> bool {
    let f = map.file(root);
    if f.text.len() > MAX_FILE_SIZE {
        let msg = format!("`{}` is too large: {} bytes (limit {MAX_FILE_SIZE} bytes)", f.name, f.text.len());
        diags.push(Diagnostic::error_nowhere(msg));
        return false;
    }
    true
}

/// A translation unit before any item is parsed: the root's preprocessed
/// tokens split into top-level items, with the modules its `require`s
/// reach read and appended. Everything a compilation's outputs depend on,
/// so the cache keys it (`crate::cache`).
#[derive(Debug, Default)]
pub struct Unit {
    pub tokens: Vec<token::Token>,
    pub items: Vec<items::RawItem>,
    pub modules_not_found: Vec<modules::MissingModule>,
    /// Names daslang's builtin-declaring modules declare.
    pub daslang_builtins: Vec<modules::DaslangBuiltin>,
    /// Paths `#include`s and `require`s looked at and found no file at:
    /// one appearing there would change the unit (a rerun's check,
    /// [`crate::rerun`]).
    pub probed: Vec<std::path::PathBuf>,
}

/// Preprocesses the root file, splits it into items and reads the modules
/// it requires (as far as shaders reach into them).
pub fn preprocess_unit(map: &mut SourceMap, root: FileId, opts: &ParseOptions, diags: &mut Diagnostics) -> Unit {
    let (mut tokens, mut probed) = preprocess::preprocess_probing(map, root, opts, diags);
    let mut items = items::split(&tokens, map);
    let loaded = modules::load(map, root, &mut tokens, &mut items, opts, diags, &mut probed);
    Unit { tokens, items, modules_not_found: loaded.missing, daslang_builtins: loaded.builtins, probed }
}

/// The rest of [`parse`] after [`preprocess_unit`]: keeps what shaders
/// reach and parses it. Separate so that a compilation whose unit is
/// already known (a cache lookup) reads and preprocesses once.
pub fn parse_unit(map: &SourceMap, root: FileId, unit: Unit, opts: &ParseOptions, diags: &mut Diagnostics) -> ast::Program {
    let base = map.file(root).base;
    let root_span = Span::new(base, base);
    let Unit { tokens: toks, items: raw, modules_not_found, daslang_builtins, .. } = unit;
    let selected = items::select(&raw, &toks, map, &opts.entries, root_span, diags);
    let texts = token::Texts::new(map);
    let mut program = ast::Program { items: Vec::with_capacity(selected.len()), modules_not_found, daslang_builtins };
    for i in selected {
        let item = &raw[i];
        // Lexing errors count only inside items that are parsed.
        for t in &toks[item.range()] {
            if let token::TokKind::Error(e) = t.kind {
                let what = match e {
                    token::LexError::BadChar => format!("unexpected character `{}`", map.slice(t.span).escape_debug()),
                    _ => e.message().to_string(),
                };
                diags.push(Diagnostic::error(what, t.span).with_label(e.message()));
            }
        }
        parser::parse_item(&toks, item, &texts, diags, &mut program.items);
    }
    program
}
