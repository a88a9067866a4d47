//! The preprocessor alone: `#define`/`#ifdef`/`#include` handling and the
//! lexer under it, on arbitrary text.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;

include!("common.rs");

fuzz_target!(|data: &[u8]| {
    let mut map = umbrac::SourceMap::new();
    let root = map.add(ROOT, Some(PathBuf::from(ROOT)), source_of(data), None);
    let mut diags = umbrac::Diagnostics::new();
    let toks = umbrac::syntax::preprocess::preprocess(&mut map, root, &parse_options(), &mut diags);
    // Every token's span lies in a file of the map.
    for t in &toks {
        assert!(map.locate(t.span).is_some(), "token span {:?} outside every file", t.span);
    }
    let diags = diags.into_vec();
    render_all(&diags, &map);
});
