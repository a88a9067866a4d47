//! Compiling at scale through the CLI: variants (`--variants`), the cache,
//! depfiles (checked with ninja), byte-identical outputs across `--jobs`
//! and working directories, and `--watch`.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::support::{on_ci, repo, skip, umbrac};

const PROGRAM: &str = "var @uniform u_tint : float4
var @out f_color : float4

[fragment_program]
def tint_fs {
    var c = u_tint
#ifdef DOUBLE
    c = c * 2.0
#endif
#ifdef BROKEN
    c = undefined_name
#endif
    f_color = c * float4(SCALE)
}
";

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn files_under(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(d) = pending.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                pending.push(p);
            } else {
                out.push((p.strip_prefix(dir).unwrap().to_string_lossy().into_owned(), std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}

struct Project {
    dir: tempfile::TempDir,
}

impl Project {
    fn new() -> Project {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("tint.das"), PROGRAM).unwrap();
        Project { dir }
    }
    fn path(&self, p: &str) -> PathBuf {
        self.dir.path().join(p)
    }
    fn write(&self, p: &str, text: &str) {
        let p = self.path(p);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
    fn run(&self, args: &[&str]) -> std::process::Output {
        umbrac(args, self.dir.path())
    }
}

/// `-v`'s counts: (compiled, from the cache, same as another).
fn counts(o: &std::process::Output) -> (usize, usize, usize) {
    let e = stderr(o);
    let line = e.lines().find(|l| l.starts_with("umbrac: ") && l.contains(" jobs: ")).unwrap_or_else(|| panic!("no -v line in:\n{e}"));
    let num = |what: &str| {
        let at = line.find(what).unwrap_or_else(|| panic!("{what} in {line}"));
        line[..at].trim_end().rsplit([' ', ',']).next().unwrap().parse::<usize>().unwrap()
    };
    (num(" compiled"), num(" from the cache"), num(" same as another"))
}

#[test]
fn variants_go_to_their_directories_with_a_manifest_and_equal_sources_compile_once() {
    let p = Project::new();
    p.write("spec.toml", "[variant.bright]\ndefines = { SCALE = \"4.0\", NOTE = \"say \\\"hi\\\" \\\\ tab\\t\" }\n\n[variant.unused]\ndefines = { SCALE = \"1.0\", NOT_READ = \"\" }\n\n[axes]\nSCALE = [\"1.0\", \"2.0\"]\nDOUBLE = [false, true]\n");
    let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out", "--cache", "cache", "-v", "--target", "wgsl"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut dirs: Vec<String> = std::fs::read_dir(p.path("out")).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    dirs.sort();
    assert_eq!(dirs, ["bright", "scale_1_0", "scale_1_0__double", "scale_2_0", "scale_2_0__double", "unused", "variants.json"]);
    // `unused` preprocesses to the same text as `scale_1_0`: one compile.
    assert_eq!(counts(&o), (5, 0, 1));
    let wgsl = std::fs::read_to_string(p.path("out/scale_2_0__double/tint.wgsl")).unwrap();
    assert!(wgsl.contains("2f") || wgsl.contains("2.0"), "{wgsl}");

    let text = std::fs::read_to_string(p.path("out/variants.json")).unwrap();
    let manifest: serde_json::Value = serde_json::from_str(&text).unwrap();
    // Written by hand in serde_json's pretty layout: exactly that text.
    assert_eq!(text, serde_json::to_string_pretty(&manifest).unwrap() + "\n");
    let variants = manifest["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 6);
    let v = variants.iter().find(|v| v["name"] == "scale_2_0__double").unwrap();
    assert_eq!(v["defines"], serde_json::json!({ "SCALE": "2.0", "DOUBLE": null }));
    assert_eq!(v["dir"], "scale_2_0__double");
    for (file, hash) in v["outputs"].as_object().unwrap() {
        let bytes = std::fs::read(p.path("out/scale_2_0__double").join(file)).unwrap();
        assert_eq!(hash.as_str().unwrap(), format!("blake3:{}", umbrac::cache::Key::of_bytes(&bytes).hex()), "{file}");
    }
    let same = variants.iter().find(|v| v["name"] == "scale_1_0").unwrap();
    assert_eq!(same["same_source_as"], "unused", "the first of the two was compiled");
    assert_eq!(same["outputs"], variants.iter().find(|v| v["name"] == "unused").unwrap()["outputs"]);
}

#[test]
fn one_failing_variant_fails_the_run_names_the_variant_and_writes_nothing() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\"]\nBROKEN = [false, true]\nDOUBLE = [false, true]\n");
    for format in ["human", "json"] {
        let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out", "--no-cache", "--depfile", "out.d", "--message-format", format]);
        assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
        let text = if format == "json" { String::from_utf8_lossy(&o.stdout).into_owned() } else { stderr(&o) };
        assert!(text.contains("undefined_name"), "{text}");
        assert!(text.contains("tint.das:11:"), "{text}");
        assert!(text.contains("in variants `scale_1_0__broken` (-D SCALE=1.0 -D BROKEN), `scale_1_0__broken__double` (-D SCALE=1.0 -D BROKEN -D DOUBLE)"), "{text}");
        assert!(!text.contains("in variants `scale_1_0`,"), "only the failing variants are named:\n{text}");
        assert!(!p.path("out").exists() && !p.path("out.d").exists(), "nothing is written");
        assert_eq!(entries(p.dir.path()), ["spec.toml", "tint.das"], "nor left behind (a stage of the outputs, say)");
    }
}

/// The names in a directory, sorted, hidden ones included.
fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

#[test]
fn a_new_output_directory_is_staged_whole_and_an_existing_one_written_in_place_alike() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\", \"2.0\"]\nDOUBLE = [false, true]\n");
    // A new directory and an existing empty one (every variant staged and
    // published by a rename each), and one holding a variant's outputs
    // already (that one written in place file by file, the others staged):
    // the same files, and no stage left in any.
    std::fs::create_dir(p.path("empty")).unwrap();
    p.write("full/scale_1_0/tint.wgsl", "old");
    p.write("full/notes.txt", "mine");
    for out in ["new", "empty", "full"] {
        let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", out, "--no-cache"]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let new = files_under(&p.path("new"));
    assert_eq!(new.len(), 4 * 5 + 1);
    assert!(new.iter().any(|(n, _)| n == "scale_1_0/tint.wgsl"));
    assert_eq!(files_under(&p.path("empty")), new);
    let mut full = files_under(&p.path("full"));
    full.retain(|(n, _)| n != "notes.txt");
    assert_eq!(full, new);
    assert_eq!(entries(p.dir.path()), ["empty", "full", "new", "spec.toml", "tint.das"], "no stage is left");
    let variant_dirs = ["scale_1_0", "scale_1_0__double", "scale_2_0", "scale_2_0__double", "variants.json"];
    assert_eq!(entries(&p.path("new")), variant_dirs);
    assert_eq!(entries(&p.path("empty")), variant_dirs);
    let mut with_notes = vec!["notes.txt"];
    with_notes.extend(variant_dirs);
    assert_eq!(entries(&p.path("full")), with_notes);

    // A failing run into an existing empty directory leaves it empty.
    std::fs::create_dir(p.path("empty2")).unwrap();
    p.write("broken.toml", "[axes]\nSCALE = [\"1.0\"]\nBROKEN = [false, true]\n");
    let o = p.run(&["compile", "tint.das", "--variants", "broken.toml", "-o", "empty2", "--no-cache"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(entries(&p.path("empty2")), Vec::<String>::new());
    std::fs::remove_dir(p.path("empty2")).unwrap();
    std::fs::remove_file(p.path("broken.toml")).unwrap();

    // Two inputs with the same outputs in one variant directory: refused
    // as when writing in place, and no stage is left.
    p.write("b/tint.das", PROGRAM);
    let o = p.run(&["compile", "tint.das", "b/tint.das", "--variants", "spec.toml", "-o", "clash", "--no-cache"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("is an output of both"), "{}", stderr(&o));
    // All or nothing: the clash is found before anything is published.
    assert_eq!(entries(p.dir.path()), ["b", "empty", "full", "new", "spec.toml", "tint.das"]);
}

#[test]
fn spec_errors_point_into_the_spec() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\"]\nDOUBLE = [false, {}]\n");
    let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out"]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("spec.toml:3:18") && e.contains("a string, a number or a boolean") && e.contains('^'), "{e}");
    p.write("spec.toml", "[axes]\nA = [\"x-y\", \"x_y\"]\nSCALE = [\"1.0\"]\n");
    let e = stderr(&p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out"]));
    assert!(e.contains("two variants are named `a_x_y__scale_1_0`"), "{e}");
    // Expansion errors point into the spec too: the axes, or the variant.
    assert!(e.contains("spec.toml:1:2") && e.contains('^'), "{e}");
    p.write("spec.toml", "[variant.base]\ndefines = { A = \"1\" }\n\n[axes]\nA = [false]\n");
    let e = stderr(&p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out"]));
    assert!(e.contains("two variants are named `base`") && e.contains("spec.toml:1:10"), "{e}");
    assert!(!p.path("out").exists());
}

#[test]
fn a_warm_run_compiles_nothing_and_serves_the_same_bytes() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\", \"3.0\"]\nDOUBLE = [false, true]\n");
    let args = ["compile", "tint.das", "--variants", "spec.toml", "-o", "out", "--cache", "cache", "-v"];
    let cold = p.run(&args);
    assert!(cold.status.success(), "{}", stderr(&cold));
    assert_eq!(counts(&cold), (4, 0, 0));
    let first = files_under(&p.path("out"));
    std::fs::remove_dir_all(p.path("out")).unwrap();
    let warm = p.run(&args);
    assert_eq!(counts(&warm), (0, 4, 0));
    assert_eq!(files_under(&p.path("out")), first);

    // A comment is not a token: still a hit. A changed line is not.
    p.write("tint.das", &format!("// a comment\n{}", PROGRAM.replace("    var c", "    // another\n    var c")));
    assert_eq!(counts(&p.run(&args)), (0, 4, 0));
    p.write("tint.das", &PROGRAM.replace("c * 2.0", "c * 2.5"));
    assert_eq!(counts(&p.run(&args)), (2, 2, 0), "only the DOUBLE variants changed");
    // Targets and conventions are in the key.
    let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out2", "--cache", "cache", "-v", "--target", "wgsl"]);
    assert_eq!(counts(&o), (4, 0, 0));
    let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out2", "--cache", "cache", "-v", "--conventions", "native"]);
    assert_eq!(counts(&o), (4, 0, 0));
}

/// A module the program `require`s is part of the key: editing what a
/// shader reaches in it is a miss, and so is a depfile entry (the module
/// is a file the compile read).
#[test]
fn a_required_module_is_in_the_key_and_the_depfile() {
    let p = Project::new();
    p.write("lib/tone.das", "def tone(c : float4) : float4 {\n    return c * 0.5\n}\n");
    p.write("m.das", "require lib/tone\nvar @uniform u_tint : float4\nvar @out f_color : float4\n[fragment_program]\ndef m_fs {\n    f_color = tone(u_tint)\n}\n");
    let args = ["compile", "m.das", "-I", ".", "-o", "out", "--cache", "cache", "-v", "--depfile", "m.d"];
    let cold = p.run(&args);
    assert!(cold.status.success(), "{}", stderr(&cold));
    assert_eq!(counts(&cold), (1, 0, 0));
    assert!(std::fs::read_to_string(p.path("m.d")).unwrap().contains("lib/tone.das"), "the module is a dependency");
    // Into another directory (the same one would have nothing to do: the
    // run record), from the cache.
    let other = ["compile", "m.das", "-I", ".", "-o", "out2", "--cache", "cache", "-v", "--depfile", "m.d"];
    assert_eq!(counts(&p.run(&other)), (0, 1, 0));
    p.write("lib/tone.das", "def tone(c : float4) : float4 {\n    return c * 0.25\n}\n");
    let o = p.run(&args);
    assert_eq!(counts(&o), (1, 0, 0), "an edited module is compiled again: {}", stderr(&o));
    assert!(std::fs::read_to_string(p.path("out/m.wgsl")).unwrap().contains("0.25"));
}

#[test]
fn damaged_cache_entries_are_detected_removed_and_recompiled() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\", \"3.0\"]\n");
    let args = ["compile", "tint.das", "--variants", "spec.toml", "-o", "out", "--cache", "cache", "-v"];
    assert!(p.run(&args).status.success());
    let good = files_under(&p.path("out"));
    let entries: Vec<PathBuf> = files_under(&p.path("cache/v4")).into_iter().map(|(f, _)| p.path("cache/v4").join(f)).collect();
    assert_eq!(entries.len(), 2);
    // One truncated, one with a flipped byte in the middle of an output.
    let bytes = std::fs::read(&entries[0]).unwrap();
    std::fs::write(&entries[0], &bytes[..bytes.len() / 2]).unwrap();
    let mut bytes = std::fs::read(&entries[1]).unwrap();
    let mid = bytes.len() / 2;
    bytes[mid] ^= 1;
    std::fs::write(&entries[1], &bytes).unwrap();
    std::fs::remove_dir_all(p.path("out")).unwrap();
    let o = p.run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(counts(&o), (2, 0, 0), "neither damaged entry is served");
    assert_eq!(files_under(&p.path("out")), good);
    // Into another directory (the same one would have nothing to do).
    let other = ["compile", "tint.das", "--variants", "spec.toml", "-o", "out2", "--cache", "cache", "-v"];
    assert_eq!(counts(&p.run(&other)), (0, 2, 0), "and both are whole again");
}

#[test]
fn processes_sharing_a_cache_agree() {
    let p = Project::new();
    p.write("spec.toml", "[axes]\nSCALE = [\"1.0\", \"2.0\", \"3.0\", \"4.0\"]\nDOUBLE = [false, true]\n");
    let children: Vec<_> = (0..4)
        .map(|i| {
            Command::new(env!("CARGO_BIN_EXE_umbrac"))
                .args(["compile", "tint.das", "--variants", "spec.toml", "-o", &format!("out{i}"), "--cache", "cache"])
                .current_dir(p.dir.path())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for c in children {
        let o = c.wait_with_output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let first = files_under(&p.path("out0"));
    for i in 1..4 {
        assert_eq!(files_under(&p.path(&format!("out{i}"))), first);
    }
    // Into a new directory (out0 again would have nothing to do: the run
    // record), every variant from the cache.
    let o = p.run(&["compile", "tint.das", "--variants", "spec.toml", "-o", "out4", "--cache", "cache", "-v"]);
    assert_eq!(counts(&o), (0, 8, 0));
    assert_eq!(files_under(&p.path("out4")), first);
    let temps: Vec<String> = files_under(&p.path("cache")).into_iter().map(|(f, _)| f).filter(|f| f.contains(".tmp-")).collect();
    assert!(temps.is_empty(), "no temporaries left: {temps:?}");
}

#[test]
fn the_depfile_names_every_output_and_every_file_read() {
    let p = Project::new();
    p.write("inc/common.das", "let SCALE = 2.0\n");
    p.write("main.das", &format!("#include \"inc/common.das\"\n{PROGRAM}"));
    let o = p.run(&["compile", "main.das", "-o", "out", "--depfile", "out/main.d", "--target", "wgsl", "--no-cache"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d = std::fs::read_to_string(p.path("out/main.d")).unwrap();
    assert_eq!(d, "out/main.reflect.json \\\nout/main.wgsl: \\\n  inc/common.das \\\n  main.das\n\ninc/common.das:\n\nmain.das:\n", "{d}");
    // With variants: every variant's outputs, variants.json and the spec.
    p.write("spec.toml", "[axes]\nDOUBLE = [false, true]\n");
    let o = p.run(&["compile", "main.das", "--variants", "spec.toml", "-o", "vout", "--depfile", "v.d", "--target", "wgsl", "--no-cache"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d = std::fs::read_to_string(p.path("v.d")).unwrap();
    for must in ["vout/base/main.wgsl", "vout/double/main.reflect.json", "vout/variants.json:", "  spec.toml", "  inc/common.das"] {
        assert!(d.contains(must), "{must} in\n{d}");
    }
}

/// ninja with `deps = gcc`: touching an include rebuilds exactly the
/// programs that include it; touching nothing rebuilds nothing.
#[test]
fn ninja_rebuilds_exactly_what_an_edit_reaches() {
    if Command::new("ninja").arg("--version").output().is_err() {
        if on_ci() {
            panic!("ninja is missing (apt-get install ninja-build)");
        }
        return skip("ninja is missing (apt-get install ninja-build)");
    }
    let p = Project::new();
    p.write("inc/a.das", "let SCALE = 2.0\n");
    p.write("inc/b.das", "let SCALE = 3.0\n");
    p.write("one.das", &format!("#include \"inc/a.das\"\n{PROGRAM}"));
    p.write("two.das", &format!("#include \"inc/a.das\"\n{PROGRAM}").replace("tint_fs", "two_fs"));
    p.write("three.das", &format!("#include \"inc/b.das\"\n{PROGRAM}").replace("tint_fs", "three_fs"));
    let umbrac = env!("CARGO_BIN_EXE_umbrac");
    let mut ninja = format!(
        "rule umbrac\n  command = {umbrac} compile $in -o out/$name --target wgsl --no-cache --depfile $out.d && echo $name >> built.log\n  depfile = $out.d\n  deps = gcc\n\n"
    );
    for n in ["one", "two", "three"] {
        ninja.push_str(&format!("build out/{n}/{n}.reflect.json: umbrac {n}.das\n  name = {n}\n"));
    }
    p.write("build.ninja", &ninja);
    let build = || {
        let _ = std::fs::remove_file(p.path("built.log"));
        let o = Command::new("ninja").current_dir(p.dir.path()).output().unwrap();
        assert!(o.status.success(), "{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
        let mut built: Vec<String> = std::fs::read_to_string(p.path("built.log")).unwrap_or_default().lines().map(String::from).collect();
        built.sort();
        built
    };
    assert_eq!(build(), ["one", "three", "two"]);
    assert!(build().is_empty(), "touching nothing rebuilds nothing");
    // mtimes have a granularity; make the touch visibly newer.
    std::thread::sleep(Duration::from_millis(20));
    let bump = |f: &str| {
        std::thread::sleep(Duration::from_millis(20));
        std::fs::File::options().write(true).open(p.path(f)).unwrap().set_modified(std::time::SystemTime::now()).unwrap()
    };
    bump("inc/a.das");
    assert_eq!(build(), ["one", "two"]);
    assert!(build().is_empty());
    bump("inc/b.das");
    assert_eq!(build(), ["three"]);
    bump("two.das");
    assert_eq!(build(), ["two"]);
}

/// Every program under shaders/, and the 256 variants of
/// shaders/programs/shadow_variants.das, compiled twice: with `--jobs 1`
/// from the repository by a relative path, and with `--jobs 2` from
/// another directory by an absolute path. Every byte agrees.
#[test]
fn outputs_are_byte_identical_across_jobs_and_working_directories() {
    let root = repo();
    let t = tempfile::tempdir().unwrap();
    let a = t.path().join("a");
    let b = t.path().join("b");
    let elsewhere = t.path().join("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    // shaders/wgsl_spirv/ holds programs only those two targets accept,
    // shaders/spirv/ ones only SPIR-V accepts: the rest is compiled from a
    // copy without them, those directories apart.
    let copy = t.path().join("src");
    copy_tree(&root.join("shaders"), &copy.join("shaders"), &|p| p.file_name().is_some_and(|n| n == "wgsl_spirv" || n == "spirv"));
    let sets: [(std::path::PathBuf, &str, &[&str]); 3] = [
        (copy.clone(), "shaders", &[]),
        (root.clone(), "shaders/wgsl_spirv", &["--target", "wgsl", "--target", "spirv"]),
        (root.clone(), "shaders/spirv", &["--target", "spirv"]),
    ];
    for (base, input, targets) in &sets {
        let abs = base.join(input);
        for (inp, out, jobs, cwd) in [(input.to_string(), a.to_string_lossy().into_owned(), "1", base.clone()), (abs.to_string_lossy().into_owned(), "../b".to_string(), "2", elsewhere.clone())] {
            let mut args: Vec<&str> = vec!["compile", &inp];
            args.extend(targets.iter());
            args.extend(["-o", &out, "--jobs", jobs, "--no-cache"]);
            let o = umbrac(&args, &cwd);
            assert!(o.status.success(), "{}", stderr(&o));
        }
    }
    let (fa, fb) = (files_under(&a), files_under(&b));
    assert!(fa.len() > 100, "{} files", fa.len());
    assert_eq!(fa.iter().map(|f| &f.0).collect::<Vec<_>>(), fb.iter().map(|f| &f.0).collect::<Vec<_>>());
    for ((name, x), (_, y)) in fa.iter().zip(&fb) {
        assert!(x == y, "{name} differs between the runs");
        let text = String::from_utf8_lossy(x);
        assert!(!text.contains(root.to_str().unwrap()) && !text.contains(t.path().to_str().unwrap()), "{name} holds an absolute path");
    }
    let manifest = std::fs::read_to_string(a.join("features/preprocessor.reflect.json")).unwrap();
    assert!(a.join("half.wgsl").is_file(), "the wgsl/spirv-only programs");
    assert!(manifest.contains("\"source\": \"features/preprocessor.das\""), "{manifest}");

    let prog = "shaders/programs/shadow_variants.das";
    let spec = "shaders/programs/shadow_variants.toml";
    let va = t.path().join("va");
    let o = umbrac(&["compile", prog, "--variants", spec, "-o", va.to_str().unwrap(), "--jobs", "1", "--no-cache"], &root);
    assert!(o.status.success(), "{}", stderr(&o));
    let (abs_prog, abs_spec) = (root.join(prog), root.join(spec));
    let o = umbrac(&["compile", abs_prog.to_str().unwrap(), "--variants", abs_spec.to_str().unwrap(), "-o", "../vb", "--jobs", "2", "--no-cache"], &elsewhere);
    assert!(o.status.success(), "{}", stderr(&o));
    let (fa, fb) = (files_under(&va), files_under(&t.path().join("vb")));
    assert_eq!(fa.len(), 256 * 7 + 1, "7 outputs per variant, and variants.json");
    assert!(fa == fb, "the variant trees differ");
}

/// `--watch`: an edit recompiles; a broken edit prints its error and keeps
/// the last good outputs; fixing it writes new ones.
#[test]
fn watch_recompiles_on_change_and_keeps_the_last_good_outputs() {
    let p = Project::new();
    p.write("inc/k.das", "let SCALE = 2.0\n");
    p.write("w.das", &format!("#include \"inc/k.das\"\n{PROGRAM}"));
    let log = std::fs::File::create(p.path("watch.log")).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
        .args(["compile", "--watch", "w.das", "-o", "out", "--target", "wgsl", "--no-cache"])
        .current_dir(p.dir.path())
        .stderr(log)
        .spawn()
        .unwrap();
    let wgsl = p.path("out/w.wgsl");
    let wait_for = |what: &str, cond: &dyn Fn() -> bool| {
        let deadline = Instant::now() + Duration::from_secs(60);
        while !cond() {
            assert!(Instant::now() < deadline, "timed out waiting for {what}; log:\n{}", std::fs::read_to_string(p.path("watch.log")).unwrap_or_default());
            std::thread::sleep(Duration::from_millis(20));
        }
    };
    let read = || std::fs::read_to_string(&wgsl).unwrap_or_default();
    let log = || std::fs::read_to_string(p.path("watch.log")).unwrap_or_default();
    wait_for("the first compile", &|| log().contains("[watch] ok"));
    assert!(read().contains("2f") || read().contains("2.0"), "{}", read());
    // The include changes (written the way editors save: a rename).
    p.write("inc/k.tmp", "let SCALE = 7.0\n");
    std::fs::rename(p.path("inc/k.tmp"), p.path("inc/k.das")).unwrap();
    wait_for("the recompile after the include changed", &|| read().contains("7f") || read().contains("7.0"));
    let good = read();
    p.write("w.das", &format!("#include \"inc/k.das\"\n{}", PROGRAM.replace("var c = u_tint", "var c = nope")));
    wait_for("the error", &|| log().contains("nope"));
    assert!(log().contains("w.das:7:"), "{}", log());
    assert_eq!(read(), good, "the last good output stays");
    p.write("w.das", &format!("#include \"inc/k.das\"\n{}", PROGRAM.replace("u_tint", "u_tint2")));
    wait_for("the fixed compile", &|| read().contains("u_tint2"));
    let _ = child.kill();
    let _ = child.wait();
}

/// Copies the files under `from` to `to`, leaving out what `skip` says.
fn copy_tree(from: &std::path::Path, to: &std::path::Path, skip: &dyn Fn(&std::path::Path) -> bool) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        if skip(&p) {
            continue;
        }
        let dest = to.join(p.file_name().unwrap());
        if p.is_dir() {
            copy_tree(&p, &dest, skip);
        } else {
            std::fs::copy(&p, &dest).unwrap();
        }
    }
}


/// The `-v` line says the run had nothing to do (src/rerun.rs).
fn did_nothing(o: &std::process::Output) -> bool {
    assert!(o.status.success(), "{}", stderr(o));
    stderr(o).contains("nothing to do")
}

fn mtimes(dir: &Path) -> Vec<(String, std::time::SystemTime)> {
    files_under(dir).into_iter().map(|(f, _)| (f.clone(), std::fs::metadata(dir.join(&f)).unwrap().modified().unwrap())).collect()
}

#[test]
fn a_rerun_that_would_change_nothing_compiles_nothing_and_anything_changed_makes_it_run() {
    let p = Project::new();
    p.write("inc/scale.das", "let SCALE = 2.0\n");
    p.write("main.das", &format!("#include \"scale.das\"\n{}", PROGRAM.replace("float4(SCALE)", "float4(SCALE_OF)")));
    p.write("spec.toml", "[axes]\nSCALE_OF = [\"SCALE\", \"1.0\"]\n");
    let args = ["compile", "main.das", "--variants", "spec.toml", "-I", "inc", "-o", "out", "--cache", "cache", "--depfile", "out.d", "-v", "--target", "wgsl"];
    assert!(!did_nothing(&p.run(&args)), "cold");
    // The first rerun reads every output back (no stamp vouches for it
    // yet), finds it as recorded and stamps it: nothing else to do. Stamps
    // are trusted once taken a margin after the file last changed.
    assert!(did_nothing(&p.run(&args)), "the first rerun reads the outputs and has nothing else to do");
    // Stamps taken less than a margin after the writes are not trusted, so
    // one more run may read the outputs again; after that, none.
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    let _ = p.run(&args);
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    let before = files_under(&p.path("out"));
    let times = mtimes(&p.path("out"));
    std::fs::remove_file(p.path("out.d")).unwrap();
    assert!(did_nothing(&p.run(&args)), "{}", stderr(&p.run(&args)));
    assert_eq!(files_under(&p.path("out")), before);
    assert_eq!(mtimes(&p.path("out")), times, "nothing touched");
    assert!(std::fs::read_to_string(p.path("out.d")).unwrap().contains("inc/scale.das"), "the depfile is written again (ninja deletes it)");

    // An output changed by hand, keeping its size: put back.
    let wgsl = p.path("out/scale_of_scale/main.wgsl");
    let text = std::fs::read_to_string(&wgsl).unwrap();
    std::fs::write(&wgsl, text.replacen('f', "g", 1)).unwrap();
    assert!(!did_nothing(&p.run(&args)));
    assert_eq!(std::fs::read_to_string(&wgsl).unwrap(), text);

    // A file appearing where the include looked first (beside main.das)
    // changes what is read.
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    assert!(did_nothing(&p.run(&args)), "the repaired output is read, found as recorded and stamped");
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    assert!(did_nothing(&p.run(&args)));
    p.write("scale.das", "let SCALE = 5.0\n");
    assert!(!did_nothing(&p.run(&args)));
    let now = std::fs::read_to_string(&wgsl).unwrap();
    assert!(now.contains('5') && now != text, "{now}");

    // An edit of an input that changes no token: compiled from the cache,
    // the outputs touched so make sees them newer than the input.
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    let spec = std::fs::read_to_string(p.path("spec.toml")).unwrap();
    p.write("spec.toml", &format!("# a comment\n{spec}"));
    let o = p.run(&args);
    assert!(!did_nothing(&o));
    let spec_time = std::fs::metadata(p.path("spec.toml")).unwrap().modified().unwrap();
    assert!(mtimes(&p.path("out")).iter().all(|(_, t)| *t >= spec_time), "outputs newer than the spec");

    // The spec's variants are not in the record's key, only its bytes:
    // a spec with one more variant is expanded and compiled, and a broken
    // one is an error, not "nothing to do".
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    let _ = p.run(&args);
    std::thread::sleep(umbrac::output::stamps::MARGIN * 3);
    assert!(did_nothing(&p.run(&args)));
    p.write("spec.toml", "[axes]\nSCALE_OF = [\"SCALE\", \"1.0\", \"3.0\"]\n");
    assert!(!did_nothing(&p.run(&args)));
    assert!(p.path("out/scale_of_3_0/main.wgsl").is_file());
    p.write("spec.toml", "[axes]\nSCALE_OF = 7\n");
    let o = p.run(&args);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("spec.toml:2:"), "{}", stderr(&o));
}

#[cfg(unix)]
#[test]
fn outputs_are_readable_by_all_whatever_the_umask() {
    use std::os::unix::fs::PermissionsExt;
    let p = Project::new();
    for (umask, dir) in [("077", "private"), ("022", "usual")] {
        let cmd = format!("umask {umask} && exec \"{}\" compile tint.das -D SCALE=1.0 -o {dir} --no-cache --target wgsl", env!("CARGO_BIN_EXE_umbrac"));
        let o = Command::new("sh").arg("-c").arg(&cmd).current_dir(p.dir.path()).output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        let mode = std::fs::metadata(p.path(dir).join("tint.wgsl")).unwrap().permissions().mode();
        assert_eq!(mode & 0o777, 0o644, "umask {umask}");
    }
}

/// A depfile that cannot be written fails the run before any output
/// changes; a file name with a line break (which make cannot read back)
/// is refused before anything is written (issue 37: the outputs were
/// already new, and the depfile malformed).
#[test]
fn a_depfile_that_cannot_be_written_changes_nothing() {
    let p = Project::new();
    p.write("main.das", &format!("let SCALE = 2.0\n{PROGRAM}"));
    let o = p.run(&["compile", "main.das", "-o", "out", "--target", "wgsl", "--no-cache"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let before = std::fs::read(p.path("out/main.wgsl")).unwrap();
    p.write("main.das", &format!("let SCALE = 3.0\n{PROGRAM}"));
    p.write("blocker", "a file, not a directory\n");
    let o = p.run(&["compile", "main.das", "-o", "out", "--target", "wgsl", "--no-cache", "--depfile", "blocker/main.d"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("cannot write the depfile `blocker/main.d`"), "{}", stderr(&o));
    assert_eq!(std::fs::read(p.path("out/main.wgsl")).unwrap(), before, "the outputs are unchanged");
    // A failing compile leaves no temporary and no directory made for the depfile.
    p.write("bad.das", "options gen2\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = nope\n}\n");
    let o = p.run(&["compile", "bad.das", "-o", "bout", "--no-cache", "--depfile", "deps/sub/bad.d"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(!p.path("deps").exists() && !p.path("bout").exists());
    // A line break in a file name.
    p.write("new\nline.das", &format!("let SCALE = 2.0\n{PROGRAM}"));
    let o = p.run(&["compile", "new\nline.das", "-o", "nl", "--target", "wgsl", "--no-cache", "--depfile", "nl.d"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("has a line break in its name, which a depfile cannot hold"), "{}", stderr(&o));
    assert!(!p.path("nl").exists() && !p.path("nl.d").exists());
    // Without a depfile the same name compiles.
    let o = p.run(&["compile", "new\nline.das", "-o", "nl", "--target", "wgsl", "--no-cache"]);
    assert!(o.status.success(), "{}", stderr(&o));
}
