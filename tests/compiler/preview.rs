//! `umbrac preview`'s server: what it serves and what it refuses
//! (docs/preview.md, "Security"). The page itself is tested in headless
//! chromium by tests/gpu/preview.rs.

use crate::support::preview::PreviewServer;

const PROGRAM: &str = "var @inout v_uv : float2\nvar @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = float4(v_uv, 0.0, 1.0)\n}\n";

fn server() -> (tempfile::TempDir, PreviewServer) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("p.das");
    std::fs::write(&file, PROGRAM).unwrap();
    // A file beside the program that no URL may reach.
    std::fs::write(dir.path().join("secret.txt"), "SECRET").unwrap();
    let s = PreviewServer::start(&file);
    (dir, s)
}

#[test]
fn it_serves_the_page_and_the_bundle() {
    let (_dir, s) = server();
    let host = s.host();
    let (status, body) = s.get("/", &host);
    assert_eq!(status, 200);
    assert!(body.contains("preview.js"), "{body}");
    for f in ["/preview.js", "/draw.js", "/controls.js", "/scene.js", "/textures.js", "/preview.css"] {
        assert_eq!(s.get(f, &host).0, 200, "{f}");
    }
    // The first compile may still be running: the bundle is there within seconds.
    let started = std::time::Instant::now();
    let bundle = loop {
        let (status, body) = s.get("/bundle.json", &host);
        if status != 503 || started.elapsed().as_secs() > 30 {
            assert_eq!(status, 200, "{body}");
            break body;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let json: serde_json::Value = serde_json::from_str(&bundle).expect("the bundle is JSON");
    assert_eq!(json["ok"], true);
    let names: Vec<&str> = json["files"].as_array().unwrap().iter().map(|f| f["name"].as_str().unwrap()).collect();
    assert!(names.iter().any(|n| n.ends_with(".300es.frag")) && names.iter().any(|n| n.ends_with(".wgsl")), "{names:?}");
}

#[test]
fn nothing_outside_the_page_and_the_bundle_is_served() {
    let (_dir, s) = server();
    let host = s.host();
    for target in [
        "/../secret.txt",
        "/%2e%2e/secret.txt",
        "/%2E%2E%2Fsecret.txt",
        "/..%2fsecret.txt",
        "/draw.js/../../secret.txt",
        "/secret.txt",
        "/p.das",
        "//etc/passwd",
        "/etc/passwd",
        "http://127.0.0.1/etc/passwd",
        "/..\\secret.txt",
        "/web/preview/draw.js",
        "/Cargo.toml",
    ] {
        let (status, body) = s.get(target, &host);
        assert!(status == 403 || status == 404, "{target}: {status}");
        assert!(!body.contains("SECRET") && !body.contains("root:") && !body.contains("[package]"), "{target}: {body}");
    }
    // Another site's name pointed at 127.0.0.1 (DNS rebinding) is refused.
    assert_eq!(s.get("/bundle.json", "evil.example").0, 403);
    assert_eq!(s.get("/", &format!("evil.example:{}", s.port)).0, 403);
}

#[test]
fn a_missing_file_is_an_error_not_a_server() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_umbrac")).args(["preview", "no/such/file.das"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/file.das"));
}

/// A folder standing for a built playground: each of its six files says
/// its own name; beside them, files no URL may reach.
fn fake_playground(dir: &std::path::Path) -> std::path::PathBuf {
    let pg = dir.join("pg");
    std::fs::create_dir_all(pg.join("pkg")).unwrap();
    for name in ["index.html", "style.css", "main.js", "worker.js", "umbrac_web_bg.wasm", "examples.json"] {
        std::fs::write(pg.join(name), format!("PLAYGROUND {name}")).unwrap();
    }
    std::fs::write(pg.join("umbrac_web.js"), "SECRET glue").unwrap();
    std::fs::write(pg.join("pkg/umbrac_web.js"), "SECRET pkg").unwrap();
    std::fs::write(pg.join("secret.txt"), "SECRET").unwrap();
    pg
}

#[test]
fn with_a_playground_it_serves_its_files_and_the_file_s_text_and_nothing_else() {
    let (dir, _) = server();
    let pg = fake_playground(dir.path());
    let s = PreviewServer::start_with(&dir.path().join("p.das"), &[std::ffi::OsStr::new("--playground"), pg.as_os_str()]);
    let host = s.host();
    assert!(s.get("/playground/", &host).1.contains("PLAYGROUND index.html"));
    for name in ["index.html", "style.css", "main.js", "worker.js", "umbrac_web_bg.wasm", "examples.json"] {
        let (status, body) = s.get(&format!("/playground/{name}"), &host);
        assert_eq!((status, body.as_str()), (200, format!("PLAYGROUND {name}").as_str()));
    }
    assert_eq!(s.get("/playground", &host).0, 301);
    let (status, live) = s.get("/playground/live.json", &host);
    assert_eq!(status, 200);
    let live: serde_json::Value = serde_json::from_str(&live).unwrap();
    assert!(live["file"].as_str().unwrap().ends_with("p.das") && live["events"] == "/events", "{live}");
    for target in [
        "/playground/secret.txt",
        "/playground/umbrac_web.js",
        "/playground/pkg/umbrac_web.js",
        "/playground/../secret.txt",
        "/playground/%2e%2e/secret.txt",
        "/playground/..%2fsecret.txt",
        "/playground/p.das",
        "/playground//etc/passwd",
        "/playground/index.html/../secret.txt",
    ] {
        let (status, body) = s.get(target, &host);
        assert!(status == 403 || status == 404, "{target}: {status}");
        assert!(!body.contains("SECRET") && !body.contains("root:"), "{target}: {body}");
    }
    assert_eq!(s.get("/playground/", &format!("evil.example:{}", s.port)).0, 403);
    // The bundle carries the program's text for the editor.
    let started = std::time::Instant::now();
    let bundle = loop {
        let (status, body) = s.get("/bundle.json", &host);
        if status != 503 || started.elapsed().as_secs() > 30 {
            break body;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let json: serde_json::Value = serde_json::from_str(&bundle).expect("the bundle is JSON");
    assert_eq!(json["source"]["text"], PROGRAM, "{json}");
    // Every default output, for the playground's panels.
    assert!(json["files"].as_array().unwrap().iter().any(|f| f["target"] == "spirv"), "{json}");
}

#[test]
fn a_folder_that_is_not_a_built_playground_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("p.das");
    std::fs::write(&file, PROGRAM).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_umbrac")).arg("preview").arg("--playground").arg(dir.path()).arg(&file).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("is not a built playground") && err.contains(&dir.path().display().to_string()), "{err}");
}

/// `--scene FILE`: the bundle carries the scene file's scene, and the
/// image files its textures name are served under /scene/NAME; nothing
/// else is: not a file beside it that it does not name, not a name that
/// leaves its directory (even one the scene names), not any without
/// `--scene`.
#[test]
fn with_a_scene_file_only_the_images_it_names_are_served() {
    let (dir, plain) = server();
    let sub = dir.path().join("scene");
    std::fs::create_dir(&sub).unwrap();
    std::fs::write(sub.join("tex.png"), "IMAGE tex").unwrap();
    std::fs::write(sub.join("other.png"), "SECRET other").unwrap();
    std::fs::write(dir.path().join("outside.png"), "SECRET outside").unwrap();
    // A link beside the scene that leads out of its directory.
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.path().join("outside.png"), sub.join("link.png")).unwrap();
    let scene = sub.join("s.toml");
    let text = "[[textures]]\nname = \"tex\"\nimage = \"tex.png\"\n\n[[textures]]\nname = \"out\"\nimage = \"../outside.png\"\n\n\
        [[textures]]\nname = \"link\"\nimage = \"link.png\"\n\n\
        [[passes]]\nname = \"main\"\nvertex = \"main_vs\"\nfragment = \"main_fs\"\ncolor = \"screen\"\nsamplers = { u_tex = { texture = \"tex\" } }\n[[passes.draws]]\nmesh = \"none\"\nvertices = 3\n";
    std::fs::write(&scene, text).unwrap();
    let s = PreviewServer::start_with(&dir.path().join("p.das"), &[std::ffi::OsStr::new("--scene"), scene.as_os_str()]);
    let host = s.host();
    let (status, body) = s.get("/scene/tex.png", &host);
    assert_eq!((status, body.as_str()), (200, "IMAGE tex"));
    for target in ["/scene/link.png", "/scene/other.png", "/scene/../outside.png", "/scene/..%2foutside.png", "/scene/%2e%2e/outside.png", "/scene/s.toml", "/scene/", "/scene//etc/passwd", "/scene/..\\outside.png"] {
        let (status, body) = s.get(target, &host);
        assert!(status == 403 || status == 404, "{target}: {status}");
        assert!(!body.contains("SECRET") && !body.contains("root:"), "{target}: {body}");
    }
    assert_eq!(plain.get("/scene/tex.png", &plain.host()).0, 404, "no scene file, no images");
    assert_eq!(s.get("/passes.js", &host).0, 200);
    let started = std::time::Instant::now();
    let json = loop {
        let (status, body) = s.get("/bundle.json", &host);
        if status == 200 {
            break serde_json::from_str::<serde_json::Value>(&body).unwrap();
        }
        assert!(started.elapsed().as_secs() < 30, "no bundle: {status}");
        std::thread::sleep(std::time::Duration::from_millis(100));
    };
    assert_eq!(json["scene"]["passes"][0]["samplers"]["u_tex"]["texture"], "tex", "the file's scene, not the inferred one: {}", json["scene"]);
}

#[test]
fn a_broken_scene_file_is_an_error_not_a_server() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("p.das");
    std::fs::write(&file, PROGRAM).unwrap();
    let scene = dir.path().join("s.toml");
    std::fs::write(&scene, "[[passes]]\nname = \"main\"\nvertex = 3\n").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_umbrac")).arg("preview").arg(&file).arg("--scene").arg(&scene).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("s.toml:3:10") && err.contains('^'), "{err}");
}
