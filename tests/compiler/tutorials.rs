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

/// What a GL host binds in one GLSL file, spelled so that two files
/// whose stages would link with each other's give the same set: uniforms,
/// uniform blocks (name, each member's type and name, instance name),
/// attributes / varyings / fragment outputs, each with its type, its
/// interpolation qualifiers (`smooth` said or not: a linker compares
/// their presence) and `layout(location = N)` (or none). Precision
/// qualifiers and the `mat4x4` / `mat4` spellings are not told apart.
fn host_declarations(glsl: &str) -> std::collections::BTreeSet<String> {
    let mut out = std::collections::BTreeSet::new();
    let text: String = glsl.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
    let words = |decl: &str| -> Vec<String> {
        decl.split_whitespace().filter(|w| !matches!(*w, "highp" | "mediump" | "lowp")).map(|w| glsl_type(w).to_string()).collect()
    };
    let mut rest = text.as_str();
    let mut top = String::new();
    // Uniform blocks: `[layout(std140)] uniform NAME { members } [instance];`.
    while let Some(at) = rest.find("uniform ") {
        let after = &rest[at + "uniform ".len()..];
        let name: String = after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        let tail = after[name.len()..].trim_start();
        if !name.is_empty() && tail.starts_with('{') {
            let close = tail.find('}').expect("a block ends");
            let members: Vec<String> = tail[1..close].split(';').map(|m| words(m).join(" ")).filter(|m| !m.is_empty()).collect();
            let end = tail[close..].find(';').map_or(tail.len(), |k| close + k);
            let instance = tail[close + 1..end].trim();
            out.insert(format!("block {name} {{ {} }} {instance}", members.join("; ")));
            top.push_str(&rest[..at]);
            rest = &tail[(end + 1).min(tail.len())..];
        } else {
            top.push_str(&rest[..at + "uniform ".len()]);
            rest = after;
        }
    }
    top.push_str(rest);
    for line in top.lines().filter(|l| !l.starts_with([' ', '\t'])) {
        let line = line.trim().trim_end_matches(';');
        let mut location = "none".to_string();
        let mut decl = line;
        if line.starts_with("layout(") {
            // `layout(location=0)` or `layout(location = 0)`.
            let close = line.find(')').expect("a layout closes");
            location = line[..close].chars().filter(|c| c.is_ascii_digit()).collect();
            decl = &line[close + 1..];
        }
        let w = words(decl);
        let (qualifiers, rest) = w.split_at(w.iter().position(|x| matches!(x.as_str(), "uniform" | "in" | "out")).unwrap_or(w.len()));
        let [storage, ty, name] = rest else { continue };
        if name.contains('(') || qualifiers.iter().any(|q| !matches!(q.as_str(), "flat" | "smooth" | "noperspective" | "centroid")) {
            continue;
        }
        let q = if qualifiers.is_empty() { String::new() } else { [qualifiers.join(" "), " ".into()].concat() };
        out.insert(format!("{q}{storage} {ty} {name} location {location}"));
    }
    out
}

/// One GLSL type spelling for the two that name the same type.
fn glsl_type(w: &str) -> &str {
    match w {
        "mat4x4" => "mat4",
        "mat3x3" => "mat3",
        "mat2x2" => "mat2",
        t => t,
    }
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
    let theirs = "uniform mat4 u_model;\n\nlayout(location=0) in vec3 a_pos;\n\nlayout(std140) uniform u_cam_ubo\n{\n    mat4 model;\n    vec3 pos;\n} u_cam;\n\nout vec3 v_n;\nflat out int v_id;\nvoid main()\n{\n\tvec3 x = v_n;\n}\n";
    let ours = "layout(std140) uniform u_cam_ubo {\n    mat4x4 model;\n    vec3 pos;\n} u_cam;\n\nuniform highp mat4x4 u_model;\n\nlayout(location = 0) in vec3 a_pos;\nout vec3 v_n;\nflat out int v_id;\n\nvoid main() {\n    vec3 x = v_n;\n}\n";
    assert_eq!(host_declarations(theirs), host_declarations(ours));
    let d = host_declarations(ours);
    assert!(d.contains("in vec3 a_pos location 0") && d.contains("block u_cam_ubo { mat4 model; vec3 pos } u_cam") && d.contains("uniform mat4 u_model location none"), "{d:?}");
    assert!(d.contains("flat out int v_id location none"), "{d:?}");
    assert_ne!(host_declarations("in vec3 a_pos;\n"), host_declarations("layout(location = 0) in vec3 a_pos;\n"));
    // What keeps two stages from linking is told apart: an interpolation
    // qualifier on one side only, a block of other members or without an
    // instance name.
    assert_ne!(host_declarations("out vec3 v_n;\n"), host_declarations("smooth out vec3 v_n;\n"));
    let wrapped = "layout(std140) uniform u_cam_ubo { Camera u_cam; };\n";
    assert_ne!(host_declarations(wrapped), host_declarations("layout(std140) uniform u_cam_ubo {\n    mat4 model;\n    vec3 pos;\n} u_cam;\n"));
    assert!(host_declarations(wrapped).contains("block u_cam_ubo { Camera u_cam } "), "{:?}", host_declarations(wrapped));
}
