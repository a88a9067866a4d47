//! Diagnostics: what every stage reports, and how it is shown.
//!
//! Stages push [`Diagnostic`]s into a [`Diagnostics`] sink and carry on where
//! recovery makes sense. Rendering (terminal text with carets, or JSON for
//! editors and build tools) happens once, at the edge, against the
//! [`SourceMap`].

use codespan_reporting::diagnostic::{Diagnostic as CsDiagnostic, Label};
use codespan_reporting::term::{self, termcolor::WriteColor};

use crate::source::{SourceMap, Span};

/// In JSON: `"error"`, `"warning"`, `"bug"`, `"note"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
    /// A bug in umbrac itself (for example naga rejecting IR that umbrac built).
    Bug,
    /// Information about the report itself, not about the source: how
    /// many errors the cap left out ([`Diagnostic::suppressed`]).
    Note,
}

#[derive(Clone, Debug)]
pub struct Diagnostic {
    pub severity: Severity,
    pub message: String,
    /// The main location; `None` for errors with no place in the source
    /// (an unreadable input file, say).
    pub span: Option<Span>,
    /// Text under the caret at `span`.
    pub label: String,
    /// Further locations with their own text.
    pub secondary: Vec<(Span, String)>,
    /// Trailing `= note:` / `= help:` lines.
    pub notes: Vec<String>,
    /// What kind of diagnostic it is, for a tool that acts on a kind
    /// rather than on wording; most have none.
    pub code: Option<Code>,
}

/// The kinds of diagnostic a tool may act on ([`Diagnostic::code`]); one
/// byte, so a diagnostic stays as small as it was.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Code {
    /// A file without entry points: no program (the CLI refuses it as an
    /// input; an editor says nothing of host code, includes and modules).
    NoEntryPoints,
}

impl Code {
    /// Its name, as tools see it.
    pub fn name(self) -> &'static str {
        match self {
            Code::NoEntryPoints => "no-entry-points",
        }
    }
}

impl Diagnostic {
    pub fn error(message: impl Into<String>, span: Span) -> Self {
        Diagnostic {
            severity: Severity::Error,
            message: message.into(),
            span: Some(span),
            label: String::new(),
            secondary: Vec::new(),
            notes: Vec::new(),
            code: None,
        }
    }

    /// An error that has no location in any source file.
    pub fn error_nowhere(message: impl Into<String>) -> Self {
        Diagnostic { span: None, ..Diagnostic::error(message, Span::default()) }
    }

    pub fn bug(message: impl Into<String>, span: Option<Span>) -> Self {
        Diagnostic { severity: Severity::Bug, span, ..Diagnostic::error(message, Span::default()) }
    }

    /// The note that follows a report cut at [`Diagnostics::MAX_ERRORS`]:
    /// not an error itself, so a reader counting errors counts the shown
    /// ones, and `n` more were found.
    pub fn suppressed(n: usize) -> Self {
        let errors = if n == 1 { "error" } else { "errors" };
        Diagnostic { severity: Severity::Note, span: None, ..Diagnostic::error(format!("{n} more {errors} not shown"), Span::default()) }
    }

    pub fn warning(message: impl Into<String>, span: Span) -> Self {
        Diagnostic { severity: Severity::Warning, ..Diagnostic::error(message, span) }
    }

    pub fn with_label(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }

    pub fn with_secondary(mut self, span: Span, label: impl Into<String>) -> Self {
        self.secondary.push((span, label.into()));
        self
    }

    pub fn with_code(mut self, code: Code) -> Self {
        self.code = Some(code);
        self
    }

    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    pub fn is_error(&self) -> bool {
        matches!(self.severity, Severity::Error | Severity::Bug)
    }

    fn to_codespan(&self, map: &SourceMap) -> CsDiagnostic<usize> {
        let mut d = match self.severity {
            Severity::Error => CsDiagnostic::error(),
            Severity::Warning => CsDiagnostic::warning(),
            Severity::Note => CsDiagnostic::note(),
            Severity::Bug => CsDiagnostic::bug(),
        };
        let msg = match self.severity {
            Severity::Bug => format!("internal compiler error: {}", self.message),
            _ => self.message.clone(),
        };
        d = d.with_message(msg);
        let mut labels = Vec::new();
        if let Some((file, range)) = self.span.and_then(|s| map.locate(s)) {
            labels.push(Label::primary(file, range).with_message(self.label.clone()));
        }
        for (span, text) in &self.secondary {
            if let Some((file, range)) = map.locate(*span) {
                labels.push(Label::secondary(file, range).with_message(text.clone()));
            }
        }
        let mut notes = self.notes.clone();
        if let Some(span) = self.span {
            for site in map.include_chain(span) {
                if let Some((file, line, col)) = map.line_col(site) {
                    let how = if map.slice(site).starts_with("require") { "required" } else { "included" };
                    notes.push(format!("{how} from {}:{}:{}", map.file(file).name, line, col));
                }
            }
        }
        d.with_labels(labels).with_notes(notes)
    }

    /// Writes the diagnostic as codespan-reporting text (file:line:col, the
    /// source line and a caret).
    pub fn emit(&self, map: &SourceMap, out: &mut dyn WriteColor) {
        let config = term::Config::default();
        // Rendering can only fail on an I/O error of `out` itself.
        if let Some(excerpt) = Excerpt::of(self, map) {
            let _ = term::emit_to_write_style(out, &config, &excerpt, &excerpt.diagnostic(self.to_codespan(map), &self.label));
            return;
        }
        let _ = term::emit_to_write_style(out, &config, map, &self.to_codespan(map));
    }

    /// The diagnostic rendered to plain text (no colour).
    pub fn render(&self, map: &SourceMap) -> String {
        let mut buf = term::termcolor::NoColor::new(Vec::new());
        self.emit(map, &mut buf);
        String::from_utf8_lossy(&buf.into_inner()).into_owned()
    }

    /// The machine-readable form used by `--message-format json`.
    pub fn to_json(&self, map: &SourceMap) -> JsonDiagnostic {
        let loc = |span: Span| {
            map.locate(span).and_then(|(file, range)| {
                let (_, line, column) = map.line_col(span)?;
                let (_, end_line, end_column) = map.line_col(Span::new(span.end, span.end))?;
                Some(JsonLocation {
                    file: map.file(file).name.clone(),
                    line,
                    column,
                    end_line,
                    end_column,
                    byte_start: range.start,
                    byte_end: range.end,
                })
            })
        };
        JsonDiagnostic {
            severity: self.severity,
            message: self.message.clone(),
            location: self.span.and_then(loc),
            label: self.label.clone(),
            related: self
                .secondary
                .iter()
                .filter_map(|(s, m)| loc(*s).map(|l| JsonRelated { location: l, message: m.clone() }))
                .collect(),
            notes: self.notes.clone(),
            include_chain: self.span.map(|s| map.include_chain(s).into_iter().filter_map(loc).collect()).unwrap_or_default(),
            rendered: self.render(map),
        }
    }
}

/// Source lines longer than this many bytes are shown as an excerpt around
/// the caret: a diagnostic on a 10 MB line printed the whole line (and
/// codespan took seconds to lay it out).
pub const MAX_SHOWN_LINE: usize = 240;

/// How much of a long line is shown on each side of the caret, in bytes.
const EXCERPT_CONTEXT: usize = 60;

/// A diagnostic whose primary location lies on a line longer than
/// [`MAX_SHOWN_LINE`], rendered against a window of that line: `...`, the
/// text around the span, `...`, with the real file name, line and column
/// in the header (codespan asks [`Files`] for them). Other locations of the
/// diagnostic become notes with their positions.
struct Excerpt {
    name: String,
    text: String,
    /// The excerpt's part under the caret.
    label: std::ops::Range<usize>,
    /// One-based line, and the column of the excerpt's first byte after
    /// the leading `...`.
    line: usize,
    first_column: usize,
    prefix: usize,
    /// Secondary labels, as notes.
    notes: Vec<String>,
}

impl Excerpt {
    fn of(d: &Diagnostic, map: &SourceMap) -> Option<Excerpt> {
        use codespan_reporting::files::Files as _;
        let (file, range) = map.locate(d.span?)?;
        let line_index = map.line_index(file, range.start).ok()?;
        let line = map.line_range(file, line_index).ok()?;
        let long = |span: Span| {
            map.locate(span).and_then(|(f, r)| map.line_index(f, r.start).ok().and_then(|i| map.line_range(f, i).ok())).is_some_and(|l| l.len() > MAX_SHOWN_LINE)
        };
        if line.len() <= MAX_SHOWN_LINE && !d.secondary.iter().any(|(s, _)| long(*s)) {
            return None;
        }
        let text = &map.file(file).text;
        let line_end = line.start + text[line.clone()].trim_end_matches(['\n', '\r']).len();
        let floor = |mut i: usize| {
            while !text.is_char_boundary(i) {
                i -= 1;
            }
            i
        };
        let start = floor(range.start.saturating_sub(EXCERPT_CONTEXT).max(line.start));
        let caret_end = floor(range.end.min(range.start + EXCERPT_CONTEXT).min(line_end).max(range.start));
        let end = floor((caret_end + EXCERPT_CONTEXT).min(line_end));
        let (before, after) = (if start > line.start { "..." } else { "" }, if end < line_end { "..." } else { "" });
        let excerpt = format!("{before}{}{after}", &text[start..end]);
        let prefix = before.len();
        let first_column = text[line.start..start].chars().count() + 1;
        let notes = d
            .secondary
            .iter()
            .filter_map(|(span, label)| map.line_col(*span).map(|(f, l, c)| format!("{label} (at {}:{l}:{c})", map.file(f).name)))
            .collect();
        Some(Excerpt {
            name: map.file(file).name.clone(),
            label: prefix + (range.start - start)..prefix + (caret_end - start),
            text: excerpt,
            line: line_index + 1,
            first_column,
            prefix,
            notes,
        })
    }

    /// `full` (the diagnostic as usual) with its labels replaced by one on
    /// the excerpt.
    fn diagnostic(&self, full: CsDiagnostic<usize>, label: &str) -> CsDiagnostic<()> {
        let mut notes = self.notes.clone();
        notes.push(format!("the line is too long to show whole; this is an excerpt (lines longer than {MAX_SHOWN_LINE} bytes are cut)"));
        notes.extend(full.notes);
        CsDiagnostic {
            severity: full.severity,
            code: full.code,
            message: full.message,
            labels: vec![Label::primary((), self.label.clone()).with_message(label.to_string())],
            notes,
        }
    }
}

impl<'a> codespan_reporting::files::Files<'a> for Excerpt {
    type FileId = ();
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, _: ()) -> Result<&'a str, codespan_reporting::files::Error> {
        Ok(&self.name)
    }

    fn source(&'a self, _: ()) -> Result<&'a str, codespan_reporting::files::Error> {
        Ok(&self.text)
    }

    fn line_index(&'a self, _: (), _: usize) -> Result<usize, codespan_reporting::files::Error> {
        Ok(0)
    }

    fn line_range(&'a self, _: (), _: usize) -> Result<std::ops::Range<usize>, codespan_reporting::files::Error> {
        Ok(0..self.text.len())
    }

    fn line_number(&'a self, _: (), _: usize) -> Result<usize, codespan_reporting::files::Error> {
        Ok(self.line)
    }

    fn column_number(&'a self, _: (), _: usize, byte_index: usize) -> Result<usize, codespan_reporting::files::Error> {
        let at = byte_index.clamp(self.prefix, self.text.len());
        Ok(self.first_column + self.text.get(self.prefix..at).map_or(0, |t| t.chars().count()))
    }
}

#[derive(Debug)]
pub struct JsonLocation {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    pub byte_start: usize,
    pub byte_end: usize,
}

#[derive(Debug)]
pub struct JsonRelated {
    pub location: JsonLocation,
    pub message: String,
}

#[derive(Debug)]
pub struct JsonDiagnostic {
    pub severity: Severity,
    pub message: String,
    pub location: Option<JsonLocation>,
    pub label: String,
    pub related: Vec<JsonRelated>,
    pub notes: Vec<String>,
    pub include_chain: Vec<JsonLocation>,
    pub rendered: String,
}

impl serde_core::Serialize for Severity {
    fn serialize<S: serde_core::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let name = match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Bug => "bug",
            Severity::Note => "note",
        };
        serializer.serialize_unit_variant("Severity", *self as u32, name)
    }
}

serialize_struct!(JsonLocation {
    "file": file,
    "line": line,
    "column": column,
    "end_line": end_line,
    "end_column": end_column,
    "byte_start": byte_start,
    "byte_end": byte_end,
});

serialize_struct!(JsonRelated {
    "location": location,
    "message": message,
});

serialize_struct!(JsonDiagnostic {
    "severity": severity,
    "message": message,
    "location": location,
    "label": label,
    "related": related,
    "notes": notes,
    "include_chain": include_chain,
    "rendered": rendered,
});

/// Where stages put their diagnostics. Caps the number of errors kept so a
/// pathological input cannot flood the output.
#[derive(Debug, Default)]
pub struct Diagnostics {
    list: Vec<Diagnostic>,
    suppressed: usize,
}

impl Diagnostics {
    pub const MAX_ERRORS: usize = 50;

    pub fn new() -> Self {
        Self::default()
    }

    pub fn push(&mut self, d: Diagnostic) {
        if d.is_error() && self.error_count() >= Self::MAX_ERRORS {
            self.suppressed += 1;
        } else {
            self.list.push(d);
        }
    }

    pub fn extend(&mut self, ds: impl IntoIterator<Item = Diagnostic>) {
        for d in ds {
            self.push(d);
        }
    }

    pub fn error_count(&self) -> usize {
        self.list.iter().filter(|d| d.is_error()).count()
    }

    pub fn has_errors(&self) -> bool {
        self.list.iter().any(|d| d.is_error())
    }

    /// Errors dropped past [`Self::MAX_ERRORS`].
    pub fn suppressed(&self) -> usize {
        self.suppressed
    }

    pub fn iter(&self) -> impl Iterator<Item = &Diagnostic> {
        self.list.iter()
    }

    pub fn into_vec(self) -> Vec<Diagnostic> {
        self.list
    }
}

/// The message a caught panic carried (`panic!("...")` gives a `&str` or a
/// `String`), for the bug diagnostic that replaces it.
pub(crate) fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// The closest candidate to a misspelt name, for "did you mean" help.
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let mut best: Option<(&str, f64)> = None;
    for c in candidates {
        let score = strsim::jaro_winkler(name, c);
        if score > 0.8 && best.is_none_or(|(_, s)| score > s) {
            best = Some((c, score));
        }
    }
    best.map(|(c, _)| c)
}

#[cfg(test)]
mod excerpt_tests {
    use super::*;

    /// A diagnostic on a very long line shows a bounded excerpt with the
    /// caret under the right character and the real line and column.
    #[test]
    fn long_lines_are_shown_as_an_excerpt() {
        let mut map = SourceMap::new();
        let line: String = "a + ".repeat(250_000) + "é + bad + b";
        let text = format!("first\n{line}\nlast\n");
        let id = map.add("long.das", None, text.clone(), None);
        let base = map.file(id).base;
        let at = text.find("bad").unwrap() as u32;
        let d = Diagnostic::error("unknown name `bad`", Span::new(base + at, base + at + 3)).with_label("here").with_secondary(Span::new(base, base + 5), "the first line");
        let shown = d.render(&map);
        assert!(shown.len() < 2000, "{} bytes rendered:\n{}", shown.len(), &shown[..2000.min(shown.len())]);
        // Column in characters: 1_000_000 ASCII bytes, then `é + `.
        assert!(shown.contains("long.das:2:1000005"), "{shown}");
        assert!(shown.contains("the first line (at long.das:1:1)"), "{shown}");
        let lines: Vec<&str> = shown.lines().collect();
        let src = lines.iter().find(|l| l.contains("bad + b")).unwrap();
        let caret = lines.iter().find(|l| l.contains('^')).unwrap();
        assert_eq!(src.chars().position(|c| c == 'b'), caret.chars().position(|c| c == '^'), "{shown}");
        // A short line is shown whole, as before.
        let d = Diagnostic::error("x", Span::new(base, base + 5));
        assert!(!d.render(&map).contains("excerpt"));
    }
}
