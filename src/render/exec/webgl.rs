//! The WebGL2 executor: the compiler's GLSL ES 3.00 output in a real
//! browser. The frame plan, with what [`bind::gl`] resolves from the
//! manifest (block names and binding points, every draw's block bytes and
//! uniform values, sampler units, attribute locations), goes to a static
//! page (`web/index.html`, `web/consumer.js`) as `plan.json`; the page
//! makes the targets, compiles and links the `.300es.*` files, checks the
//! linked programs against what it is told to bind, draws and hands back
//! the read-back target. Debian's headless `chromium`, driven by
//! `playwright-core` (`web/drive.mjs`), opens the page from a small static
//! server on 127.0.0.1. The page reads no manifest and does no math.

use std::io::{BufRead, BufReader, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use image::RgbaImage;
use serde_json::{json, Value};

use crate::render::bind::{self, gl::UniformCall};
use crate::render::consumer::Consumer;
use crate::render::plan::{Cull, FramePlan, Geometry, Mesh};
use crate::render::program::{ShaderCode, ShaderSet};
use crate::Target;

use super::{ExecError, Executor, Readback};

/// How to install what the WebGL2 consumer needs.
pub const INSTALL_HINT: &str = "apt-get install chromium nodejs npm, then `npm ci --prefix web` (playwright-core)";

/// The tools the WebGL2 consumer runs: node, the driver script, chromium.
#[derive(Debug)]
pub struct WebGl {
    pub node: PathBuf,
    pub chromium: PathBuf,
    /// The repository's `web/` directory.
    pub web_dir: PathBuf,
    /// `node --version`.
    pub node_version: String,
    /// What the last frame ran on: WebGL's renderer string and the browser.
    last_device: Mutex<String>,
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
    pub fn find() -> Result<WebGl, ExecError> {
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
            Ok(WebGl { node: PathBuf::from("node"), chromium, web_dir, node_version, last_device: Mutex::default() })
        } else {
            Err(ExecError::Unavailable { consumer: Consumer::WebGl2, why: missing.join("; "), install: INSTALL_HINT.into() })
        }
    }

    /// Runs the page on each of `data` (each holds a `plan.json` and its
    /// sources), one after the other in one browser, and returns what each
    /// reported.
    fn drive(&self, data: &[&Path]) -> Vec<Result<Value, ExecError>> {
        let mut servers = Vec::new();
        for d in data {
            match Server::start(self.web_dir.clone(), d.to_path_buf()) {
                Ok(s) => servers.push(s),
                Err(e) => return data.iter().map(|_| Err(ExecError::Api(e.clone()))).collect(),
            }
        }
        let mut cmd = Command::new(&self.node);
        cmd.arg(self.web_dir.join("drive.mjs"));
        for (server, d) in servers.iter().zip(data) {
            cmd.arg(format!("http://{}/index.html", server.addr)).arg(d.join("result.json"));
        }
        let child = cmd.env("UMBRAC_CHROMIUM", &self.chromium).stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn();
        let mut child = match child {
            Ok(c) => c,
            Err(e) => return data.iter().map(|_| Err(ExecError::Api(format!("starting node: {e}")))).collect(),
        };
        let started = Instant::now();
        let limit = Duration::from_secs(240 + 60 * data.len().saturating_sub(1) as u64);
        let status = loop {
            match child.try_wait() {
                Ok(Some(s)) => break s,
                Ok(None) => {}
                Err(e) => return data.iter().map(|_| Err(ExecError::Api(e.to_string()))).collect(),
            }
            if started.elapsed() > limit {
                let _ = child.kill();
                let _ = child.wait();
                return data.iter().map(|_| Err(ExecError::Api(format!("chromium did not finish the frames in {} s", limit.as_secs())))).collect();
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let log = child.wait_with_output().map(|o| String::from_utf8_lossy(&o.stderr).into_owned()).unwrap_or_default();
        drop(servers);
        data.iter()
            .map(|d| {
                let text = std::fs::read_to_string(d.join("result.json"))
                    .map_err(|_| ExecError::Api(format!("the browser driver wrote no result (exit {status}):\n{}", tail(&log))))?;
                serde_json::from_str(&text).map_err(|e| ExecError::Api(format!("the driver's result is not JSON: {e}")))
            })
            .collect()
    }

    /// Runs several frames in one browser (a browser start is most of a
    /// small frame's time): each plan with its program, as [`Executor::run`]
    /// would, one result each.
    pub fn run_batch(&self, jobs: &[(&ShaderSet, &FramePlan)]) -> Vec<Result<Readback, ExecError>> {
        let written: Vec<Result<(tempfile::TempDir, Value), ExecError>> = jobs.iter().map(|(set, plan)| write_job(set, plan)).collect();
        let dirs: Vec<&Path> = written.iter().filter_map(|w| w.as_ref().ok().map(|(d, _)| d.path())).collect();
        let mut results = self.drive(&dirs).into_iter();
        written
            .iter()
            .zip(jobs)
            .map(|(w, (_, plan))| {
                let (_, doc) = w.as_ref().map_err(Clone::clone)?;
                let result = results.next().expect("one result per page")?;
                self.readback(doc, &result, plan)
            })
            .collect()
    }

    /// The image (or words) a page reported for `plan`.
    fn readback(&self, doc: &Value, result: &Value, plan: &FramePlan) -> Result<Readback, ExecError> {
        if result["ok"] != json!(true) {
            return Err(page_error(result));
        }
        *self.last_device.lock().unwrap_or_else(|p| p.into_inner()) =
            format!("{} (chromium {})", result["renderer"].as_str().unwrap_or("?"), result["browser"].as_str().unwrap_or("?"));
        let read = plan.target(plan.readback);
        let (w, h) = (read.width, read.height);
        let bytes = base64_decode(result["pixels"].as_str().unwrap_or("")).map_err(ExecError::Api)?;
        let texel = if read.format == crate::render::plan::Format::Rgba32Uint { 16 } else { 4 };
        if bytes.len() != (w * h) as usize * texel {
            return Err(ExecError::Api(format!("the page sent {} bytes for a {w}x{h} target", bytes.len())));
        }
        // readPixels gives rows bottom first, as GL does: GL-dialect pictures are top row first.
        let top_first = doc["top_first"] == json!(true);
        let rows: Vec<u8> = if top_first { bytes } else { bytes.chunks_exact(w as usize * texel).rev().flatten().copied().collect() };
        Ok(if texel == 16 {
            Readback::Words { width: w, height: h, words: bytemuck::cast_slice(&rows).to_vec() }
        } else {
            Readback::Rgba8(RgbaImage::from_raw(w, h, rows).expect("sized above"))
        })
    }
}

/// A directory holding `plan.json` and the sources of one frame, and the plan's JSON.
fn write_job(set: &ShaderSet, plan: &FramePlan) -> Result<(tempfile::TempDir, Value), ExecError> {
    super::check_sizes(plan, 16384)?;
    if plan.target(plan.readback).format.is_depth() {
        return Err(ExecError::Unsupported("WebGL2 cannot read depth back: no --view shadow-map on webgl2".into()));
    }
    let (doc, files) = plan_json(set, plan)?;
    let data = tempfile::tempdir().map_err(|e| ExecError::Api(format!("temporary directory: {e}")))?;
    for (file, text) in &files {
        std::fs::write(data.path().join(file), text).map_err(|e| ExecError::Api(format!("writing {file}: {e}")))?;
    }
    std::fs::write(data.path().join("plan.json"), doc.to_string()).map_err(|e| ExecError::Api(format!("writing plan.json: {e}")))?;
    Ok((data, doc))
}

fn tail(log: &str) -> String {
    let lines: Vec<&str> = log.lines().collect();
    lines[lines.len().saturating_sub(20)..].join("\n")
}

/// A program ready for the page: its sources and the plan it was fitted to.
pub struct WebGlProgram {
    set: ShaderSet,
}

/// The page's error report as an [`ExecError`].
fn page_error(result: &Value) -> ExecError {
    let s = |k: &str| result[k].as_str().unwrap_or_default().to_string();
    let message = result["error"].as_str().unwrap_or("the page failed without a message").to_string();
    match result["kind"].as_str() {
        Some("compile") => ExecError::Compile { file: s("file"), log: s("log") },
        Some("link") => ExecError::Link { pass: s("pass"), log: s("log") },
        Some("program") => ExecError::Program(message),
        _ => ExecError::Api(message),
    }
}

fn mesh_json(m: &Mesh) -> Value {
    let floats: Vec<f32> = bytemuck::cast_slice(&m.vertices).to_vec();
    let instances = m.instances.map(|i| json!({ "base": i.base, "stride": i.stride, "count": i.count }));
    json!({ "vertices": floats, "indices": m.indices, "stride": m.stride, "instances": instances, "points": m.points })
}

/// The plan as the page runs it, with everything bound resolved from the
/// manifest, and the source files it needs (file name, text).
pub fn plan_json(set: &ShaderSet, plan: &FramePlan) -> Result<(Value, Vec<(String, String)>), ExecError> {
    let r = set.manifest().map_err(ExecError::Program)?;
    let fit = bind::fit(&set.label, r, plan)?;
    let mut files = Vec::new();
    let mut meshes = serde_json::Map::new();
    let mut programs = Vec::new();
    let mut passes = Vec::new();
    for (pass, pf) in plan.passes.iter().zip(&fit.passes) {
        let program = bind::gl::program(r, pf);
        let (vs, vs_text) = set.glsl(&pass.vertex).map_err(ExecError::Program)?;
        let (fs, fs_text) = set.glsl_fragment(pass.fragment.as_deref(), vs_text).map_err(ExecError::Program)?;
        for (f, t) in [(vs, vs_text), (fs.as_str(), fs_text.as_str())] {
            if !files.iter().any(|(name, _)| name == f) {
                files.push((f.to_string(), t.to_string()));
            }
        }
        programs.push(json!({
            "pass": pass.name,
            "vertex": vs,
            "fragment": fs,
            "blocks": program.blocks.iter().map(|b| json!({ "name": b.glsl_name, "point": b.point, "size": b.layout.size })).collect::<Vec<_>>(),
            "samplers": program.samplers.iter().map(|s| json!({ "name": s.glsl_name, "unit": s.unit })).collect::<Vec<_>>(),
            "attributes": program.attributes.iter().map(|a| json!({ "name": a.glsl_name, "location": a.location, "offset": a.field.offset, "components": a.field.format.components(), "per_instance": a.field.per_instance })).collect::<Vec<_>>(),
            "uniforms": program.uniforms.iter().map(|u| &u.glsl_name).collect::<Vec<_>>(),
        }));
        let textures: Vec<Value> = bind::gl::textures(&program, pass)
            .map_err(ExecError::Program)?
            .into_iter()
            .map(|(unit, t)| {
                let input = &pass.textures[t];
                json!({ "unit": unit, "target": input.target.0, "compare": input.sampling.compare, "linear": input.sampling.linear, "repeat": input.sampling.repeat })
            })
            .collect();
        let mut draws = Vec::new();
        for draw in &pass.draws {
            let data = bind::gl::draw(&program, pass, draw, plan.unset).map_err(ExecError::Program)?;
            let blocks: Vec<Value> = data
                .blocks
                .iter()
                .map(|(point, bytes)| json!({ "point": point, "words": bytemuck::cast_slice::<u8, u32>(bytes) }))
                .collect();
            let uniforms: Vec<Value> = data
                .uniforms
                .iter()
                .map(|(name, v)| {
                    let call = UniformCall::of(v);
                    json!({ "name": name, "call": call.webgl(), "matrix": matches!(call, UniformCall::Matrix { .. }), "words": v.words })
                })
                .collect();
            let (mesh, vertices) = match draw.geometry {
                Geometry::Mesh(m) => {
                    meshes.entry(m.name).or_insert_with(|| mesh_json(m));
                    (Some(m.name), 0)
                }
                Geometry::Vertices(n) => (None, n),
            };
            draws.push(json!({ "mesh": mesh, "vertices": vertices, "blocks": blocks, "uniforms": uniforms }));
        }
        passes.push(json!({
            "name": pass.name,
            "program": programs.len() - 1,
            "color": pass.color.map(|a| json!({ "target": a.target.0, "clear": a.clear })),
            "more_colors": pass.more_colors.iter().map(|a| json!({ "target": a.target.0, "clear": a.clear })).collect::<Vec<_>>(),
            "depth": pass.depth.map(|a| json!({ "target": a.target.0, "clear": a.clear })),
            "cull": match pass.cull { Cull::None => "none", Cull::Front => "front", Cull::Back => "back" },
            "depth_bias": pass.depth_bias,
            "textures": textures,
            "draws": draws,
        }));
    }
    let targets: Vec<Value> = plan
        .targets
        .iter()
        .map(|t| json!({ "name": t.name, "width": t.width, "height": t.height, "format": t.format.name(), "contents": t.contents, "dim": t.dim.name(), "layers": t.dim.layers() }))
        .collect();
    let doc = json!({
        "scene": plan.scene,
        "targets": targets,
        "meshes": meshes,
        "programs": programs,
        "passes": passes,
        "readback": plan.readback.0,
        // Vulkan-dialect code keeps its picture's top in row 0.
        "top_first": bind::is_vulkan(r, plan),
    });
    Ok((doc, files))
}

impl Executor for WebGl {
    type Prepared = WebGlProgram;

    fn prepare(&self, set: &ShaderSet, plan: &FramePlan) -> Result<WebGlProgram, ExecError> {
        if set.target != Target::Gles300 {
            return Err(ExecError::Unsupported(format!("{}: WebGL2 runs GLSL ES 3.00, not {}", set.label, set.target.name())));
        }
        if !set.modules.iter().all(|m| matches!(m, ShaderCode::Glsl { .. })) {
            return Err(ExecError::Program(format!("{}: not GLSL files", set.label)));
        }
        plan_json(set, plan)?;
        Ok(WebGlProgram { set: set.clone() })
    }

    fn run(&self, prepared: &WebGlProgram, plan: &FramePlan) -> Result<Readback, ExecError> {
        self.run_batch(&[(&prepared.set, plan)]).pop().expect("one job, one result")
    }

    fn device_name(&self) -> String {
        let d = self.last_device.lock().unwrap_or_else(|p| p.into_inner()).clone();
        if d.is_empty() {
            format!("chromium at {}", self.chromium.display())
        } else {
            d
        }
    }
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
    use crate::render::{hand, plan::tutorial, FrameParams};

    #[test]
    fn base64_round_trip() {
        assert_eq!(base64_decode("aGVsbG8=").unwrap(), b"hello");
        assert_eq!(base64_decode("AAECAw==").unwrap(), vec![0, 1, 2, 3]);
        assert_eq!(base64_decode("").unwrap(), Vec::<u8>::new());
    }

    #[test]
    fn the_page_gets_every_draw_resolved() {
        let mut r = hand::reflection();
        for e in &mut r.entry_points {
            e.files = [("gles300".to_string(), format!("{}.300es.x", e.name))].into();
        }
        let set = ShaderSet {
            label: "hand".into(),
            target: Target::Gles300,
            modules: r.entry_points.iter().map(|e| ShaderCode::Glsl { file: format!("{}.300es.x", e.name), text: String::new() }).collect(),
            entry_module: r.entry_points.iter().enumerate().map(|(i, e)| (e.name.clone(), i)).collect(),
            reflection: Some(r),
        };
        let (v, files) = plan_json(&set, &tutorial::plan(&FrameParams::new(1.0, 8, 6))).unwrap();
        assert_eq!(files.len(), 4);
        let main = &v["passes"][1];
        assert_eq!(main["draws"].as_array().unwrap().len(), 2);
        // u_is_floor of the floor draw: a plain uniform set by name to 1.0.
        let floor = &main["draws"][1]["uniforms"];
        let is_floor = floor.as_array().unwrap().iter().find(|u| u["name"] == json!("u_is_floor")).unwrap();
        assert_eq!((is_floor["call"].as_str(), &is_floor["words"][0]), (Some("uniform1fv"), &json!(1.0f32.to_bits())));
        assert!(main["draws"][1]["blocks"].as_array().unwrap().is_empty(), "plain uniforms need no blocks");
        assert_eq!(main["textures"][0]["unit"], json!(0));
        assert_eq!(v["meshes"]["cube"]["vertices"].as_array().unwrap().len(), 24 * 6);
    }
}
