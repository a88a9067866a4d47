// Shared by the fuzz targets (included with `include!`).

/// The fuzz input as source text: invalid UTF-8 is replaced, like a user's
/// editor would not do, but the bytes-to-text path is covered by
/// `umbrac::syntax::read_source` tests; here the text stages are the target.
fn source_of(data: &[u8]) -> String {
    String::from_utf8_lossy(data).into_owned()
}

/// A root path in a directory that does not exist: every `#include` in a
/// fuzz input fails to resolve, so runs never read the machine's files and
/// stay deterministic.
const ROOT: &str = "/nonexistent-umbrac-fuzz/fuzz.das";

fn parse_options() -> umbrac::syntax::ParseOptions {
    umbrac::syntax::ParseOptions {
        defines: vec![("FUZZ".into(), Some("1.0".into())), ("EMPTY".into(), None)],
        ..Default::default()
    }
}

/// Renders every diagnostic both ways: codespan slicing and line/column
/// arithmetic must hold for any span the stages produce.
fn render_all(diags: &[umbrac::Diagnostic], map: &umbrac::SourceMap) {
    for d in diags {
        let text = d.render(map);
        assert!(!text.is_empty());
        let _ = d.to_json(map);
    }
}
