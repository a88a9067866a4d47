//! Robustness: text edge cases, #include confinement, outputs that survive
//! failures and kills, error recovery without cascades, and internal
//! compiler errors.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use umbrac::{compile_file, compile_source, Compilation, Options, Severity};

use crate::support::umbrac;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn errors(c: &Compilation) -> Vec<String> {
    c.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.message.clone()).collect()
}

/// `file:line:col: message` of each error.
fn locs(c: &Compilation) -> Vec<String> {
    c.diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| match d.span.and_then(|s| c.sources.line_col(s)) {
            Some((f, l, col)) => {
                let name = Path::new(&c.sources.file(f).name).file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
                format!("{name}:{l}:{col}: {}", d.message)
            }
            None => d.message.clone(),
        })
        .collect()
}

/// Every file under `dir` with its bytes.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut m = BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            m.extend(snapshot(&p));
        } else {
            m.insert(p.clone(), std::fs::read(&p).unwrap());
        }
    }
    m
}

const FS_HEAD: &str = "var @out f_color : float4\n[fragment_program]\ndef fs {\n";

fn fs(body: &str) -> String {
    format!("{FS_HEAD}{body}\n}}\n")
}

// ---------------------------------------------------------------- text

#[test]
fn non_utf8_input_names_the_file_line_and_offset() {
    let d = tempfile::tempdir().unwrap();
    let mut bytes = fs("    f_color = float4(1.0)").into_bytes();
    // Line 4 is "    f_color = ..."; put a Latin-1 'é' after "// caf".
    let at = bytes.len();
    bytes.extend_from_slice(b"// caf\xe9\n");
    std::fs::write(d.path().join("latin1.das"), &bytes).unwrap();
    let c = compile_file(&d.path().join("latin1.das"), &Options::default());
    let m = errors(&c);
    assert_eq!(m.len(), 1, "{m:?}");
    assert!(m[0].contains("latin1.das") && m[0].contains("not UTF-8"), "{}", m[0]);
    let want = format!("invalid byte 0xE9 at line 6, column 7 (byte offset {})", at + 6);
    assert!(m[0].ends_with(&want), "{} / {want}", m[0]);

    // Through the CLI: exit 1, nothing written.
    let o = umbrac(&["compile", "latin1.das", "-o", "out"], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains(&want), "{}", stderr(&o));
    assert!(!d.path().join("out").exists());
}

#[test]
fn nul_bytes_are_an_error_in_code_and_ignored_in_comments() {
    let c = compile_source("nul.das", &fs("    // a \0 in a comment\n    f_color = float4(1.0)"), &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let c = compile_source("nul.das", &fs("    f_color = float4(1.0)\0"), &Options::default());
    assert_eq!(locs(&c), ["nul.das:4:26: unexpected character `\\0`"]);
}

#[test]
fn crlf_bom_and_tabs_compile_to_the_same_outputs() {
    let plain = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/shadow.das")).unwrap();
    let dos = format!("\u{feff}{}", plain.replace("    ", "\t").replace('\n', "\r\n"));
    let a = compile_source("shadow.das", &plain, &Options::default());
    let b = compile_source("shadow.das", &dos, &Options::default());
    assert!(!a.has_errors() && !b.has_errors(), "{}", b.render_diagnostics());
    let (a, b) = (a.result.unwrap(), b.result.unwrap());
    for x in &a.artifacts {
        if x.target == Some(umbrac::Target::Spirv) {
            continue; // SPIR-V carries no text positions but is compared anyway below
        }
        let y = b.artifact(&x.file_name).unwrap();
        assert_eq!(x.text(), y.text(), "{}", x.file_name);
    }
    // Errors after CRLF lines are on the right line and column.
    let c = compile_source("dos.das", &fs("\tf_color = float4(1.0)\r\n\tf_color = colr").replace('\n', "\r\n"), &Options::default());
    assert_eq!(locs(&c), ["dos.das:5:12: unknown name `colr`"]);
}

/// Columns count characters (a tab is one, `é` is one), and the rendered
/// caret sits under the right character once the terminal expands tabs.
#[test]
fn columns_count_characters_and_carets_line_up() {
    let src = fs("\t/* déjà vu, 日本 */ f_color = float4(colr)");
    let c = compile_source("cols.das", &src, &Options::default());
    // 1 tab + 18 chars of comment and space + "f_color = float4(" (17) before `colr`.
    assert_eq!(locs(&c), ["cols.das:4:37: unknown name `colr`"]);
    let json = c.diagnostics[0].to_json(&c.sources);
    assert_eq!((json.location.as_ref().unwrap().column, json.location.as_ref().unwrap().end_column), (37, 41));

    // In the rendered text, the caret line's `^` starts at the display
    // column where `colr` starts in the source line above it (wide
    // characters take two columns, tabs expand to spaces).
    let rendered = c.render_diagnostics();
    let lines: Vec<&str> = rendered.lines().collect();
    let src_line = lines.iter().position(|l| l.contains("float4(colr)")).expect(&rendered);
    let caret_line = lines[src_line + 1];
    let width = |s: &str| s.chars().map(|ch| if ('\u{3000}'..='\u{9fff}').contains(&ch) { 2 } else { 1 }).sum::<usize>();
    let src_text = lines[src_line];
    assert!(!src_text.contains('\t'), "codespan expands tabs: {src_text:?}");
    let colr_at = width(&src_text[..src_text.find("colr").unwrap()]);
    let caret_at = width(&caret_line[..caret_line.find('^').expect(&rendered)]);
    assert_eq!(caret_at, colr_at, "\n{rendered}");
}

#[test]
fn very_long_lines() {
    // A 1 MB comment line, then a 1 MB line of statements.
    let comment = format!("    // {}\n", "x".repeat(1 << 20));
    let stmts = "f_color = f_color * 1.0; ".repeat((1 << 20) / 25);
    let c = compile_source("long.das", &fs(&format!("    f_color = float4(1.0)\n{comment}    {stmts}")), &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    // An error at the end of a 1 MB line has the right column.
    let pad = "a".repeat(1 << 20);
    let c = compile_source("long.das", &fs(&format!("    /* {pad} */ f_color = colr")), &Options::default());
    assert_eq!(locs(&c), [format!("long.das:4:{}: unknown name `colr`", 4 + 3 + pad.len() + 4 + 10 + 1)]);
}

// ---------------------------------------------------------------- includes

struct Dir(tempfile::TempDir);

impl Dir {
    fn new() -> Dir {
        Dir(tempfile::tempdir().unwrap())
    }
    fn path(&self, name: &str) -> PathBuf {
        self.0.path().join(name)
    }
    fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(&p, text).unwrap();
        p
    }
}

fn with_include(inc: &str) -> String {
    format!("#include \"{inc}\"\n{}", fs("    f_color = float4(1.0)"))
}

#[test]
fn include_of_a_directory_is_an_error() {
    let d = Dir::new();
    std::fs::create_dir(d.path("proj/sub")).unwrap_or_else(|_| {
        std::fs::create_dir_all(d.path("proj/sub")).unwrap();
    });
    let root = d.write("proj/main.das", &with_include("sub"));
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c), ["main.das:1:10: cannot find include file `sub`"]);
    assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("is not a file")), "{:?}", c.diagnostics[0].notes);
}

#[test]
fn absolute_includes_are_confined_too() {
    let d = Dir::new();
    let inside = d.write("proj/lib.das", "let K = 1.0\n");
    let outside = d.write("elsewhere/lib.das", "let K = 1.0\n");
    let root = d.write("proj/main.das", &with_include(inside.to_str().unwrap()));
    let c = compile_file(&root, &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let root = d.write("proj/main.das", &with_include(outside.to_str().unwrap()));
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c).len(), 1, "{:?}", locs(&c));
    assert!(locs(&c)[0].contains("reaches outside the input's directory"), "{:?}", locs(&c));
    let c = compile_file(&root, &Options { allow_outside_includes: true, ..Options::default() });
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let c = compile_file(&root, &Options { include_dirs: vec![d.path("elsewhere")], ..Options::default() });
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
}

#[test]
fn dotdot_escapes_are_refused_with_the_chain() {
    let d = Dir::new();
    d.write("secret.das", "let K = 1.0\n");
    d.write("proj/a.das", "#include \"inner/b.das\"\n");
    d.write("proj/inner/b.das", "#include \"../../secret.das\"\n");
    let root = d.write("proj/main.das", &with_include("a.das"));
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c), ["b.das:1:10: `#include \"../../secret.das\"` reaches outside the input's directory and the include directories"]);
    // The chain: b.das was included from a.das, which main.das included.
    let text = c.render_diagnostics();
    let a = text.find("included from").expect(&text);
    assert!(text[a..].contains("a.das:1:1") && text[a..].contains("main.das:1:1"), "{text}");
    let json = c.diagnostics[0].to_json(&c.sources);
    let chain: Vec<String> = json.include_chain.iter().map(|l| format!("{}:{}", Path::new(&l.file).file_name().unwrap().to_string_lossy(), l.line)).collect();
    assert_eq!(chain, ["a.das:1", "main.das:1"]);
}

/// The directory the user named is the boundary (a sandbox of symlinks
/// must work, tests/compiler/sandbox.rs): a link placed inside it is
/// followed, but a `..` through a link that leads elsewhere is judged by
/// where it really leads.
#[cfg(unix)]
#[test]
fn symlinks_that_escape_or_loop_are_refused() {
    let d = Dir::new();
    let secret = d.write("secret.das", "let K = 1.0\n");
    d.write("elsewhere/deep/x.das", "");
    std::fs::create_dir_all(d.path("proj")).unwrap();
    std::os::unix::fs::symlink(&secret, d.path("proj/link.das")).unwrap();
    let root = d.write("proj/main.das", &with_include("link.das"));
    let c = compile_file(&root, &Options::default());
    assert!(!c.has_errors(), "a link inside the named directory: {}", c.render_diagnostics());
    std::os::unix::fs::symlink(d.path("elsewhere/deep"), d.path("proj/deep")).unwrap();
    let root = d.write("proj/main.das", &with_include("deep/../secret.das"));
    std::fs::write(d.path("elsewhere/secret.das"), "let K = 1.0\n").unwrap();
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c).len(), 1, "{:?}", locs(&c));
    assert!(locs(&c)[0].contains("reaches outside"), "{:?}", locs(&c));
    assert!(c.diagnostics[0].notes.iter().any(|n| n.contains("elsewhere/secret.das")), "the note shows where it resolves");

    // A loop of symlinks, included from a nested include: the error is at
    // the inner directive and the chain leads back to main.das.
    std::os::unix::fs::symlink(d.path("proj/l1.das"), d.path("proj/l2.das")).unwrap();
    std::os::unix::fs::symlink(d.path("proj/l2.das"), d.path("proj/l1.das")).unwrap();
    d.write("proj/mid.das", "\n#include \"l1.das\"\n");
    let root = d.write("proj/main.das", &with_include("mid.das"));
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c), ["mid.das:2:10: cannot find include file `l1.das`"]);
    let text = c.render_diagnostics();
    assert!(text.contains("symbolic links") && text.contains("included from") && text.contains("main.das:1:1"), "{text}");
}

#[test]
fn include_cycles_show_the_whole_chain() {
    let d = Dir::new();
    d.write("a.das", "#include \"b.das\"\n");
    d.write("b.das", "#include \"c.das\"\n");
    d.write("c.das", "#include \"a.das\"\n");
    let root = d.write("main.das", &with_include("a.das"));
    let c = compile_file(&root, &Options::default());
    assert_eq!(locs(&c), ["c.das:1:10: include cycle: `".to_owned() + &d.path("a.das").display().to_string() + "` includes itself"]);
    let note = c.diagnostics[0].notes.iter().find(|n| n.starts_with("cycle:")).unwrap();
    let names: Vec<&str> = note.trim_start_matches("cycle: ").split(" -> ").map(|p| p.rsplit('/').next().unwrap()).collect();
    assert_eq!(names, ["a.das", "b.das", "c.das", "a.das"]);
}

// ---------------------------------------------------------------- outputs

#[test]
fn output_path_that_is_a_file_is_a_clear_cli_error() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("out"), "not a directory").unwrap();
    let src = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/shadow.das");
    let o = umbrac(&["compile", src, "-o", "out"], d.path());
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("the output path exists and is not a directory"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(d.path().join("out")).unwrap(), "not a directory");
    let o = umbrac(&["compile", src, "-o", "out/sub"], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("cannot create the output directory"), "{}", stderr(&o));
}

/// A big generated program: many helper functions, so a compile takes a
/// while and its outputs are large.
fn big_program(n: usize, salt: &str) -> String {
    let mut s = String::from("var @uniform u_k : float\nvar @inout v_x : float4\nvar @out f_color : float4\n");
    for i in 0..n {
        s.push_str(&format!("def h{i}(x : float4) : float4 {{\n    return sin(x * {i}.5 + float4(u_k)) * 0.5 + cos(x.yzwx) * {salt}\n}}\n"));
    }
    s.push_str("[vertex_program]\ndef vs {\n    var p = float4(0.0)\n");
    for i in 0..n {
        s.push_str(&format!("    p = h{i}(p)\n"));
    }
    s.push_str("    v_x = p\n    gl_Position = p\n}\n[fragment_program]\ndef fs {\n    f_color = v_x\n}\n");
    s
}

/// SIGKILL at many points of a compile: every output is always either the
/// previous version or the new one, complete, and no temporary ever looks
/// like an output. The next successful run cleans up leftover temporaries.
#[cfg(unix)]
#[test]
fn killed_compiles_leave_previous_outputs_intact() {
    use std::time::{Duration, Instant};
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    std::fs::write(d.path().join("big.das"), big_program(300, "0.25")).unwrap();
    let o = umbrac(&["compile", "big.das", "-o", "out"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let old = snapshot(&out);
    assert!(old.len() >= 5);

    // The new version of the outputs, made in another directory.
    std::fs::write(d.path().join("big.das"), big_program(300, "0.75")).unwrap();
    // The kill points are fractions of a full run's time: the quickest of
    // three, so that one run slowed by a loaded machine does not push every
    // kill past the end of the (faster) runs that follow.
    let mut full = Duration::MAX;
    for _ in 0..3 {
        let start = Instant::now();
        let o = umbrac(&["compile", "big.das", "-o", "new"], d.path());
        full = full.min(start.elapsed());
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    let new: BTreeMap<String, Vec<u8>> = snapshot(&d.path().join("new")).into_iter().map(|(p, b)| (p.file_name().unwrap().to_string_lossy().into_owned(), b)).collect();
    let old: BTreeMap<String, Vec<u8>> = old.into_iter().map(|(p, b)| (p.file_name().unwrap().to_string_lossy().into_owned(), b)).collect();
    assert_eq!(new.keys().collect::<Vec<_>>(), old.keys().collect::<Vec<_>>());
    assert!(new.iter().filter(|(k, v)| old[*k] != **v).count() >= 4, "the shader outputs differ between the versions");

    let mut killed = 0;
    let mut finished = 0;
    // Kills after which some outputs were new and some old: the kill landed
    // between two renames.
    let mut mixed = 0;
    let steps = 24;
    for step in 0..steps {
        // Kill points spread over the whole run, densest near the end where
        // the writes happen.
        let frac = 1.0 - (1.0 - (step as f64 + 0.5) / steps as f64).powi(2);
        let delay = full.mul_f64(frac * 1.6);
        let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["compile", "big.das", "-o", "out"])
            .current_dir(d.path())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(delay.min(Duration::from_secs(60)));
        let _ = child.kill(); // SIGKILL
        let status = child.wait().unwrap();
        if status.success() {
            finished += 1;
        } else {
            killed += 1;
        }
        let (mut as_old, mut as_new) = (0, 0);
        for e in std::fs::read_dir(&out).unwrap() {
            let name = e.unwrap().file_name().to_string_lossy().into_owned();
            if name.starts_with('.') {
                assert!(name == umbrac::output::journal::RECORD || (name.starts_with(".umbrac-") && name.ends_with(".tmp")), "unexpected hidden file {name}");
                continue;
            }
            let bytes = std::fs::read(out.join(&name)).unwrap();
            let (o, n) = (old.get(&name), new.get(&name));
            assert!(o.is_some(), "stray output {name} after a kill at {delay:?}");
            assert!(Some(&bytes) == o || Some(&bytes) == n, "{name} is neither the old nor the new version after a kill at {delay:?}");
            if o != n {
                if Some(&bytes) == o {
                    as_old += 1;
                } else {
                    as_new += 1;
                }
            }
        }
        if as_old > 0 && as_new > 0 {
            mixed += 1;
        }
        // Start the next run from the old outputs again.
        for (name, bytes) in &old {
            std::fs::write(out.join(name), bytes).unwrap();
        }
        for name in old.keys() {
            assert!(out.join(name).exists(), "{name} disappeared after a kill at {delay:?}");
        }
    }
    // Kills aimed at the write phase: as soon as a temporary appears.
    let mut during_write = 0;
    for _ in 0..6 {
        let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["compile", "big.das", "-o", "out"])
            .current_dir(d.path())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            let temp = std::fs::read_dir(&out).unwrap().flatten().any(|e| e.file_name().to_string_lossy().starts_with(".umbrac-"));
            if temp {
                let _ = child.kill();
                during_write += 1;
                break;
            }
            if child.try_wait().unwrap().is_some() || Instant::now() > deadline {
                break;
            }
        }
        let _ = child.kill();
        let _ = child.wait();
        for (name, bytes) in &old {
            let now = std::fs::read(out.join(name)).unwrap();
            assert!(now == *bytes || Some(&now) == new.get(name), "{name} is neither version after a kill during the write");
        }
        for e in std::fs::read_dir(&out).unwrap().flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            assert!(old.contains_key(&name) || name.starts_with(".umbrac-"), "stray file {name}");
        }
        for (name, bytes) in &old {
            std::fs::write(out.join(name), bytes).unwrap();
        }
    }
    let leftovers = std::fs::read_dir(&out).unwrap().flatten().filter(|e| e.file_name().to_string_lossy().starts_with(".umbrac-")).count();
    eprintln!("{during_write} runs killed during the write phase, {leftovers} temporaries left behind");
    assert!(killed > 0, "no run was killed ({finished} finished)");
    eprintln!("{killed} runs killed ({mixed} between two renames), {finished} finished; full compile {full:?}");

    // A full run afterwards: exactly the new outputs, no temporaries.
    let o = umbrac(&["compile", "big.das", "-o", "out"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let now: BTreeMap<String, Vec<u8>> = snapshot(&out).into_iter().map(|(p, b)| (p.file_name().unwrap().to_string_lossy().into_owned(), b)).collect();
    assert_eq!(now, new);
}

/// SIGKILL at many instants of the write phase (from the moment the first
/// temporary or the commit record appears, then a little later each
/// time) into a directory
/// holding the old version of every output: what is on disk is the old
/// set or the new one, or the new one committed (`.umbrac-commit` present)
/// and finished by whoever next takes the directory's lock, never a mix.
/// Without the commit record, 5 of 40 such kills left new GLSL beside old
/// WGSL and SPIR-V.
#[test]
fn a_kill_never_leaves_a_mixed_set() {
    use std::time::{Duration, Instant};
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let names = |dir: &Path| -> BTreeMap<String, Vec<u8>> {
        snapshot(dir).into_iter().map(|(p, b)| (p.file_name().unwrap().to_string_lossy().into_owned(), b)).collect()
    };
    let version = |salt: &str, dir: &str| {
        std::fs::write(d.path().join("big.das"), big_program(40, salt)).unwrap();
        let o = umbrac(&["compile", "big.das", "-o", dir], d.path());
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        names(&d.path().join(dir))
    };
    let old = version("0.25", "old");
    let new = version("0.75", "new");
    assert_eq!(old.keys().collect::<Vec<_>>(), new.keys().collect::<Vec<_>>());
    // The outputs that tell the versions apart (the fragment stage's do not).
    let differing: Vec<&String> = old.keys().filter(|k| old[*k] != new[*k]).collect();
    assert!(differing.len() >= 4, "{differing:?}");
    let record = out.join(umbrac::output::journal::RECORD);
    let (mut all_old, mut all_new, mut committed, mut finished) = (0, 0, 0, 0);
    let kills = 40;
    for k in 0..kills {
        let _ = std::fs::remove_dir_all(&out);
        std::fs::create_dir(&out).unwrap();
        for (name, bytes) in &old {
            std::fs::write(out.join(name), bytes).unwrap();
        }
        let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["compile", "big.das", "-o", "out"])
            .current_dir(d.path())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let deadline = Instant::now() + Duration::from_secs(60);
        // Half the kills aim at the first temporary, half at the commit
        // record (the renames follow it), each a little later every time.
        let (aim, step) = if k % 2 == 0 { (".umbrac-", 50) } else { (umbrac::output::journal::RECORD, 10) };
        loop {
            if std::fs::read_dir(&out).unwrap().flatten().any(|e| e.file_name().to_string_lossy().starts_with(aim)) {
                let until = Instant::now() + Duration::from_micros(step * (k / 2 % 8));
                while Instant::now() < until {}
                break;
            }
            if child.try_wait().unwrap().is_some() || Instant::now() > deadline {
                break;
            }
        }
        let _ = child.kill();
        if child.wait().unwrap().success() {
            finished += 1;
        }
        let pending = record.exists();
        let classify = || {
            let now = names(&out);
            let outputs: BTreeMap<&String, &Vec<u8>> = now.iter().filter(|(n, _)| !n.starts_with('.')).collect();
            assert_eq!(outputs.keys().copied().collect::<Vec<_>>(), old.keys().collect::<Vec<_>>(), "kill {k}: the outputs present");
            assert!(outputs.iter().all(|(n, b)| old[*n] == **b || new[*n] == **b), "kill {k}: an output of neither version");
            let olds = differing.iter().filter(|n| old[**n] == *outputs[*n]).count();
            let news = differing.iter().filter(|n| new[**n] == *outputs[*n]).count();
            (olds, news)
        };
        let (olds, news) = classify();
        if pending {
            committed += 1;
        } else {
            assert!(olds == 0 || news == 0, "kill {k}: a mixed set without a commit record: {olds} old, {news} new");
            if news == 0 { all_old += 1 } else { all_new += 1 }
        }
        // What the next run (or a reader) does first.
        umbrac::output::settle(&out).unwrap();
        assert!(!record.exists());
        let (olds, news) = classify();
        if pending {
            assert_eq!(olds, 0, "kill {k}: a committed set finished as old");
        }
        assert!(olds == 0 || news == 0, "kill {k}: a mixed set after settling: {olds} old, {news} new");
    }
    eprintln!("{kills} kills: {all_old} all old, {all_new} all new, {committed} committed and finished by the next lock holder ({finished} runs ended before the kill)");
    assert!(all_old > 0 && committed > 0, "no kill landed before the commit point, or none between it and the last rename");
}

// ---------------------------------------------------------------- error recovery

/// A declaration that fails leaves its name declared (with an error type),
/// so its uses report nothing more.
#[test]
fn a_bad_declaration_does_not_cascade_through_its_uses() {
    let uses = "    f_color = float4(x)\n".repeat(10);
    for decl in ["    let x : floot = 1.0", "    let x = undefined_thing * 2.0", "    let x = nrmalize(float3(1.0)).x", "    var x : float = true"] {
        let c = compile_source("c.das", &fs(&format!("{decl}\n{uses}")), &Options::default());
        assert_eq!(errors(&c).len(), 1, "{decl}: {:?}", errors(&c));
    }
}

/// A type error poisons only the expression; everything computed from it
/// stays quiet.
#[test]
fn a_type_error_does_not_cascade_through_what_uses_the_result() {
    let body = "    let a = float3(1.0) + true\n    let b = a * 2.0\n    let c = normalize(b) + a.xyz\n    let d = dot(c, float3(b.x))\n    f_color = float4(c, d) * a.x\n    if (d > 0.5) {\n        f_color.x = length(b - c)\n    }";
    let c = compile_source("t.das", &fs(body), &Options::default());
    assert_eq!(locs(&c), ["t.das:4:13: type mismatch: `+` cannot be applied to `float3` and `bool`"]);
}

#[test]
fn a_wrong_helper_or_constant_is_reported_once() {
    let src = format!(
        "let K : int = 1.5\nlet K2 = K * 2\ndef bad(x : float) : float {{\n    return x + undefined_thing\n}}\n{}",
        fs(&"    f_color = float4(bad(1.0) + float(K2) + float(K))\n".repeat(10))
    );
    let c = compile_source("h.das", &src, &Options::default());
    let m = locs(&c);
    assert_eq!(m.len(), 2, "{m:?}");
    assert!(m.iter().any(|l| l.starts_with("h.das:1:15: constant `K` is declared `int`")), "{m:?}");
    assert!(m.iter().any(|l| l.starts_with("h.das:4:16: unknown name `undefined_thing`")), "{m:?}");
}

#[test]
fn independent_errors_are_all_reported_and_capped() {
    // Three independent mistakes in three functions and a global.
    let src = "var @out f_color : float4\nvar @in @location = 99 a_bad : float\ndef f(x : float) : float {\n    return x + one\n}\ndef g(x : float) : float {\n    return x + true\n}\n[fragment_program]\ndef fs {\n    f_color = float4(f(1.0) + g(1.0) + two)\n}\n";
    let c = compile_source("m.das", src, &Options::default());
    let m = locs(&c);
    assert_eq!(m.len(), 4, "{m:?}");
    // 200 independent errors: 50 shown, the rest counted.
    let body: String = (0..200).map(|i| format!("    let v{i} : int = 1.0\n")).collect();
    let c = compile_source("many.das", &fs(&format!("{body}    f_color = float4(1.0)")), &Options::default());
    assert_eq!(errors(&c).len(), umbrac::Diagnostics::MAX_ERRORS);
    assert_eq!(c.suppressed_errors, 150);
    // A note about the report, not a 51st error.
    assert!(c.render_diagnostics().ends_with("note: 150 more errors not shown\n\n"), "{}", c.render_diagnostics());

    // The same through the command line, in both formats: 50 errors and
    // the note; and one error over the cap says `1 more error`.
    let d = tempfile::tempdir().unwrap();
    for (n, more) in [(200, "150 more errors not shown"), (51, "1 more error not shown")] {
        let body: String = (0..n).map(|i| format!("    let v{i} : int = 1.0\n")).collect();
        std::fs::write(d.path().join("many.das"), fs(&format!("{body}    f_color = float4(1.0)"))).unwrap();
        let o = umbrac(&["check", "many.das", "--message-format", "json"], d.path());
        assert_eq!(o.status.code(), Some(1));
        let lines: Vec<serde_json::Value> = String::from_utf8_lossy(&o.stdout).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        assert_eq!(lines.iter().filter(|l| l["severity"] == "error").count(), umbrac::Diagnostics::MAX_ERRORS);
        let last = lines.last().unwrap();
        assert_eq!((last["severity"].as_str(), last["message"].as_str()), (Some("note"), Some(more)), "{last}");
        let o = umbrac(&["check", "many.das"], d.path());
        let text = stderr(&o);
        assert_eq!(text.lines().filter(|l| l.starts_with("error")).count(), umbrac::Diagnostics::MAX_ERRORS, "{text}");
        assert!(text.contains(&format!("note: {more}")), "{text}");
    }
}

// ---------------------------------------------------------------- internal errors

/// naga rejecting IR umbrac built is an internal compiler error that names
/// the source location and carries naga's message. Reached through the
/// library: lower a real program, break its IR as a lowering bug would,
/// and validate it.
#[test]
fn naga_validation_failure_is_an_internal_error_with_a_location() {
    let src = fs("    f_color = float4(0.5)");
    let mut sources = umbrac::SourceMap::new();
    let root = sources.add("ice.das", None, src.clone(), None);
    let mut diags = umbrac::Diagnostics::new();
    let ast = umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
    let checked = umbrac::sema::check(&ast, &mut diags).expect("checks");
    let lowered = umbrac::lower::lower(&checked, umbrac::Conventions::default()).expect("lowers");
    let mut module = lowered.gpu.clone();
    for stmt in module.entry_points[0].function.body.iter_mut() {
        if let naga::Statement::Store { pointer, value } = stmt {
            std::mem::swap(pointer, value);
            break;
        }
    }
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), Default::default()).validate(&module);
    assert!(info.is_err(), "the broken module must not validate");
    // The same failure through the compiler's own validation entry point.
    let d = umbrac::lower::validate(&module, umbrac::lower::Flavor::Gpu(Default::default())).expect_err("rejected");
    assert_eq!(d.severity, Severity::Bug);
    let (_, line, col) = sources.line_col(d.span.expect("located")).unwrap();
    // naga names the stored value, `float4(0.5)`.
    assert_eq!((line, col), (4, 15), "{}", d.render(&sources));
    let text = d.render(&sources);
    assert!(text.starts_with("bug: internal compiler error: naga rejected the IR"), "{text}");
    assert!(text.contains("ice.das:4:15") && text.contains("doesn't relate to a valid destination for a store"), "{text}");
}

/// Through the CLI (debug builds carry the fault hook): exit status 3, the
/// message and location, and no output written.
#[test]
fn internal_error_exits_3_and_writes_nothing() {
    if !cfg!(debug_assertions) {
        eprintln!("skipping: the fault hook exists in debug builds only");
        return;
    }
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("ice.das"), fs("    f_color = float4(0.5)")).unwrap();
    std::fs::create_dir(d.path().join("out")).unwrap();
    std::fs::write(d.path().join("out/ice.wgsl"), "previous").unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_umbrac"))
        .args(["compile", "ice.das", "-o", "out"])
        .env("UMBRAC_TEST_FAULT", "naga-validation")
        .current_dir(d.path())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("internal compiler error: naga rejected the IR built for the WGSL/SPIR-V targets"), "{e}");
    assert!(e.contains("ice.das:4:15") && e.contains("no output was written"), "{e}");
    assert_eq!(snapshot(&d.path().join("out")).len(), 1);
    assert_eq!(std::fs::read_to_string(d.path().join("out/ice.wgsl")).unwrap(), "previous");
    // JSON says "bug".
    let o = Command::new(env!("CARGO_BIN_EXE_umbrac"))
        .args(["check", "ice.das", "--message-format", "json"])
        .env("UMBRAC_TEST_FAULT", "naga-validation")
        .current_dir(d.path())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(3));
    let v: serde_json::Value = serde_json::from_str(String::from_utf8_lossy(&o.stdout).lines().next().unwrap()).unwrap();
    assert_eq!(v["severity"], "bug");
    assert_eq!(v["location"]["line"], 4);
}

/// A `return` at the bottom of nested `if`s: whether every path returns
/// was asked twice per level (depth 26: 3 s, 40: never). Linear now: 40
/// and 100 levels, constant and non-constant conditions, each in well
/// under a second even unoptimised (2^40 steps would never end). (GLSL and
/// SPIR-V: WGSL takes at most 62 nested `if`s.)
#[test]
fn returns_under_nested_ifs_take_linear_time() {
    let opts = Options { targets: vec![umbrac::Target::Glsl330, umbrac::Target::Spirv], ..Options::default() };
    for depth in [40, 100] {
        for cond in ["true", "x > 0.0"] {
            let body = format!("{}return x\n{}", format!("if ({cond}) {{\n").repeat(depth), "} else {\nreturn 1.0\n}\n".repeat(depth));
            let src = format!("var @uniform u : float\nvar @out f_color : float4\ndef h(x : float) : float {{\n{body}}}\n[fragment_program]\ndef fs {{\n    f_color = float4(h(u))\n}}\n");
            let start = std::time::Instant::now();
            let c = compile_source("deep_return.das", &src, &opts);
            let took = start.elapsed();
            assert!(!c.has_errors(), "{depth} `if ({cond})`: {}", c.render_diagnostics());
            assert!(took < std::time::Duration::from_secs(3), "{depth} nested `if ({cond})` took {took:?}");
            // Without `else`: only a constant-true condition returns on every path.
            let body = format!("{}return x\n{}", format!("if ({cond}) {{\n").repeat(depth), "}\n".repeat(depth));
            let src = format!("var @uniform u : float\nvar @out f_color : float4\ndef h(x : float) : float {{\n{body}}}\n[fragment_program]\ndef fs {{\n    f_color = float4(h(u))\n}}\n");
            let start = std::time::Instant::now();
            let c = compile_source("deep_return.das", &src, &opts);
            let took = start.elapsed();
            assert_eq!(c.has_errors(), cond != "true", "{depth} `if ({cond})` without else: {}", c.render_diagnostics());
            assert!(took < std::time::Duration::from_secs(3), "{depth} nested `if ({cond})` without else took {took:?}");
        }
    }
}

/// An entry point annotation written over several lines (`[`,
/// `fragment_program`, `]`) was not seen, and the entry point was silently
/// left out; a stray character between the annotation and `def` is a
/// located error (tests/bad_inputs/items_annotation_then_*.das).
#[test]
fn annotations_over_several_lines_name_entry_points() {
    let src = "var @out f_color : float4\nvar @in a : float4\n[\n    vertex_program\n]\ndef vs {\n    gl_Position = a\n}\n[\nfragment_program(\n    name = \"shade\"\n)\n]\ndef fs {\n    f_color = float4(1.0)\n}\n";
    let c = compile_source("multiline.das", src, &Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    let names: Vec<&str> = c.result.as_ref().unwrap().reflection.entry_points.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["vs", "shade"]);
}
