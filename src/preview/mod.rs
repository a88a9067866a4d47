//! `umbrac preview FILE`: one program drawn in the browser, redrawn on
//! every save (feature `preview`; docs/preview.md).
//!
//! A blocking HTTP server (tiny_http) on 127.0.0.1 answers a fixed table
//! of names: the page's files (`web/preview/`, built into the binary) and
//! the program's [`Bundle`] (`/bundle.json`, and `/events`, a Server-Sent
//! Events stream that carries each new one). Nothing else is read from
//! disk on a request's behalf, so no URL reaches another file, except,
//! with a scene file ([`SceneFile`]), the image files its textures name
//! under `/scene/NAME`. A watch thread
//! ([`crate::watch`], what `--watch` uses) recompiles the program when a
//! file it read changes and hands the new bundle to every open stream;
//! a failed compile is sent too (its diagnostics), and the page keeps
//! drawing the last good one.
//!
//! With a built playground ([`Playground`]) it also serves that page under
//! `/playground/`, with the file loaded: the bundles then carry the
//! file's text for its editor.

mod playground;
mod routes;
mod scene_file;

use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use crate::bundle::Bundle;
use crate::run::Watched;
use crate::{Options, Target};

pub use playground::{Playground, FILES as PLAYGROUND_FILES};
pub use routes::{route, Route};
pub use scene_file::SceneFile;

/// The targets a preview compiles: what the page draws from (the manifest
/// comes with every compile).
pub const TARGETS: [Target; 2] = [Target::Gles300, Target::Wgsl];

/// How often an idle event stream sends a comment, so that a closed tab's
/// connection is noticed and its thread ends.
const KEEPALIVE: Duration = Duration::from_secs(10);

/// The latest bundle and its number (1 for the first compile).
struct Latest {
    generation: u64,
    json: Arc<String>,
}

/// What the watch thread and the request threads share.
#[derive(Clone)]
pub struct Published {
    inner: Arc<(Mutex<Latest>, Condvar)>,
}

impl Default for Published {
    fn default() -> Self {
        Published { inner: Arc::new((Mutex::new(Latest { generation: 0, json: Arc::new(String::new()) }), Condvar::new())) }
    }
}

impl Published {
    /// Makes `json` the latest bundle and wakes every stream.
    pub fn publish(&self, json: String) {
        let (lock, changed) = &*self.inner;
        let mut l = lock.lock().unwrap_or_else(|e| e.into_inner());
        l.generation += 1;
        l.json = Arc::new(json);
        changed.notify_all();
    }

    /// The latest bundle and its number (0: none yet).
    pub fn latest(&self) -> (u64, Arc<String>) {
        let l = self.inner.0.lock().unwrap_or_else(|e| e.into_inner());
        (l.generation, l.json.clone())
    }

    /// Waits until a bundle newer than `seen` is published, or `timeout`.
    fn wait_newer(&self, seen: u64, timeout: Duration) -> Option<(u64, Arc<String>)> {
        let (lock, changed) = &*self.inner;
        let l = lock.lock().unwrap_or_else(|e| e.into_inner());
        let (l, _) = changed.wait_timeout_while(l, timeout, |l| l.generation <= seen).unwrap_or_else(|e| e.into_inner());
        (l.generation > seen).then(|| (l.generation, l.json.clone()))
    }
}

/// The options a preview compiles `file` with: `base`'s, for the page's targets.
pub fn options_for(file: &Path, base: &Options) -> Options {
    let mut o = base.clone();
    o.targets = TARGETS.to_vec();
    if o.source_name.is_none() {
        o.source_name = file.file_name().map(|n| n.to_string_lossy().into_owned());
    }
    o
}

/// Compiles `file` once: its bundle, its diagnostics as text (for the
/// terminal), and what to watch (every file read, and the paths an
/// `#include` or `require` looked for and did not find).
pub fn compile(file: &Path, opts: &Options) -> (Bundle, String, Watched) {
    compile_for(file, opts, false, None)
}

/// [`compile`], the bundle carrying the file's text (`source`) when asked,
/// and `scene`'s scene instead of the inferred one.
fn compile_for(file: &Path, opts: &Options, with_source: bool, scene: Option<&SceneFile>) -> (Bundle, String, Watched) {
    let pre = crate::preprocess_file(file, opts);
    let mut files = pre.files_read();
    // A probe in a directory that does not exist (a daslang module root
    // absent here) cannot be watched: its directory is not there either.
    files.extend(pre.probed().iter().filter(|p| p.parent().is_some_and(Path::is_dir)).cloned());
    if files.is_empty() {
        files.push(file.to_path_buf());
    }
    let c = pre.compile(opts);
    files.extend(c.files_read());
    files.sort();
    files.dedup();
    let mut bundle = Bundle::of(&c);
    if with_source {
        bundle.source = Some(playground::source_of(file, &c));
    }
    let mut text = c.render_diagnostics();
    if let Some(sf) = scene {
        files.push(sf.path().to_path_buf());
        if bundle.ok {
            match sf.load() {
                Ok(s) => bundle.scene = Some(s.to_json()),
                // Drawn as a failed compile: the page keeps the last good picture.
                Err(e) => {
                    bundle.ok = false;
                    bundle.diagnostics.push(SceneFile::diagnostic(&e));
                    text += &format!("error: {e}\n");
                }
            }
        }
    }
    (bundle, text, Watched { files, dirs: Vec::new() })
}

/// A bound server, not yet answering.
pub struct Server {
    http: tiny_http::Server,
    port: u16,
}

impl Server {
    /// Listens on 127.0.0.1:`port` (0: any free port). Never on another interface.
    pub fn bind(port: u16) -> Result<Server, String> {
        let http = tiny_http::Server::http(("127.0.0.1", port)).map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = http.server_addr().to_ip().map(|a| a.port()).ok_or("the server has no IP address")?;
        Ok(Server { http, port })
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    /// The page's address.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }

    /// Compiles `file` now and on every change (diagnostics to stderr),
    /// and answers requests until the process ends; with `playground`,
    /// serves it too, and every bundle carries the file's text; with
    /// `scene`, the program is drawn with that scene file. Returns only if
    /// the watcher or the listening socket fails.
    pub fn serve(self, file: PathBuf, opts: Options, playground: Option<Playground>, scene: Option<SceneFile>) -> Result<(), String> {
        let published = Published::default();
        let p = published.clone();
        let with_source = playground.is_some();
        let site = Arc::new(Site { live: playground::live_json(&file, &opts), playground, scene: scene.clone() });
        let watcher = std::thread::Builder::new()
            .name("preview-watch".into())
            .spawn(move || {
                crate::watch::watch(|| {
                    let (bundle, text, watched) = compile_for(&file, &opts, with_source, scene.as_ref());
                    eprint!("{text}");
                    let code = if bundle.ok { 0 } else { crate::run::EXIT_ERROR };
                    p.publish(bundle.to_json());
                    (code, watched)
                })
            })
            .map_err(|e| format!("cannot start the watch thread: {e}"))?;
        for request in self.http.incoming_requests() {
            if watcher.is_finished() {
                break;
            }
            let published = published.clone();
            let site = site.clone();
            let port = self.port;
            // An event stream holds its thread for as long as the tab is open.
            let _ = std::thread::Builder::new().name("preview-request".into()).spawn(move || answer(request, port, &published, &site));
        }
        match watcher.join() {
            Ok(Err(e)) => Err(e),
            _ => Err("the server stopped".into()),
        }
    }
}

/// What is served besides the built-in page and the bundles.
struct Site {
    /// `/playground/live.json`.
    live: String,
    playground: Option<Playground>,
    /// `--scene`: its images under `/scene/NAME`.
    scene: Option<SceneFile>,
}

fn answer(request: tiny_http::Request, port: u16, published: &Published, site: &Site) {
    let host = request.headers().iter().find(|h| h.field.equiv("Host")).map(|h| h.value.as_str().to_string());
    let get = matches!(request.method(), tiny_http::Method::Get | tiny_http::Method::Head);
    let r = route(get, request.url(), host.as_deref(), port);
    let respond = |request: tiny_http::Request, status: u16, kind: &str, body: Vec<u8>| {
        let header = tiny_http::Header::from_bytes("Content-Type", kind).expect("a valid header");
        let no_store = tiny_http::Header::from_bytes("Cache-Control", "no-store").expect("a valid header");
        let _ = request.respond(tiny_http::Response::from_data(body).with_status_code(status).with_header(header).with_header(no_store));
    };
    let not_built = |request| respond(request, 404, "text/plain; charset=utf-8", b"no playground is served: build it with scripts/build-playground.sh, or give --playground DIR\n".to_vec());
    match r {
        Route::Refused(status, why) => respond(request, status, "text/plain; charset=utf-8", format!("{why}\n").into_bytes()),
        Route::Static(name) => match routes::asset(name) {
            Some((kind, body)) => respond(request, 200, kind, body),
            None => respond(request, 404, "text/plain; charset=utf-8", b"not found\n".to_vec()),
        },
        Route::Bundle => match published.latest() {
            (0, _) => respond(request, 503, "text/plain; charset=utf-8", b"the first compile is still running\n".to_vec()),
            (_, json) => respond(request, 200, "application/json", json.as_bytes().to_vec()),
        },
        Route::Events => stream(request, published),
        Route::Playground(name) => match site.playground.as_ref().and_then(|p| p.file(name)) {
            Some((kind, body)) => respond(request, 200, kind, body.to_vec()),
            None => not_built(request),
        },
        Route::Live if site.playground.is_some() => respond(request, 200, "application/json", site.live.clone().into_bytes()),
        Route::Live => not_built(request),
        Route::SceneImage(name) => match site.scene.as_ref().map(|s| s.image(&name)) {
            Some(Ok((kind, body))) => respond(request, 200, kind, body),
            Some(Err((status, why))) => respond(request, status, "text/plain; charset=utf-8", format!("{why}\n").into_bytes()),
            None => respond(request, 404, "text/plain; charset=utf-8", b"no scene file is drawn (umbrac preview FILE --scene SCENE)\n".to_vec()),
        },
        Route::Redirect(to) => {
            let location = tiny_http::Header::from_bytes("Location", to).expect("a valid header");
            let _ = request.respond(tiny_http::Response::empty(301).with_header(location));
        }
    }
}

/// Server-Sent Events: the latest bundle at once, then each new one.
fn stream(request: tiny_http::Request, published: &Published) {
    use std::io::Write;
    let mut w = request.into_writer();
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n";
    if w.write_all(head.as_bytes()).and_then(|_| w.flush()).is_err() {
        return;
    }
    let mut seen = 0;
    loop {
        // A bundle is one line of JSON: one `data:` line.
        let sent = match published.wait_newer(seen, KEEPALIVE) {
            Some((generation, json)) => {
                seen = generation;
                write!(w, "id: {generation}\nevent: bundle\ndata: {json}\n\n")
            }
            None => w.write_all(b": keepalive\n\n"),
        };
        if sent.and_then(|_| w.flush()).is_err() {
            return;
        }
    }
}

/// Starts the desktop's browser on `url`, if there is one
/// (`$BROWSER`, `xdg-open`, macOS's `open`).
pub fn open_browser(url: &str) -> Result<(), String> {
    let mut tried = Vec::new();
    let browser = std::env::var("BROWSER").ok().filter(|b| !b.is_empty());
    for cmd in browser.iter().map(String::as_str).chain(["xdg-open", "open"]) {
        match std::process::Command::new(cmd).arg(url).stdin(std::process::Stdio::null()).spawn() {
            Ok(_) => return Ok(()),
            Err(_) => tried.push(cmd.to_string()),
        }
    }
    Err(format!("no browser to open (tried {}); open {url} yourself", tried.join(", ")))
}
