//! Inputs and surroundings chosen to make the command line hang, blow up
//! or lose its output: FIFOs, devices, symlink cycles, full or closed
//! standard output, odd file names. Each runs the `umbrac` binary under a
//! time bound, so a hang fails the test instead of blocking the suite.

use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Runs `umbrac args` in `cwd`, killed after `secs`: `None` if it had to be.
fn run_bounded(args: &[&str], cwd: &Path, secs: u64, stdout: Stdio) -> Option<Output> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
        .args(args)
        .current_dir(cwd)
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("run umbrac");
    let end = Instant::now() + Duration::from_secs(secs);
    while Instant::now() < end {
        if child.try_wait().expect("wait").is_some() {
            return Some(child.wait_with_output().expect("output"));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

fn bounded(args: &[&str], cwd: &Path) -> Output {
    run_bounded(args, cwd, 60, Stdio::piped()).unwrap_or_else(|| panic!("`umbrac {}` did not finish within 60 s", args.join(" ")))
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

const PROGRAM: &str = "var @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n";

fn mkfifo(path: &Path) {
    use std::os::unix::ffi::OsStrExt;
    let c = std::ffi::CString::new(path.as_os_str().as_bytes()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0, "mkfifo {}", path.display());
}

#[test]
fn a_fifo_or_a_device_given_as_the_input_is_refused_at_once() {
    let d = tempfile::tempdir().unwrap();
    mkfifo(&d.path().join("pipe.das"));
    for (input, what) in [("pipe.das", "a FIFO"), ("/dev/zero", "a device"), ("/dev/null", "a device")] {
        for cmd in ["compile", "check", "reflect"] {
            let mut args = vec![cmd, input];
            if cmd == "compile" {
                args.extend(["-o", "out"]);
            }
            let o = bounded(&args, d.path());
            let err = text(&o.stderr);
            assert_eq!(o.status.code(), Some(1), "`umbrac {}`: {err}", args.join(" "));
            assert!(err.contains(&format!("it is {what}, not a regular file")), "`umbrac {}`: {err}", args.join(" "));
        }
    }
    assert!(!d.path().join("out").exists() || std::fs::read_dir(d.path().join("out")).unwrap().next().is_none());
}

#[test]
fn a_fifo_inside_a_directory_input_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let src = d.path().join("src");
    std::fs::create_dir(&src).unwrap();
    std::fs::write(src.join("a.das"), PROGRAM).unwrap();
    mkfifo(&src.join("x.das"));
    let o = bounded(&["compile", "src", "-o", "out"], d.path());
    let err = text(&o.stderr);
    // Which files are inputs is decided before anything is compiled
    // (`batch::programs_under`): a bad entry is a usage error.
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("x.das") && err.contains("not a regular file"), "{err}");
}

#[test]
fn a_directory_tree_with_symlink_cycles_is_walked_once() {
    let d = tempfile::tempdir().unwrap();
    let src = d.path().join("src");
    std::fs::create_dir_all(src.join("inner")).unwrap();
    std::fs::write(src.join("inner/a.das"), PROGRAM).unwrap();
    std::os::unix::fs::symlink(".", src.join("self")).unwrap();
    std::os::unix::fs::symlink("..", src.join("inner/up")).unwrap();
    let o = bounded(&["compile", "src", "-o", "out"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // Outputs mirror the tree under the input directory, once.
    assert!(d.path().join("out/inner/a.wgsl").is_file());
    let dirs: Vec<_> = std::fs::read_dir(d.path().join("out")).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(dirs, ["inner"]);
}

/// Standard output that cannot take the output: a full device, or closed.
/// Either way the output is lost, so the run fails and says so.
#[test]
fn a_failed_write_to_standard_output_is_an_error() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("p.das"), PROGRAM).unwrap();
    let full = || Stdio::from(std::fs::OpenOptions::new().write(true).open("/dev/full").expect("/dev/full"));
    let cases: [(&[&str], &str); 3] = [
        (&["compile", "p.das", "--target", "wgsl", "-o", "-"], "full"),
        (&["reflect", "p.das"], "full"),
        (&["reflect", "p.das"], "closed"),
    ];
    for (args, how) in cases {
        let out = match how {
            "full" => full(),
            _ => closed_stdout(),
        };
        let o = run_bounded(args, d.path(), 60, out).expect("finishes");
        let err = text(&o.stderr);
        assert_ne!(o.status.code(), Some(0), "`umbrac {}` with stdout {how} exited 0: {err}", args.join(" "));
        assert!(err.contains("standard output"), "`umbrac {}` with stdout {how}: {err}", args.join(" "));
    }
    // A descriptor that is not open at all (`>&-` in a shell).
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!("exec '{}' reflect p.das >&-", env!("CARGO_BIN_EXE_umbrac")))
        .current_dir(d.path())
        .output()
        .expect("sh");
    let err = text(&o.stderr);
    assert_ne!(o.status.code(), Some(0), "`umbrac reflect p.das >&-` exited 0: {err}");
    assert!(err.contains("standard output"), "{err}");
}

/// A write end whose read end is already closed: writing fails (EPIPE).
fn closed_stdout() -> Stdio {
    let mut fds = [0; 2];
    // SAFETY: `fds` has room for two descriptors.
    assert_eq!(unsafe { libc::pipe(fds.as_mut_ptr()) }, 0);
    // SAFETY: closing the read end we own.
    unsafe { libc::close(fds[0]) };
    use std::os::fd::FromRawFd;
    // SAFETY: the write end is ours and open.
    Stdio::from(unsafe { std::fs::File::from_raw_fd(fds[1]) })
}

/// A program with `n` fragment entry points (so many output files) that
/// all carry `salt`, so every output of one version differs from the other's.
fn many_entry_points(n: usize, salt: f32) -> String {
    let mut s = String::from("var @out f_color : float4\n");
    for i in 0..n {
        s.push_str(&format!("[fragment_program]\ndef fs{i} {{\n    f_color = float4({salt:?} + {i}.0)\n}}\n"));
    }
    s
}

/// Two compiles of different versions of one program into one directory at
/// the same time: the directory ends with one version's outputs, all of
/// them, never a mix (the renames happen under a lock on the directory).
#[test]
fn concurrent_compiles_into_one_directory_leave_one_version() {
    let d = tempfile::tempdir().unwrap();
    let versions = [many_entry_points(12, 0.25), many_entry_points(12, 0.75)];
    // Each version's outputs, compiled alone.
    let mut expected = Vec::new();
    for (i, v) in versions.iter().enumerate() {
        let dir = d.path().join(format!("alone{i}"));
        std::fs::create_dir(&dir).unwrap();
        std::fs::write(dir.join("p.das"), v).unwrap();
        let o = bounded(&["compile", "p.das", "-o", "out"], &dir);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let files: std::collections::BTreeMap<_, _> =
            std::fs::read_dir(dir.join("out")).unwrap().map(|e| e.unwrap()).map(|e| (e.file_name(), std::fs::read(e.path()).unwrap())).collect();
        expected.push(files);
    }
    assert_eq!(expected[0].len(), 12 * 2 + 3);
    for (i, v) in versions.iter().enumerate() {
        std::fs::write(d.path().join(format!("v{i}.das")), v).unwrap();
    }
    for round in 0..20 {
        let out = d.path().join("shared");
        // The same input name, so the outputs have the same names.
        let dirs: Vec<_> = (0..2).map(|i| d.path().join(format!("r{round}-{i}"))).collect();
        let children: Vec<_> = dirs
            .iter()
            .enumerate()
            .map(|(i, dir)| {
                std::fs::create_dir(dir).unwrap();
                std::fs::copy(d.path().join(format!("v{i}.das")), dir.join("p.das")).unwrap();
                Command::new(env!("CARGO_BIN_EXE_umbrac")).args(["compile", "p.das", "-o"]).arg(&out).current_dir(dir).stderr(Stdio::piped()).spawn().unwrap()
            })
            .collect();
        for c in children {
            let o = c.wait_with_output().unwrap();
            assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        }
        let got: std::collections::BTreeMap<_, _> = std::fs::read_dir(&out).unwrap().map(|e| e.unwrap()).map(|e| (e.file_name(), std::fs::read(e.path()).unwrap())).collect();
        assert!(got == expected[0] || got == expected[1], "round {round}: the directory holds a mix of both versions: {:?}", got.keys().collect::<Vec<_>>());
    }
}

/// A line break in the input's name ended the `//` comment bindgen wrote
/// the path into, and the rest of the name became Rust code.
#[test]
fn bindgen_output_parses_whatever_the_file_is_called() {
    let d = tempfile::tempdir().unwrap();
    let name = "evil\nfn broken() {}\n.das";
    std::fs::write(d.path().join(name), PROGRAM).unwrap();
    let o = bounded(&["bindgen", name, "--module", "evil", "--no-bytemuck", "-o", "b.rs"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let rust = std::fs::read_to_string(d.path().join("b.rs")).unwrap();
    assert!(rust.contains(r"`evil\nfn broken() {}\n.das`"), "{rust}");
    // The Rust compiler that runs this test is the judge.
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let o = Command::new(rustc).args(["--edition", "2021", "--crate-type", "lib", "--emit=metadata", "-o"]).arg(d.path().join("b.rmeta")).arg(d.path().join("b.rs")).output().expect("rustc");
    assert!(o.status.success(), "the bindings do not compile:\n{}\n{rust}", text(&o.stderr));
}

/// Outputs are named after the input, as text: a file name that is not
/// UTF-8 gave outputs named with U+FFFD instead of its bytes. It is an
/// error now, and nothing is written.
#[test]
fn a_file_name_that_is_not_utf8_is_an_error() {
    use std::os::unix::ffi::OsStrExt;
    let d = tempfile::tempdir().unwrap();
    let name = std::ffi::OsStr::from_bytes(b"bad\xff.das");
    if std::fs::write(d.path().join(name), PROGRAM).is_err() {
        eprintln!("skipping: this file system refuses non-UTF-8 names");
        return;
    }
    let o = Command::new(env!("CARGO_BIN_EXE_umbrac")).arg("compile").arg(name).args(["-o", "out"]).current_dir(d.path()).output().unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("is not UTF-8, and the outputs are named after it"), "{err}");
    assert!(!d.path().join("out").exists());
}
