//! daslang's own OpenGL tutorials (`../shared/reference/daslang-tutorials/`),
//! compiled verbatim, host code and all, to every target; every output is
//! validated (naga inside the compiler; glslangValidator on each GLSL file
//! and each program's vertex/fragment pair linked, per profile; spirv-val;
//! tint).
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

/// What a GL host binds in one GLSL file: uniforms, uniform blocks,
/// attributes / varyings / fragment outputs, each with its type and
/// `layout(location = N)` (or none).
fn host_declarations(glsl: &str) -> std::collections::BTreeSet<String> {
    let mut out = std::collections::BTreeSet::new();
    let text: String = glsl.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
    let mut rest = text.as_str();
    let mut top = String::new();
    // Uniform blocks: `[layout(std140)] uniform NAME { ... } [instance];`.
    while let Some(at) = rest.find("uniform ") {
        let after = &rest[at + "uniform ".len()..];
        let name: String = after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        let tail = after[name.len()..].trim_start();
        if !name.is_empty() && tail.starts_with('{') {
            let close = tail.find("};").or_else(|| tail.find('}')).expect("a block ends");
            out.insert(format!("block {name}"));
            top.push_str(&rest[..at]);
            rest = &tail[close..];
            rest = &rest[rest.find(';').map_or(rest.len(), |k| k + 1)..];
        } else {
            top.push_str(&rest[..at + "uniform ".len()]);
            rest = after;
        }
    }
    top.push_str(rest);
    for line in top.lines().filter(|l| !l.starts_with([' ', '\t'])) {
        let mut words: Vec<&str> = line.trim().trim_end_matches(';').split_whitespace().collect();
        let mut location = "none".to_string();
        if let Some(first) = words.first().copied() {
            if first.starts_with("layout(") {
                // `layout(location=0)` or `layout(location = 0)`.
                let mut l = String::new();
                while let Some(w) = words.first().copied() {
                    l.push_str(w);
                    words.remove(0);
                    if w.ends_with(')') {
                        break;
                    }
                }
                location = l.chars().filter(|c| c.is_ascii_digit()).collect();
            }
        }
        words.retain(|w| !matches!(*w, "flat" | "smooth" | "noperspective" | "centroid" | "highp" | "mediump" | "lowp"));
        let [storage, ty, name] = words[..] else { continue };
        if !matches!(storage, "uniform" | "in" | "out") || name.contains('(') {
            continue;
        }
        let ty = match ty {
            "mat4x4" => "mat4",
            "mat3x3" => "mat3",
            "mat2x2" => "mat2",
            t => t,
        };
        out.insert(format!("{storage} {ty} {name} location {location}"));
    }
    out
}

/// For every program of the twelve tutorials, the declarations a GL host
/// binds (uniforms and blocks, attributes, varyings, fragment outputs:
/// name, type, location or none) in umbrac's GLSL 330 and ES 3.00 are the
/// ones daslang's own generator declares for the same program
/// (`../shared/reference/dasglsl-glsl/`).
#[test]
fn gl_interfaces_match_daslangs_generator() {
    let Some(files) = tutorials() else { return };
    let peer = support::repo().join("../shared/reference/dasglsl-glsl");
    let mut failures = Vec::new();
    let mut compared = 0;
    for f in &files {
        let stem = f.file_stem().unwrap().to_string_lossy().into_owned();
        let c = umbrac::compile_file(f, &umbrac::Options::default());
        let Some(compiled) = c.result.as_ref() else {
            failures.push(format!("{stem} does not compile:\n{}", c.render_diagnostics()));
            continue;
        };
        for ep in &compiled.reflection.entry_points {
            for (target, sub) in [("glsl330", ""), ("gles300", "es300/")] {
                let theirs_path = peer.join(&stem).join(format!("{sub}{}.glsl", ep.name));
                let Ok(theirs) = std::fs::read_to_string(&theirs_path) else {
                    failures.push(format!("{stem}: daslang's generator has no {}", theirs_path.display()));
                    continue;
                };
                let ours = compiled.artifact(&ep.files[target]).expect("every GLSL file is emitted").text().into_owned();
                let (a, b) = (host_declarations(&theirs), host_declarations(&ours));
                compared += 1;
                if a != b {
                    let only = |x: &std::collections::BTreeSet<String>, y: &std::collections::BTreeSet<String>| x.difference(y).cloned().collect::<Vec<_>>();
                    failures.push(format!("{stem} {} ({target}):\n  only daslang's: {:?}\n  only umbrac's: {:?}", ep.name, only(&a, &b), only(&b, &a)));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // 51 programs' stages in two profiles (the peer's 102 files).
    assert_eq!(compared, 102, "every file of daslang's generator is compared");
}

#[test]
fn host_declarations_read_both_spellings() {
    let theirs = "uniform mat4 u_model;\n\nlayout(location=0) in vec3 a_pos;\n\nlayout(std140) uniform u_cam_ubo\n{\n    mat4 model;\n} u_cam;\n\nout vec3 v_n;\nvoid main()\n{\n\tvec3 x = v_n;\n}\n";
    let ours = "layout(std140) uniform u_cam_ubo { Camera u_cam; };\n\nuniform mat4x4 u_model;\n\nlayout(location = 0) in vec3 a_pos;\nsmooth out vec3 v_n;\n\nvoid main() {\n    vec3 x = v_n;\n}\n";
    assert_eq!(host_declarations(theirs), host_declarations(ours));
    let d = host_declarations(ours);
    assert!(d.contains("in vec3 a_pos location 0") && d.contains("block u_cam_ubo") && d.contains("uniform mat4 u_model location none"), "{d:?}");
    assert_ne!(host_declarations("in vec3 a_pos;\n"), host_declarations("layout(location = 0) in vec3 a_pos;\n"));
}
