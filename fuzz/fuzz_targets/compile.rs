//! The whole compile, every target and the reflection manifest: anything
//! the front end accepts must lower, validate in naga and emit. An internal
//! compiler error (naga rejecting umbrac's IR, a backend failure or a
//! caught panic) is a finding.
#![no_main]

use libfuzzer_sys::fuzz_target;

include!("common.rs");

fuzz_target!(|data: &[u8]| {
    let text = source_of(data);
    let opts = umbrac::Options { defines: parse_options().defines, ..Default::default() };
    let c = umbrac::compile_source(ROOT, &text, &opts);
    render_all(&c.diagnostics, &c.sources);
    if let Some(bug) = c.diagnostics.iter().find(|d| d.severity == umbrac::Severity::Bug) {
        panic!("internal compiler error:\n{}", bug.render(&c.sources));
    }
    match &c.result {
        Some(r) => {
            assert!(!c.has_errors());
            assert!(r.artifacts.len() >= 4, "every target was emitted");
        }
        None => assert!(c.diagnostics.iter().any(|d| d.is_error()), "a failed compile says why"),
    }
});
