//! Golden outputs: every program under shaders/ is compiled for every target
//! and diffed against tests/golden/<stem>/ on every run.
//! Re-bless after an intended change with `UMBRAC_BLESS=1 cargo test --test compiler golden::`.

use std::path::{Path, PathBuf};

fn programs() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let mut out = Vec::new();
    let mut dirs = vec![root];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(&d).expect("shaders/ is readable") {
            let p = e.expect("directory entry").path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|x| x == "das") && !p.to_string_lossy().contains("/include/") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

#[test]
fn every_program_matches_its_golden_outputs() {
    let programs = programs();
    assert!(!programs.is_empty(), "no programs under shaders/");
    let mut failures = Vec::new();
    for p in &programs {
        let rel = p.strip_prefix(env!("CARGO_MANIFEST_DIR")).unwrap();
        let c = umbrac::compile_file(rel, &umbrac::Options::default());
        let Some(compiled) = c.result.as_ref() else {
            failures.push(format!("{} does not compile:\n{}", rel.display(), c.render_diagnostics()));
            continue;
        };
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden").join(umbrac::stem_of(&rel.to_string_lossy()));
        if let Err(e) = umbrac::golden::check_or_bless(&compiled.artifacts, &dir) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
