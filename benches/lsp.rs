//! The language server's speed (criterion): `cargo bench --bench lsp`.
//!
//! For shaders/shadow.das (121 lines) and the same program grown to about
//! 2,000 lines (`support::scaled_source`, every helper reached):
//!
//! - `check`: an in-process check of the text, `umbrac::compile_source`
//!   with the default options (what `umbrac check` does per file);
//! - `workspace_check`: the server's check of the text alone
//!   (`Workspace::check`: the compilation and the index queries use);
//! - `diagnostics_after_edit`: `umbrac lsp` over an in-memory connection,
//!   from a `didChange` with new text to its `publishDiagnostics`;
//! - `hover`, `definition`, `completion`: a request to its response, from
//!   the last analysis.
//!
//! CPU time, as the compile benchmarks: of the process for `check` and
//! `workspace_check` (they run on the benchmark's thread), of the server's
//! thread for the protocol's numbers (what the server spends; the client's
//! side, building and reading the messages and waiting on the channel,
//! is the editor's). docs/performance.md has the ratios (issue 39 asks at
//! most 1.2x a check for the diagnostics, 0.1x for the queries).

#[path = "support/mod.rs"]
mod support;

use std::path::Path;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::{json, Value};
use support::*;

type C = Criterion<CpuTime>;

/// A server on a thread with one document open, and the client's end.
struct Server {
    conn: Connection,
    /// The server thread's CPU clock.
    clock: libc::clockid_t,
    thread: Option<std::thread::JoinHandle<()>>,
    uri: String,
    version: i32,
    next_id: i32,
}

impl Server {
    fn open(path: &Path, text: &str) -> Server {
        let (server, conn) = Connection::memory();
        let (clock_tx, clock_rx) = std::sync::mpsc::channel();
        let thread = Some(std::thread::spawn(move || {
            let mut clock: libc::clockid_t = 0;
            // SAFETY: this thread's own handle and a valid out pointer.
            assert_eq!(unsafe { libc::pthread_getcpuclockid(libc::pthread_self(), &mut clock) }, 0);
            clock_tx.send(clock).unwrap();
            umbrac::lsp::serve(server).expect("the server ends cleanly")
        }));
        let clock = clock_rx.recv().unwrap();
        let uri = umbrac::lsp::uri_of(path).unwrap().as_str().to_string();
        let mut s = Server { conn, clock, thread, uri, version: 0, next_id: 0 };
        s.request("initialize", json!({"capabilities": {}}));
        s.notify("initialized", json!({}));
        s.notify("textDocument/didOpen", json!({"textDocument": {"uri": s.uri, "languageId": "daslang", "version": 0, "text": text}}));
        s.wait_diagnostics(0);
        s
    }

    fn notify(&self, method: &str, params: Value) {
        self.conn.sender.send(Message::Notification(Notification::new(method.into(), params))).unwrap();
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        self.conn.sender.send(Message::Request(Request::new(id.clone(), method.into(), params))).unwrap();
        loop {
            match self.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("a response") {
                Message::Response(r) if r.id == id => {
                    assert!(r.error.is_none(), "{method}: {:?}", r.error);
                    return r.result.unwrap_or(Value::Null);
                }
                _ => {}
            }
        }
    }

    /// Waits for the diagnostics of `version`; they must be empty.
    fn wait_diagnostics(&self, version: i32) {
        loop {
            match self.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("diagnostics") {
                Message::Notification(n) if n.method == "textDocument/publishDiagnostics" && n.params["version"] == json!(version) => {
                    assert_eq!(n.params["diagnostics"], json!([]), "{}", n.params);
                    return;
                }
                _ => {}
            }
        }
    }

    /// A new text (the program with an edited comment at its end) and its diagnostics.
    fn edit(&mut self, text: &str) {
        self.version += 1;
        let edited = format!("{text}// edit {}\n", self.version % 2);
        self.notify("textDocument/didChange", json!({"textDocument": {"uri": self.uri, "version": self.version}, "contentChanges": [{"text": edited}]}));
        self.wait_diagnostics(self.version);
    }

    fn at(&self, text: &str, needle: &str, plus: usize) -> Value {
        let at = text.rfind(needle).unwrap_or_else(|| panic!("`{needle}`")) + plus;
        let line = text[..at].matches('\n').count();
        let col = at - text[..at].rfind('\n').map_or(0, |i| i + 1);
        json!({"textDocument": {"uri": self.uri}, "position": {"line": line, "character": col}})
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        self.thread.take().unwrap().join().unwrap();
    }
}

fn configure<M: criterion::measurement::Measurement>(g: &mut criterion::BenchmarkGroup<'_, M>) {
    g.sample_size(20).measurement_time(Duration::from_secs(8)).warm_up_time(Duration::from_secs(2));
}

fn program(c: &mut C, name: &str, text: &str) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().canonicalize().unwrap().join("program.das");
    std::fs::write(&path, text).unwrap();
    let group = format!("lsp_{name}");
    let mut g = c.benchmark_group(&group);
    configure(&mut g);
    let opts = umbrac::Options::default();
    g.bench_function("check", |b| {
        b.iter(|| {
            let c = umbrac::compile_source("program.das", std::hint::black_box(text), &opts);
            assert!(!c.has_errors());
            c
        })
    });
    // The server's check alone, without the protocol.
    let mut ws = umbrac::workspace::Workspace::new(opts.clone());
    ws.set_document(&path, text.to_string(), 0);
    g.bench_function("workspace_check", |b| b.iter(|| ws.check(&path)));
    g.finish();
    drop(ws);

    let mut server = Server::open(&path, text);
    let mut sc = Criterion::default().with_measurement(CpuTime(server.clock)).configure_from_args();
    let mut g = sc.benchmark_group(&group);
    configure(&mut g);
    g.bench_function("diagnostics_after_edit", |b| b.iter(|| server.edit(text)));
    // Queries: a local in the last helper, a call of a helper, names in its body.
    let hover = server.at(text, "let ndotl", 4);
    let definition = server.at(text, "= sun_visibility", 3);
    let completion = server.at(text, "    let up = ", 13);
    let h = server.request("textDocument/hover", hover.clone());
    assert!(h["contents"]["value"].as_str().unwrap_or("").contains("float"), "{h}");
    assert!(!server.request("textDocument/definition", definition.clone()).is_null());
    assert!(server.request("textDocument/completion", completion.clone()).as_array().is_some_and(|a| a.len() > 50));
    g.bench_function("hover", |b| b.iter(|| server.request("textDocument/hover", hover.clone())));
    g.bench_function("definition", |b| b.iter(|| server.request("textDocument/definition", definition.clone())));
    g.bench_function("completion", |b| b.iter(|| server.request("textDocument/completion", completion.clone())));
    g.finish();
}

fn shadow(c: &mut C) {
    program(c, "shadow", SHADOW_DAS);
}

fn lines_2000(c: &mut C) {
    let text = scaled_source(37);
    eprintln!("lsp_2000_lines: {} lines", text.lines().count());
    program(c, "2000_lines", &text);
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(CpuTime::PROCESS);
    targets = shadow, lines_2000
}
criterion_main!(benches);
