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
    for f in ["/preview.js", "/draw.js", "/controls.js", "/preview.css"] {
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
