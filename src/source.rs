//! Source files and spans.
//!
//! Every file the compiler reads (the input, each `#include`d file, and a
//! virtual file holding the `-D` definitions) is added to one [`SourceMap`].
//! Each file occupies its own range of one global byte-offset space, so a
//! [`Span`] is just two `u32`s — the same shape as `naga::Span`, which lets
//! spans travel into the naga IR and come back out of validation errors
//! still pointing at the right file, line and column.

use std::ops::Range;
use std::path::PathBuf;
use std::sync::OnceLock;

use codespan_reporting::files::{self, Files};

/// Index of a file in a [`SourceMap`].
pub type FileId = usize;

/// A byte range in the global offset space of a [`SourceMap`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    pub start: u32,
    pub end: u32,
}

impl Span {
    pub const fn new(start: u32, end: u32) -> Self {
        Span { start, end }
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span { start: self.start.min(other.start), end: self.end.max(other.end) }
    }

    pub fn is_empty(&self) -> bool {
        self.start == self.end
    }
}

impl From<Span> for naga::Span {
    fn from(s: Span) -> naga::Span {
        naga::Span::new(s.start, s.end)
    }
}

impl From<naga::Span> for Span {
    fn from(s: naga::Span) -> Span {
        match s.to_range() {
            Some(r) => Span::new(r.start as u32, r.end as u32),
            None => Span::default(),
        }
    }
}

/// One file's text and where it sits in the global offset space.
#[derive(Debug)]
pub struct SourceFile {
    /// The name shown in diagnostics (the path as the user gave it).
    pub name: String,
    /// The path on disk, if the file came from disk.
    pub path: Option<PathBuf>,
    pub text: String,
    /// Offset of the file's first byte in the global space.
    pub base: u32,
    /// Byte offsets of line starts, relative to the file: made when a
    /// diagnostic first needs a line number (a successful compile never does).
    line_starts: OnceLock<Vec<usize>>,
    /// The `#include` directive that brought this file in, if any.
    pub included_from: Option<Span>,
}

impl SourceFile {
    pub fn span(&self) -> Span {
        Span::new(self.base, self.base + self.text.len() as u32)
    }

    fn line_starts(&self) -> &[usize] {
        self.line_starts.get_or_init(|| files::line_starts(&self.text).collect())
    }
}

/// All files read by one compilation.
#[derive(Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a file and returns its id. Offsets leave a one-byte gap between
    /// files so that an end-of-file span never lands in the next file.
    pub fn add(&mut self, name: impl Into<String>, path: Option<PathBuf>, text: String, included_from: Option<Span>) -> FileId {
        let base = self.files.last().map(|f| f.base + f.text.len() as u32 + 1).unwrap_or(0);
        self.files.push(SourceFile { name: name.into(), path, text, base, line_starts: OnceLock::new(), included_from });
        self.files.len() - 1
    }

    pub fn file(&self, id: FileId) -> &SourceFile {
        &self.files[id]
    }

    pub fn files(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files.iter().enumerate()
    }

    pub fn len(&self) -> usize {
        self.files.len()
    }

    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// The file containing a global offset.
    pub fn file_of(&self, offset: u32) -> Option<FileId> {
        let idx = self.files.partition_point(|f| f.base <= offset);
        if idx == 0 {
            return None;
        }
        let id = idx - 1;
        let f = &self.files[id];
        (offset <= f.base + f.text.len() as u32).then_some(id)
    }

    /// The file and file-relative byte range of a span.
    pub fn locate(&self, span: Span) -> Option<(FileId, Range<usize>)> {
        let id = self.file_of(span.start)?;
        let f = &self.files[id];
        let start = (span.start - f.base) as usize;
        let end = (span.end.max(span.start) - f.base).min(f.text.len() as u32) as usize;
        Some((id, start..end.max(start)))
    }

    /// The source text a span covers ("" when it is not in any file).
    pub fn slice(&self, span: Span) -> &str {
        match self.locate(span) {
            Some((id, r)) => self.files[id].text.get(r).unwrap_or(""),
            None => "",
        }
    }

    /// One-based line and column (in characters) of a span's start.
    pub fn line_col(&self, span: Span) -> Option<(FileId, usize, usize)> {
        let (id, r) = self.locate(span)?;
        let line = self.line_index(id, r.start).ok()?;
        let col = self.column_number(id, line, r.start).ok()?;
        Some((id, line + 1, col))
    }

    /// The chain of `#include` sites leading to the file holding `span`,
    /// innermost first.
    pub fn include_chain(&self, span: Span) -> Vec<Span> {
        let mut chain = Vec::new();
        let mut cur = self.file_of(span.start);
        while let Some(id) = cur {
            match self.files[id].included_from {
                Some(site) if chain.len() < 64 => {
                    chain.push(site);
                    cur = self.file_of(site.start);
                }
                _ => break,
            }
        }
        chain
    }
}

impl<'a> Files<'a> for SourceMap {
    type FileId = FileId;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        self.files.get(id).map(|f| f.name.as_str()).ok_or(files::Error::FileMissing)
    }

    fn source(&'a self, id: FileId) -> Result<&'a str, files::Error> {
        self.files.get(id).map(|f| f.text.as_str()).ok_or(files::Error::FileMissing)
    }

    fn line_index(&'a self, id: FileId, byte_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        Ok(f.line_starts().partition_point(|&s| s <= byte_index).saturating_sub(1))
    }

    fn line_range(&'a self, id: FileId, line_index: usize) -> Result<Range<usize>, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        let line_starts = f.line_starts();
        let start = *line_starts.get(line_index).ok_or(files::Error::LineTooLarge {
            given: line_index,
            max: line_starts.len() - 1,
        })?;
        let end = line_starts.get(line_index + 1).copied().unwrap_or(f.text.len());
        Ok(start..end)
    }
}
