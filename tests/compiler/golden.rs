//! Golden outputs: every program under shaders/ is compiled for every target
//! and diffed against tests/golden/<stem>/ on every run.
//! Re-bless after an intended change with `UMBRAC_BLESS=1 cargo test --test compiler golden::`.

use std::path::{Path, PathBuf};

/// The programs under shaders/, found as `umbrac compile shaders/` finds
/// them.
fn programs() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    umbrac::batch::programs_under(&root).expect("shaders/ is readable").into_iter().map(|f| f.path).collect()
}

#[test]
fn every_program_matches_its_golden_outputs() {
    let programs = programs();
    assert!(!programs.is_empty(), "no programs under shaders/");
    let mut failures = Vec::new();
    for p in &programs {
        let rel = p.strip_prefix(env!("CARGO_MANIFEST_DIR")).unwrap();
        let c = umbrac::compile_file(rel, &options_of(p));
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

/// The options a program under shaders/ asks for on its first line,
/// `// umbrac: --target wgsl --target spirv` (a program with a construct
/// only some targets have: shaders/wgsl_spirv/, shaders/spirv/), or `// umbrac:
/// --gl-uniforms blocks`; default: all targets, plain GL uniforms.
fn options_of(path: &Path) -> umbrac::Options {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut opts = umbrac::Options::default();
    if let Some(args) = text.lines().next().and_then(|l| l.strip_prefix("// umbrac:")) {
        let words: Vec<&str> = args.split_whitespace().collect();
        for pair in words.chunks(2) {
            match pair {
                ["--target", t] => opts.targets.push(umbrac::Target::from_name(t).unwrap_or_else(|| panic!("{}: unknown target `{t}`", path.display()))),
                ["--gl-uniforms", "blocks"] => opts.gl_uniforms = umbrac::GlUniforms::Blocks,
                other => panic!("{}: unknown option {other:?} on the first line", path.display()),
            }
        }
    }
    opts
}
