//! The whole front end's text stages: preprocessing, item splitting and
//! selection, and the parser.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;

include!("common.rs");

fuzz_target!(|data: &[u8]| {
    let mut map = umbrac::SourceMap::new();
    let root = map.add(ROOT, Some(PathBuf::from(ROOT)), source_of(data), None);
    let mut diags = umbrac::Diagnostics::new();
    let program = umbrac::syntax::parse(&mut map, root, &parse_options(), &mut diags);
    let diags = diags.into_vec();
    render_all(&diags, &map);
    // The checker must take whatever the parser produced without errors.
    if !diags.iter().any(|d| d.is_error()) {
        let mut more = umbrac::Diagnostics::new();
        let _ = umbrac::sema::check(&program, &mut more);
        assert!(more.iter().all(|d| d.severity != umbrac::Severity::Bug));
    }
});
