//! The WebGL2 consumer: the compiler's GLSL ES 3.00 output in a real
//! browser. A static page (`web/index.html`, `web/consumer.js`) loads the
//! emitted `.300es.*` files and the reflection manifest, binds everything by
//! the manifest's names and draws the scene with WebGL2 calls; Debian's
//! headless `chromium`, driven by `playwright-core` (`web/drive.mjs`),
//! opens it from a tiny static server on 127.0.0.1 and hands back what the
//! canvas holds.
//!
//! The host values stay in one place: this module writes the frame's
//! uniform values (by the scene's value names), meshes and sizes as
//! `scene.json` from [`scene`]; the page does no math of its own.

use std::io::{BufRead, BufReader, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use image::RgbaImage;
use serde_json::{json, Value};

use super::glsl_set::GlslSet;
use super::scene::{self, Frame, FrameParams, View};
use crate::Target;

/// How to install what the WebGL2 consumer needs.
pub const INSTALL_HINT: &str =
    "on Debian/Ubuntu: `apt-get install chromium nodejs npm`, then `npm ci --prefix web` (playwright-core)";

/// The tools the WebGL2 consumer runs: node, the driver script, chromium.
#[derive(Clone, Debug)]
pub struct WebGl {
    pub node: PathBuf,
    pub chromium: PathBuf,
    /// The repository's `web/` directory.
    pub web_dir: PathBuf,
    /// `node --version`.
    pub node_version: String,
}

/// What a WebGL2 render produced.
#[derive(Clone, Debug)]
pub struct WebGlFrame {
    pub image: RgbaImage,
    /// WebGL's renderer string (the unmasked one where the browser gives it).
    pub renderer: String,
    pub browser: String,
}

/// The page's `web/` directory: `$UMBRAC_WEB_DIR`, or the one in this
/// source tree.
pub fn web_dir() -> PathBuf {
    match std::env::var_os("UMBRAC_WEB_DIR") {
        Some(d) => PathBuf::from(d),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("web"),
    }
}

impl WebGl {
    /// Finds node, chromium and playwright-core, or says which is missing.
    pub fn find() -> Result<WebGl, String> {
        let web_dir = web_dir();
        let chromium = std::env::var_os("UMBRAC_CHROMIUM").map_or_else(|| PathBuf::from("/usr/bin/chromium"), PathBuf::from);
        let mut missing = Vec::new();
        let node_version = match Command::new("node").arg("--version").output() {
            Ok(o) if o.status.success() => String::from_utf8_lossy(&o.stdout).trim().to_string(),
            _ => {
                missing.push("`node` is not on PATH".to_string());
                String::new()
            }
        };
        if !chromium.is_file() {
            missing.push(format!("no browser at {}", chromium.display()));
        }
        if !web_dir.join("index.html").is_file() || !web_dir.join("drive.mjs").is_file() {
            missing.push(format!("the page is not in {}", web_dir.display()));
        } else if !web_dir.join("node_modules/playwright-core/package.json").is_file() {
            missing.push(format!("playwright-core is not installed in {}/node_modules", web_dir.display()));
        }
        if missing.is_empty() {
            Ok(WebGl { node: PathBuf::from("node"), chromium, web_dir, node_version })
        } else {
            Err(missing.join("; "))
        }
    }

    /// Renders one frame of an ES 3.00 program in chromium. Compile and
    /// link failures come back as the browser's info log.
    pub fn render(&self, set: &GlslSet, params: &FrameParams) -> Result<WebGlFrame, String> {
        if set.target != Target::Gles300 {
            return Err(format!("{}: WebGL2 runs GLSL ES 3.00, not {}", set.label, set.target.name()));
        }
        if params.view == View::ShadowMap {
            return Err("--view shadow-map reads depth back, which WebGL2 cannot".into());
        }
        let data = tempfile::tempdir().map_err(|e| format!("temporary directory: {e}"))?;
        for (file, text) in &set.files {
            std::fs::write(data.path().join(file), text).map_err(|e| format!("writing {file}: {e}"))?;
        }
        let manifest = serde_json::to_string_pretty(&set.reflection).expect("the reflection serialises");
        std::fs::write(data.path().join("reflect.json"), manifest).map_err(|e| format!("writing the manifest: {e}"))?;
        let scene = scene_json(params, "reflect.json");
        std::fs::write(data.path().join("scene.json"), scene.to_string()).map_err(|e| format!("writing scene.json: {e}"))?;

        let server = Server::start(self.web_dir.clone(), data.path().to_path_buf())?;
        let url = format!("http://{}/index.html", server.addr);
        let out = data.path().join("result.json");
        let mut child = Command::new(&self.node)
            .arg(self.web_dir.join("drive.mjs"))
            .arg(&url)
            .arg(&out)
            .env("UMBRAC_CHROMIUM", &self.chromium)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("starting node: {e}"))?;
        let started = Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().map_err(|e| e.to_string())? {
                break s;
            }
            if started.elapsed() > Duration::from_secs(240) {
                let _ = child.kill();
                let _ = child.wait();
                return Err("chromium did not finish the frame in 240 s".into());
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let log = child.wait_with_output().map(|o| String::from_utf8_lossy(&o.stderr).into_owned()).unwrap_or_default();
        drop(server);
        let text = std::fs::read_to_string(&out)
            .map_err(|_| format!("the browser driver wrote no result (exit {status}):\n{}", tail(&log)))?;
        let result: Value = serde_json::from_str(&text).map_err(|e| format!("the driver's result is not JSON: {e}"))?;
        if result["ok"] != json!(true) {
            return Err(result["error"].as_str().unwrap_or("the page failed without a message").to_string());
        }
        let (w, h) = (params.width, params.height);
        let bytes = base64_decode(result["pixels"].as_str().unwrap_or(""))?;
        if bytes.len() != (w * h * 4) as usize {
            return Err(format!("the page sent {} bytes for a {w}x{h} image", bytes.len()));
        }
        // readPixels gives rows bottom first, as GL does.
        let rows: Vec<u8> = bytes.chunks_exact(w as usize * 4).rev().flatten().copied().collect();
        Ok(WebGlFrame {
            image: RgbaImage::from_raw(w, h, rows).expect("sized above"),
            renderer: result["renderer"].as_str().unwrap_or("?").to_string(),
            browser: result["browser"].as_str().unwrap_or("?").to_string(),
        })
    }
}

fn tail(log: &str) -> String {
    let lines: Vec<&str> = log.lines().collect();
    lines[lines.len().saturating_sub(20)..].join("\n")
}

/// The host side of one frame as the page reads it: sizes, GL state
/// values, meshes, the two passes' entry points and every draw's uniform
/// values by their scene names (matrices column-major).
pub fn scene_json(params: &FrameParams, manifest: &str) -> Value {
    let frame = Frame::of(params);
    let mesh = |m: scene::Mesh| {
        let vertices: Vec<f32> = m.vertices.iter().flat_map(|v| v.pos.into_iter().chain(v.normal)).collect();
        json!({ "vertices": vertices, "indices": m.indices })
    };
    let draws: Vec<Value> = frame
        .draws()
        .iter()
        .map(|d| {
            let values: serde_json::Map<String, Value> = scene::UNIFORM_NAMES
                .iter()
                .map(|name| {
                    let v = match frame.uniform(name, d).expect("the scene sets its own names") {
                        scene::UniformValue::Float(f) => json!(f),
                        scene::UniformValue::Vec3(v) => json!(v.to_array()),
                        scene::UniformValue::Mat4(m) => json!(m.to_cols_array()),
                    };
                    (name.to_string(), v)
                })
                .collect();
            let object = match d.object {
                scene::Object::Cube => "cube",
                scene::Object::Floor => "floor",
            };
            json!({ "mesh": object, "values": values })
        })
        .collect();
    let fields: serde_json::Map<String, Value> = [scene::ATTR_POS, scene::ATTR_NORMAL]
        .iter()
        .map(|n| (n.to_string(), json!({ "offset": scene::attribute_offset(n), "components": 3 })))
        .collect();
    json!({
        "manifest": manifest,
        "width": params.width,
        "height": params.height,
        "shadow_size": params.shadow_size,
        "view": params.view.name(),
        "clear": scene::CLEAR,
        "polygon_offset": { "factor": 2.0, "units": 4.0 },
        "passes": {
            "shadow": { "vertex": scene::SHADOW_VS, "fragment": scene::SHADOW_FS },
            "main": { "vertex": scene::MAIN_VS, "fragment": scene::MAIN_FS },
        },
        "vertex": { "stride": scene::VERTEX_STRIDE, "fields": fields },
        "meshes": { "cube": mesh(scene::cube_mesh()), "floor": mesh(scene::floor_mesh()) },
        "draws": draws,
    })
}

fn base64_decode(s: &str) -> Result<Vec<u8>, String> {
    let val = |c: u8| -> Option<u32> {
        Some(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        } as u32)
    };
    let bytes: Vec<u8> = s.bytes().filter(|c| !c.is_ascii_whitespace() && *c != b'=').collect();
    let mut out = Vec::with_capacity(bytes.len() * 3 / 4);
    for chunk in bytes.chunks(4) {
        let mut acc = 0u32;
        for (i, &c) in chunk.iter().enumerate() {
            acc |= val(c).ok_or("bad base64 in the page's pixels")? << (18 - 6 * i);
        }
        let n = chunk.len() * 6 / 8;
        out.extend_from_slice(&acc.to_be_bytes()[1..1 + n]);
    }
    Ok(out)
}

/// A static file server on 127.0.0.1 for one page load: `/data/...` from
/// `data`, everything else from `root`. Stops when dropped.
pub struct Server {
    pub addr: SocketAddr,
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Server {
    pub fn start(root: PathBuf, data: PathBuf) -> Result<Server, String> {
        let listener = TcpListener::bind("127.0.0.1:0").map_err(|e| format!("binding 127.0.0.1: {e}"))?;
        let addr = listener.local_addr().map_err(|e| e.to_string())?;
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            for stream in listener.incoming() {
                if flag.load(Ordering::SeqCst) {
                    break;
                }
                let Ok(stream) = stream else { continue };
                let (root, data) = (root.clone(), data.clone());
                std::thread::spawn(move || {
                    let _ = serve(stream, &root, &data);
                });
            }
        });
        Ok(Server { addr, stop, thread: Some(thread) })
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        let _ = TcpStream::connect(self.addr);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

fn serve(stream: TcpStream, root: &Path, data: &Path) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut request = String::new();
    reader.read_line(&mut request)?;
    loop {
        let mut header = String::new();
        if reader.read_line(&mut header)? == 0 || header.trim().is_empty() {
            break;
        }
    }
    let mut parts = request.split_whitespace();
    let (method, target) = (parts.next().unwrap_or(""), parts.next().unwrap_or("/"));
    let path = target.split(['?', '#']).next().unwrap_or("/");
    let path = if path == "/" { "/index.html" } else { path };
    let (base, rel) = match path.strip_prefix("/data/") {
        Some(rel) => (data, rel),
        None => (root, path.trim_start_matches('/')),
    };
    let rel = Path::new(rel);
    let safe = rel.components().all(|c| matches!(c, Component::Normal(_)));
    let body = if method == "GET" && safe { std::fs::read(base.join(rel)).ok() } else { None };
    let mut out = stream;
    match body {
        Some(body) => {
            let kind = match rel.extension().and_then(|e| e.to_str()) {
                Some("html") => "text/html; charset=utf-8",
                Some("js" | "mjs") => "text/javascript; charset=utf-8",
                Some("json") => "application/json",
                _ => "text/plain; charset=utf-8",
            };
            write!(out, "HTTP/1.1 200 OK\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n", body.len())?;
            out.write_all(&body)?;
        }
        None => {
            let msg = b"not found";
            write!(out, "HTTP/1.1 404 Not Found\r\nContent-Length: {}\r\nConnection: close\r\n\r\n", msg.len())?;
            out.write_all(msg)?;
        }
    }
    out.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_round_trip() {
        assert_eq!(base64_decode("aGVsbG8=").unwrap(), b"hello");
        assert_eq!(base64_decode("AAECAw==").unwrap(), vec![0, 1, 2, 3]);
        assert_eq!(base64_decode("").unwrap(), Vec::<u8>::new());
    }

    #[test]
    fn scene_json_has_every_value_per_draw() {
        let v = scene_json(&FrameParams::new(1.0, 8, 6), "m.json");
        assert_eq!(v["draws"].as_array().unwrap().len(), 2);
        assert_eq!(v["draws"][1]["values"]["u_is_floor"], json!(1.0));
        assert_eq!(v["draws"][0]["values"]["u_model"].as_array().unwrap().len(), 16);
        assert_eq!(v["meshes"]["cube"]["vertices"].as_array().unwrap().len(), 24 * 6);
    }
}
