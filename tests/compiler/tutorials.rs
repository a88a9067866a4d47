//! daslang's own OpenGL tutorials (`../shared/reference/daslang-tutorials/`),
//! compiled verbatim, host code and all, to every target; every output is
//! validated (naga inside the compiler; glslangValidator on each GLSL file
//! and each program's vertex/fragment pair linked, per profile; spirv-val).
//! Skipped only when the reference folder is not there.

use std::path::PathBuf;

use crate::support;

fn tutorials() -> Option<Vec<PathBuf>> {
    let dir = support::repo().join("../shared/reference/daslang-tutorials");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        eprintln!("skipping: {} is not here", dir.display());
        return None;
    };
    let mut files: Vec<PathBuf> = entries.map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "das")).collect();
    files.sort();
    Some(files)
}

#[test]
fn every_tutorial_compiles_to_every_target_and_validates() {
    let Some(files) = tutorials() else { return };
    assert_eq!(files.len(), 12, "daslang's twelve GL tutorials");
    let mut failures = Vec::new();
    let mut runs = 0;
    for f in &files {
        let c = umbrac::compile_file(f, &umbrac::Options::default());
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let Some(compiled) = c.result.as_ref().filter(|_| !c.has_errors()) else {
            failures.push(format!("{name} does not compile:\n{}", c.render_diagnostics()));
            continue;
        };
        if compiled.reflection.entry_points.is_empty() {
            failures.push(format!("{name}: no entry points"));
        }
        let dir = tempfile::tempdir().unwrap();
        support::write_all(dir.path(), &compiled.artifacts);
        runs += support::validate_dir(dir.path(), &compiled.reflection);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!("{} tutorials, {runs} validator runs", files.len());
}
