//! `umbrac lsp` over an in-memory connection: the handshake, diagnostics
//! as documents change (also in included files), hover, definition,
//! references, document symbols, and bad input (half-typed code,
//! positions past the end, a deleted file, unknown requests).

use std::path::{Path, PathBuf};
use std::time::Duration;

use lsp_server::{Connection, Message, Notification, Request, RequestId, Response};
use serde_json::{json, Value};

use crate::support;

const SHADER: &str = "\
//! The light's colour.
var @uniform light : float3
var @out f_color : float4

def shade(c : float3) : float3 {
    return c * light
}

[vertex_program]
def vs {
    gl_Position = float4(shade(light), 1.0)
}

[fragment_program]
def fs {
    let k = length(light)
    f_color = float4(float3(k), 1.0)
}
";

/// A server on a thread, and the client's end.
struct Client {
    conn: Connection,
    server: Option<std::thread::JoinHandle<()>>,
    next_id: i32,
}

impl Client {
    fn start(init: Value) -> Client {
        let (server, conn) = Connection::memory();
        let handle = std::thread::spawn(move || umbrac::lsp::serve(server).expect("the server ends cleanly"));
        let mut c = Client { conn, server: Some(handle), next_id: 0 };
        let caps = c.request("initialize", json!({"capabilities": {}, "initializationOptions": init}));
        assert_eq!(caps["capabilities"]["hoverProvider"], json!(true), "{caps}");
        c.notify("initialized", json!({}));
        c
    }

    /// A client whose first messages (`queue`) all wait on the connection
    /// before the server reads any: what it does with a backlog is then
    /// the same on every run.
    fn start_queued(init: Value, queue: impl FnOnce(&mut Client)) -> Client {
        let (server, conn) = Connection::memory();
        let mut c = Client { conn, server: None, next_id: 0 };
        let init_id = c.send("initialize", json!({"capabilities": {}, "initializationOptions": init}));
        c.notify("initialized", json!({}));
        queue(&mut c);
        c.server = Some(std::thread::spawn(move || umbrac::lsp::serve(server).expect("the server ends cleanly")));
        assert!(c.response(&init_id).error.is_none());
        c
    }

    /// Sends a request; its id.
    fn send(&mut self, method: &str, params: Value) -> RequestId {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        self.conn.sender.send(Message::Request(Request::new(id.clone(), method.into(), params))).unwrap();
        id
    }

    /// The response to `id` (what comes before it is dropped).
    fn response(&self, id: &RequestId) -> Response {
        loop {
            match self.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("a response") {
                Message::Response(r) if &r.id == id => return r,
                _ => continue,
            }
        }
    }

    fn notify(&self, method: &str, params: Value) {
        self.conn.sender.send(Message::Notification(Notification::new(method.into(), params))).unwrap();
    }

    /// Sends a request and waits for its response (notifications on the way are dropped).
    fn request_raw(&mut self, method: &str, params: Value) -> Response {
        let id = self.send(method, params);
        self.response(&id)
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        let r = self.request_raw(method, params);
        assert!(r.error.is_none(), "{method}: {:?}", r.error);
        r.result.unwrap_or(Value::Null)
    }

    /// The next diagnostics published for `uri`.
    fn diagnostics(&self, uri: &str) -> Value {
        loop {
            match self.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("diagnostics are published") {
                Message::Notification(n) if n.method == "textDocument/publishDiagnostics" && n.params["uri"] == uri => return n.params,
                _ => continue,
            }
        }
    }

    /// Diagnostics as published, the latest per URI, until `done` holds of them.
    fn diagnostics_until(&self, done: impl Fn(&std::collections::HashMap<String, Value>) -> bool) -> std::collections::HashMap<String, Value> {
        let mut latest = std::collections::HashMap::new();
        while !done(&latest) {
            match self.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("diagnostics are published") {
                Message::Notification(n) if n.method == "textDocument/publishDiagnostics" => {
                    latest.insert(n.params["uri"].as_str().unwrap().to_string(), n.params["diagnostics"].clone());
                }
                _ => continue,
            }
        }
        latest
    }

    fn open(&self, uri: &str, text: &str, version: i32) {
        self.notify("textDocument/didOpen", json!({"textDocument": {"uri": uri, "languageId": "daslang", "version": version, "text": text}}));
    }

    fn change(&self, uri: &str, text: &str, version: i32) {
        self.notify("textDocument/didChange", json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": text}]}));
    }

    fn at(uri: &str, line: u32, character: u32) -> Value {
        json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
    }

    /// `shutdown`, `exit`, and the server's thread ends without an error.
    fn finish(mut self) {
        self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        self.server.take().unwrap().join().expect("the server did not panic");
    }
}

fn uri(path: &Path) -> String {
    umbrac::lsp::uri_of(path).unwrap().as_str().to_string()
}

fn temp_with(files: &[(&str, &str)]) -> (tempfile::TempDir, PathBuf) {
    let d = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(d.path().join(name), text).unwrap();
    }
    let root = d.path().canonicalize().unwrap();
    (d, root)
}

/// Line and column (0-based) of the first `needle` in `text`.
fn pos(text: &str, needle: &str) -> (u32, u32) {
    let at = text.find(needle).unwrap_or_else(|| panic!("`{needle}` in the text"));
    let line = text[..at].matches('\n').count() as u32;
    let col = (at - text[..at].rfind('\n').map_or(0, |i| i + 1)) as u32;
    (line, col)
}

#[test]
fn diagnostics_follow_the_edits_and_match_the_cli() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let mut c = Client::start(json!({"targets": ["wgsl"]}));
    c.open(&u, SHADER, 1);
    let ok = c.diagnostics(&u);
    assert_eq!(ok["diagnostics"], json!([]), "{ok}");
    assert_eq!(ok["version"], json!(1));
    // An unknown name: reported where it is, with the CLI's message.
    let bad = SHADER.replace("c * light", "c * lihgt");
    c.change(&u, &bad, 2);
    let d = c.diagnostics(&u);
    assert_eq!(d["version"], json!(2));
    let diags = d["diagnostics"].as_array().unwrap();
    assert_eq!(diags.len(), 1, "{d}");
    let (line, col) = pos(&bad, "lihgt");
    assert_eq!(diags[0]["range"]["start"], json!({"line": line, "character": col}), "{d}");
    assert_eq!(diags[0]["range"]["end"], json!({"line": line, "character": col + 5}), "{d}");
    let cli = umbrac::compile_source("a.das", &bad, &umbrac::Options { targets: vec![umbrac::Target::Wgsl], ..Default::default() });
    assert!(diags[0]["message"].as_str().unwrap().starts_with(&cli.diagnostics[0].message), "{d}");
    // The checker's "did you mean" is a quick fix.
    let actions = c.request("textDocument/codeAction", json!({"textDocument": {"uri": u}, "range": diags[0]["range"], "context": {"diagnostics": [diags[0]]}}));
    assert_eq!(actions[0]["edit"]["changes"][&u][0]["newText"], json!("light"), "{actions}");
    assert_eq!(actions[0]["edit"]["changes"][&u][0]["range"], diags[0]["range"], "{actions}");
    // Rapid changes: only the newest version's result is published.
    c.change(&u, &bad, 3);
    c.change(&u, SHADER, 4);
    let fixed = c.diagnostics(&u);
    assert_eq!((fixed["version"].clone(), fixed["diagnostics"].clone()), (json!(4), json!([])), "{fixed}");
    c.finish();
}

#[test]
fn an_error_in_an_open_included_file_shows_at_the_include_line() {
    let main = "#include \"inc.das\"\n";
    let (_d, root) = temp_with(&[("main.das", main), ("inc.das", SHADER)]);
    let (mu, iu) = (uri(&root.join("main.das")), uri(&root.join("inc.das")));
    let c = Client::start(Value::Null);
    c.open(&mu, main, 1);
    assert_eq!(c.diagnostics(&mu)["diagnostics"], json!([]));
    // The unsaved text of the included file counts: the error shows at the
    // #include line, and in the included document where the name is.
    c.open(&iu, &SHADER.replace("c * light", "c * nothing"), 1);
    let some = |v: Option<&Value>| v.is_some_and(|d| d != &json!([]));
    let seen = c.diagnostics_until(|l| some(l.get(&mu)) && some(l.get(&iu)));
    let (outer, inner) = (&seen[&mu], &seen[&iu]);
    assert_eq!(outer.as_array().unwrap().len(), 1, "{outer}");
    assert_eq!(outer[0]["range"]["start"], json!({"line": 0, "character": 0}), "{outer}");
    assert!(outer[0]["message"].as_str().unwrap().contains("inc.das:6:"), "{outer}");
    let (line, col) = pos(SHADER, "light\n}");
    assert_eq!(inner[0]["range"]["start"], json!({"line": line, "character": col}), "{inner}");
    assert!(inner[0]["message"].as_str().unwrap().starts_with("unknown name `nothing`"), "{inner}");
    // Fixed in the included document: both clear.
    c.change(&iu, SHADER, 2);
    let empty = |v: Option<&Value>| v == Some(&json!([]));
    c.diagnostics_until(|l| empty(l.get(&mu)) && empty(l.get(&iu)));
    c.finish();
}

#[test]
fn hover_definition_references_and_symbols() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let mut c = Client::start(Value::Null);
    c.open(&u, SHADER, 1);
    c.diagnostics(&u);
    let (line, col) = pos(SHADER, "light\n}");
    let h = c.request("textDocument/hover", Client::at(&u, line, col + 2));
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("light : float3") && text.contains("The light's colour.") && text.contains("\"glsl_name\":\"light\""), "{h}");
    let (bl, bc) = pos(SHADER, "length(");
    let b = c.request("textDocument/hover", Client::at(&u, bl, bc + 1));
    assert!(b["contents"]["value"].as_str().unwrap().contains("length(float3) : float"), "{b}");
    assert!(b["contents"]["value"].as_str().unwrap().contains("builtin: the length of a vector"), "{b}");
    let def = c.request("textDocument/definition", Client::at(&u, line, col));
    let (dl, dc) = pos(SHADER, "light :");
    assert_eq!(def["range"]["start"], json!({"line": dl, "character": dc}), "{def}");
    assert_eq!(def["uri"], json!(u));
    let refs = c.request("textDocument/references", json!({"textDocument": {"uri": u}, "position": {"line": line, "character": col}, "context": {"includeDeclaration": true}}));
    assert_eq!(refs.as_array().unwrap().len(), 4, "{refs}");
    let syms = c.request("textDocument/documentSymbol", json!({"textDocument": {"uri": u}}));
    let names: Vec<&str> = syms.as_array().unwrap().iter().map(|s| s["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["light", "f_color", "shade", "vs", "fs"], "{syms}");
    // Semantic tokens, decoded: the first is `light`'s declaration.
    let toks = c.request("textDocument/semanticTokens/full", json!({"textDocument": {"uri": u}}));
    let data: Vec<u64> = toks["data"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap()).collect();
    assert_eq!(data.len() % 5, 0);
    assert_eq!(&data[..5], &[dl as u64, dc as u64, 5, 0, 1], "{toks}");
    let (mut line, mut col, mut builtins) = (0u64, 0u64, Vec::new());
    for t in data.chunks(5) {
        col = if t[0] == 0 { col + t[1] } else { t[1] };
        line += t[0];
        if t[4] & 4 != 0 {
            let l = SHADER.lines().nth(line as usize).unwrap();
            builtins.push(l[col as usize..(col + t[2]) as usize].to_string());
        }
    }
    assert_eq!(builtins, ["gl_Position", "length"], "{toks}");
    // Signature help inside `shade(`.
    let (sl, sc) = pos(SHADER, "shade(light)");
    let help = c.request("textDocument/signatureHelp", Client::at(&u, sl, sc + 6));
    assert_eq!(help["signatures"][0]["label"], json!("def shade(c : float3) : float3"), "{help}");
    assert_eq!(help["activeParameter"], json!(0));
    c.finish();
}

#[test]
fn rename_across_an_include_and_its_refusals() {
    let main = "#include \"inc.das\"\n\n[fragment_program]\ndef fs2 {\n    f_color = float4(shade(light), 1.0)\n}\n";
    let inc = SHADER.replace("[fragment_program]\ndef fs {\n    let k = length(light)\n    f_color = float4(float3(k), 1.0)\n}\n", "");
    let (_d, root) = temp_with(&[("main.das", main), ("inc.das", &inc)]);
    let (mu, iu) = (uri(&root.join("main.das")), uri(&root.join("inc.das")));
    let mut c = Client::start(Value::Null);
    c.open(&mu, main, 1);
    assert_eq!(c.diagnostics(&mu)["diagnostics"], json!([]));
    let (line, col) = pos(main, "light)");
    let edit = c.request("textDocument/rename", json!({"textDocument": {"uri": mu}, "position": {"line": line, "character": col}, "newName": "sun"}));
    let changes = edit["changes"].as_object().unwrap();
    assert_eq!(changes[&mu].as_array().unwrap().len(), 1, "{edit}");
    assert_eq!(changes[&iu].as_array().unwrap().len(), 3, "the declaration and two uses: {edit}");
    for (u, text) in [(&mu, main), (&iu, inc.as_str())] {
        for e in changes[u].as_array().unwrap() {
            let (l, ch) = (e["range"]["start"]["line"].as_u64().unwrap() as usize, e["range"]["start"]["character"].as_u64().unwrap() as usize);
            assert_eq!(&text.lines().nth(l).unwrap()[ch..ch + 5], "light", "{e}");
        }
    }
    let refused = c.request_raw("textDocument/rename", json!({"textDocument": {"uri": mu}, "position": {"line": line, "character": col}, "newName": "f_color"}));
    assert!(refused.error.unwrap().message.contains("already declared"));
    let refused = c.request_raw("textDocument/rename", json!({"textDocument": {"uri": mu}, "position": {"line": line, "character": col}, "newName": "texture"}));
    assert!(refused.error.is_some());
    c.finish();
}

#[test]
fn definition_into_a_required_module_and_inlay_hints() {
    let lib = "def tint(c : float3) : float3 {\n    return c * 0.5\n}\n";
    let main = "require lib\n\nvar @out f_color : float4\n\n[fragment_program]\ndef fs {\n    let t = tint(float3(1.0))\n    f_color = float4(t, 1.0)\n}\n";
    let (_d, root) = temp_with(&[("main.das", main), ("lib.das", lib)]);
    let (mu, lu) = (uri(&root.join("main.das")), uri(&root.join("lib.das")));
    let mut c = Client::start(Value::Null);
    c.open(&mu, main, 1);
    assert_eq!(c.diagnostics(&mu)["diagnostics"], json!([]));
    let (line, col) = pos(main, "tint(");
    let def = c.request("textDocument/definition", Client::at(&mu, line, col + 1));
    assert_eq!(def["uri"], json!(lu), "{def}");
    assert_eq!(def["range"]["start"], json!({"line": 0, "character": 4}), "{def}");
    let hints = c.request("textDocument/inlayHint", json!({"textDocument": {"uri": mu}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 99, "character": 0}}}));
    let (tl, tc) = pos(main, "t = tint");
    assert_eq!(hints, json!([{"position": {"line": tl, "character": tc + 1}, "label": ": float3", "kind": 1}]), "{hints}");
    c.finish();
}

#[test]
fn completion_in_scope_and_after_a_dot() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let mut c = Client::start(Value::Null);
    c.open(&u, SHADER, 1);
    c.diagnostics(&u);
    let (line, col) = pos(SHADER, "f_color = float4(float3");
    let all = c.request("textDocument/completion", Client::at(&u, line, col));
    let labels: Vec<&str> = all.as_array().unwrap().iter().map(|i| i["label"].as_str().unwrap()).collect();
    for want in ["k", "light", "shade", "f_color", "normalize"] {
        assert!(labels.contains(&want), "{want}: {labels:?}");
    }
    // Half-typed: `light.` completes its components from the last good analysis.
    let typed = SHADER.replace("f_color = float4(float3(k), 1.0)", "f_color = float4(light.");
    c.change(&u, &typed, 2);
    let (line, col) = pos(&typed, "light.\n");
    let comps = c.request("textDocument/completion", Client::at(&u, line, col + 6));
    let labels: Vec<&str> = comps.as_array().unwrap().iter().map(|i| i["label"].as_str().unwrap()).collect();
    assert_eq!(labels, ["x", "y", "z", "r", "g", "b"], "{comps}");
    c.finish();
}

/// A builtin's overloads and meaning in signature help (the parameter at
/// the cursor by its place in the label) and in completion.
#[test]
fn builtins_in_signature_help_and_completion() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let mut c = Client::start(Value::Null);
    c.open(&u, SHADER, 1);
    c.diagnostics(&u);
    let typed = SHADER.replace("let k = length(light)", "let k = mix(light, light, ");
    c.change(&u, &typed, 2);
    let (line, col) = pos(&typed, "mix(");
    let help = c.request("textDocument/signatureHelp", Client::at(&u, line, col + 26));
    let sigs = help["signatures"].as_array().unwrap();
    assert_eq!(sigs.len(), 2, "{help}");
    assert_eq!(sigs[0]["label"], json!("mix(floatN, floatN, floatN) : floatN"), "{help}");
    assert!(sigs[0]["documentation"].as_str().unwrap().contains("linear blend"), "{help}");
    assert_eq!(help["activeParameter"], json!(2), "{help}");
    // The third `floatN`, not the first.
    assert_eq!(sigs[0]["parameters"][2]["label"], json!([20, 26]), "{help}");
    let tex = SHADER.replace("let k = length(light)", "let k = textureLod(");
    c.change(&u, &tex, 3);
    let (line, col) = pos(&tex, "textureLod(");
    let help = c.request("textDocument/signatureHelp", Client::at(&u, line, col + 11));
    assert!(help["signatures"][0]["label"].as_str().unwrap().starts_with("textureLod(s : sampler, uv : floatN, lod : float)"), "{help}");
    let all = c.request("textDocument/completion", Client::at(&u, line, col));
    let smooth = all.as_array().unwrap().iter().find(|i| i["label"] == "smoothstep").unwrap();
    assert!(smooth["detail"].as_str().unwrap().starts_with("smoothstep(floatN, floatN, floatN) : floatN (+1 more)"), "{smooth}");
    c.finish();
}

#[test]
fn bad_input_never_stops_the_server() {
    let (d, root) = temp_with(&[("a.das", SHADER)]);
    let path = root.join("a.das");
    let u = uri(&path);
    let mut c = Client::start(json!({"targets": ["nonsense"], "defines": 7}));
    c.open(&u, SHADER, 1);
    c.diagnostics(&u);
    // Half-typed code: diagnostics, and the last good analysis still answers.
    let half = format!("{SHADER}\n[fragment_program]\ndef more {{\n    let x = length(");
    c.change(&u, &half, 2);
    let d2 = c.diagnostics(&u);
    assert!(!d2["diagnostics"].as_array().unwrap().is_empty(), "{d2}");
    let (line, col) = pos(SHADER, "light\n}");
    assert!(c.request("textDocument/hover", Client::at(&u, line, col)).is_object());
    // Positions past a line's end, past the last line, huge: null or a result, never a crash.
    for (l, ch) in [(line, 10_000), (10_000, 0), (u32::MAX, u32::MAX)] {
        let r = c.request_raw("textDocument/hover", Client::at(&u, l, ch));
        assert!(r.error.is_none(), "{r:?}");
        let r = c.request_raw("textDocument/definition", Client::at(&u, l, ch));
        assert!(r.error.is_none(), "{r:?}");
    }
    // A 10 MB paste (host comments around the shader), and a position
    // inside a UTF-16 surrogate pair.
    let big = format!("// \u{1F600} pasted\n{}{SHADER}", "// host text pasted in\n".repeat((10 << 20) / 23 + 1));
    assert!(big.len() > 10 << 20);
    c.change(&u, &big, 3);
    let d3 = c.diagnostics(&u);
    assert_eq!((d3["version"].clone(), d3["diagnostics"].clone()), (json!(3), json!([])), "the paste checks");
    let r = c.request_raw("textDocument/hover", Client::at(&u, 0, 4));
    assert!(r.error.is_none(), "{r:?}");
    let (hl, hc) = pos(&big, "light\n}");
    let h = c.request("textDocument/hover", Client::at(&u, hl, hc));
    assert!(h["contents"]["value"].as_str().unwrap().contains("light : float3"), "{h}");
    // Bad parameters and unknown methods are errors, not the end.
    assert!(c.request_raw("textDocument/hover", json!({"nonsense": true})).error.is_some());
    assert!(c.request_raw("umbrac/unknown", Value::Null).error.is_some());
    // A file deleted while open, then closed: its diagnostics are cleared.
    std::fs::remove_file(&path).unwrap();
    c.notify("textDocument/didClose", json!({"textDocument": {"uri": u}}));
    assert_eq!(c.diagnostics(&u)["diagnostics"], json!([]));
    assert!(c.request("textDocument/hover", Client::at(&u, line, col)).is_null());
    // A document that is not a file, and one never opened.
    c.open("untitled:Untitled-1", "def", 1);
    assert!(c.request("textDocument/hover", Client::at(&uri(&root.join("never.das")), 0, 0)).is_null());
    drop(d);
    c.finish();
}

/// `$/cancelRequest` before the answer: `RequestCanceled` (-32800); the
/// next request is answered; a cancellation of nothing waiting is ignored.
#[test]
fn a_cancelled_request_answers_request_canceled() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let (line, col) = pos(SHADER, "light : float3");
    let (mut cancelled, mut answered) = (None, None);
    let mut c = Client::start_queued(json!({"targets": ["wgsl"]}), |c| {
        c.open(&u, SHADER, 1);
        let id = c.send("textDocument/hover", Client::at(&u, line, col));
        c.notify("$/cancelRequest", json!({"id": 1}));
        c.notify("$/cancelRequest", json!({"id": 99}));
        c.notify("$/cancelRequest", serde_json::to_value(&id).map(|id| json!({"id": id})).unwrap());
        cancelled = Some(id);
        answered = Some(c.send("textDocument/hover", Client::at(&u, line, col)));
    });
    let r = c.response(&cancelled.unwrap());
    assert_eq!(r.error.as_ref().map(|e| e.code), Some(-32800), "{r:?}");
    let r = c.response(&answered.unwrap());
    assert!(r.result.as_ref().unwrap()["contents"]["value"].as_str().unwrap().contains("light : float3"), "{r:?}");
    // Cancelling what was answered changes nothing.
    c.notify("$/cancelRequest", json!({"id": 3}));
    assert!(c.request("textDocument/hover", Client::at(&u, line, col))["contents"]["value"].as_str().unwrap().contains("float3"));
    c.finish();
}

/// A request between edits is answered from the version before it, but
/// nothing is published for a version a newer one already waits behind.
#[test]
fn nothing_is_published_over_a_newer_version() {
    let (_d, root) = temp_with(&[("a.das", SHADER)]);
    let u = uri(&root.join("a.das"));
    let (line, col) = pos(SHADER, "light : float3");
    let bad = SHADER.replace("c * light", "c * lihgt");
    let mut hover = None;
    let c = Client::start_queued(json!({"targets": ["wgsl"]}), |c| {
        c.open(&u, &bad, 1);
        c.change(&u, &bad.replace("lihgt", "lgiht"), 2);
        hover = Some(c.send("textDocument/hover", Client::at(&u, line, col)));
        c.change(&u, SHADER, 3);
    });
    let hover = hover.unwrap();
    let mut versions = Vec::new();
    let mut answered = false;
    while versions.last() != Some(&json!(3)) {
        match c.conn.receiver.recv_timeout(Duration::from_secs(60)).expect("diagnostics are published") {
            Message::Notification(n) if n.method == "textDocument/publishDiagnostics" => {
                assert_eq!(n.params["diagnostics"], json!([]), "{}", n.params);
                versions.push(n.params["version"].clone());
            }
            Message::Response(r) if r.id == hover => answered = true,
            _ => {}
        }
    }
    assert!(answered);
    assert_eq!(versions, [json!(3)]);
    c.finish();
}

/// The server reads the project file above a document; its
/// initializationOptions win key by key; a bad project file is a
/// diagnostic naming its line and column.
#[test]
fn the_project_file_and_the_settings_over_it() {
    let shader = "var @out f_color : float4\n\n[fragment_program]\ndef fs {\n    f_color = float4(TINT)\n}\n";
    let (_d, root) = temp_with(&[("umbrac.toml", "targets = [\"wgsl\"]\n[defines]\nTINT = \"0.5\"\n")]);
    std::fs::create_dir(root.join("sub")).unwrap();
    std::fs::write(root.join("sub/a.das"), shader).unwrap();
    let u = uri(&root.join("sub/a.das"));
    let mut c = Client::start(Value::Null);
    c.open(&u, shader, 1);
    assert_eq!(c.diagnostics(&u)["diagnostics"], json!([]));
    // The project's target is the one whose output the command shows.
    let out = c.request("workspace/executeCommand", json!({"command": "umbrac.output", "arguments": [u, "wgsl"]}));
    assert_eq!(out["files"][0]["name"], json!("a.wgsl"), "{out}");
    assert!(out["files"][0]["text"].as_str().unwrap().contains("@fragment"), "{out}");
    let glsl = c.request("workspace/executeCommand", json!({"command": "umbrac.output", "arguments": [u, "gles300"]}));
    assert!(glsl["files"][0]["text"].as_str().unwrap().contains("#version 300 es"), "{glsl}");
    let spirv = c.request_raw("workspace/executeCommand", json!({"command": "umbrac.output", "arguments": [u, "spirv"]}));
    assert!(spirv.error.unwrap().message.contains("binary"));
    // A bad project file: where it is wrong, at the top of the document.
    std::fs::write(root.join("umbrac.toml"), "targets = [\"wgsl\"]\n[defines]\nTINT = [1]\n").unwrap();
    c.notify("workspace/didChangeWatchedFiles", json!({"changes": [{"uri": uri(&root.join("umbrac.toml")), "type": 2}]}));
    let d = c.diagnostics(&u);
    let msg = d["diagnostics"][0]["message"].as_str().unwrap_or_default();
    assert!(msg.contains("umbrac.toml:3:8:") && msg.contains("one-line string"), "{d}");
    c.finish();
    // The settings' define wins over the project's.
    std::fs::write(root.join("umbrac.toml"), "[defines]\nTINT = \"0.5\"\n").unwrap();
    let c = Client::start(json!({"defines": ["TINT=nope"]}));
    c.open(&u, shader, 1);
    let d = c.diagnostics(&u);
    assert!(d["diagnostics"][0]["message"].as_str().unwrap_or_default().contains("nope"), "{d}");
    c.finish();
}

#[test]
fn host_code_says_nothing() {
    let host = "options gen2\n\n[export]\ndef main {\n    print(\"hello\")\n}\n";
    let (_d, root) = temp_with(&[("host.das", host)]);
    let u = uri(&root.join("host.das"));
    let c = Client::start(Value::Null);
    c.open(&u, host, 1);
    assert_eq!(c.diagnostics(&u)["diagnostics"], json!([]));
    c.finish();
}

/// Runs Neovim headless with `script` (tests/editor/) on `file`; what it
/// saw, as `key -> value`. `None`: no Neovim (skipped, failing under CI).
fn neovim(script: &str, file: &Path) -> Option<std::collections::HashMap<String, String>> {
    if std::process::Command::new("nvim").arg("--version").output().is_err() {
        support::skip("`nvim` cannot be run (apt-get install neovim)");
        return None;
    }
    let dir = file.parent().unwrap();
    let out = dir.join("seen.txt");
    let mut child = std::process::Command::new("nvim")
        .args(["--headless", "-u", "NONE", "-i", "NONE", "-n", "-c"])
        .arg(format!("luafile {}", support::repo().join("tests/editor").join(script).display()))
        .env("UMBRAC", env!("CARGO_BIN_EXE_umbrac"))
        .env("FILE", file)
        .env("OUT", &out)
        .env("XDG_STATE_HOME", dir)
        .env("XDG_DATA_HOME", dir)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("start nvim");
    let started = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("nvim did not finish in 120 s");
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let seen = std::fs::read_to_string(&out).expect("the script wrote what it saw");
    assert!(!seen.contains("lua_error"), "{seen}");
    Some(seen.lines().filter_map(|l| l.split_once('\t')).map(|(k, v)| (k.to_string(), v.replace("\\n", "\n"))).collect())
}

/// Neovim's own LSP client drives `umbrac lsp` on daslang's first GL
/// tutorial (tests/editor/nvim_lsp.lua): an error typed in shows at its
/// line and column, undoing it clears it, a hover shows a uniform's type.
#[test]
fn neovim_sees_the_diagnostic_and_the_hover() {
    let tutorial = support::repo().join("../shared/reference/daslang-tutorials/01_triangle.das");
    let Ok(text) = std::fs::read_to_string(&tutorial) else {
        return support::skip(format!("{} is not here", tutorial.display()));
    };
    let (_d, root) = temp_with(&[("01_triangle.das", &text)]);
    let Some(seen) = neovim("nvim_lsp.lua", &root.join("01_triangle.das")) else { return };
    let get = |k: &str| seen.get(k).map(String::as_str).unwrap_or_else(|| panic!("`{k}` in {seen:?}"));
    assert_eq!(get("attached"), "true", "{seen:?}");
    assert_eq!(get("diag_seen"), "true", "{seen:?}");
    assert_eq!((get("diag_line"), get("diag_col")), (get("error_line"), get("error_col")), "{seen:?}");
    assert!(get("diag_message").contains("v_colr"), "{seen:?}");
    assert_eq!(get("cleared"), "true", "{seen:?}");
    assert!(get("hover").contains("u_angle : float"), "{seen:?}");
}

/// Neovim jumps into a required module, renames a function across the
/// program and the module, and completes a struct's fields
/// (tests/editor/nvim_lsp_project.lua).
#[test]
fn neovim_jumps_renames_across_files_and_completes_a_field() {
    let lib = "def tint(c : float3) : float3 {\n    return c * 0.5\n}\n";
    let main = "require lib\n\nstruct Material {\n    albedo : float3\n    rough : float\n}\n\nvar @out f_color : float4\n\n[fragment_program]\ndef fs {\n    var m : Material\n    m.albedo = float3(1.0)\n    m.rough = 0.5\n    f_color = float4(tint(m.albedo * m.rough), 1.0)\n}\n";
    let (_d, root) = temp_with(&[("main.das", main), ("lib.das", lib)]);
    let Some(seen) = neovim("nvim_lsp_project.lua", &root.join("main.das")) else { return };
    let get = |k: &str| seen.get(k).map(String::as_str).unwrap_or_else(|| panic!("`{k}` in {seen:?}"));
    assert_eq!(get("definition"), format!("{}:0:4", root.join("lib.das").display()), "{seen:?}");
    assert_eq!(get("rename_error"), "none");
    assert_eq!(get("main_after"), main.replace("tint(", "shade_it(").trim_end(), "{seen:?}");
    assert_eq!(get("lib_after"), lib.replace("tint(", "shade_it(").trim_end(), "{seen:?}");
    assert_eq!(get("completion"), "albedo,rough", "{seen:?}");
}

/// The VS Code extension (editors/vscode/) type-checks, bundles and
/// packages with `@vscode/vsce` (VS Code itself cannot run here); its
/// settings are the initialization options the server reads, and the
/// command it sends is the server's.
#[test]
fn the_vscode_extension_builds_and_packages() {
    let ext = support::repo().join("editors/vscode");
    let vsce = ext.join("node_modules/.bin/vsce");
    if !vsce.exists() {
        return support::skip("editors/vscode/node_modules is not installed (npm ci --prefix editors/vscode)");
    }
    let out_dir = tempfile::tempdir().unwrap();
    let vsix = out_dir.path().join("umbrac.vsix");
    // `vsce package` runs `vscode:prepublish`: tsc --noEmit, then esbuild.
    let out = std::process::Command::new(&vsce)
        .args(["package", "--no-dependencies", "--out"])
        .arg(&vsix)
        .current_dir(&ext)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("run vsce");
    assert!(out.status.success(), "vsce package failed:\n{}\n{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&vsix).unwrap();
    assert_eq!(&bytes[..2], b"PK", "a .vsix is a zip");
    let has = |name: &str| bytes.windows(name.len()).any(|w| w == name.as_bytes());
    assert!(has("extension/dist/extension.js") && has("extension/package.json"), "the package holds the bundle and its manifest");
    let bundle = std::fs::read_to_string(ext.join("dist/extension.js")).unwrap();
    assert!(bundle.contains(umbrac::lsp::OUTPUT_COMMAND), "the extension sends the server's output command");
    // Every setting is an initialization option the server understands.
    let manifest: Value = serde_json::from_str(&std::fs::read_to_string(ext.join("package.json")).unwrap()).unwrap();
    let props = manifest["contributes"]["configuration"]["properties"].as_object().unwrap();
    let keys: Vec<&str> = props.keys().filter_map(|k| k.strip_prefix("umbrac.")).filter(|k| *k != "path").collect();
    assert_eq!(keys.len(), 8, "{keys:?}");
    let example = json!({"targets": ["wgsl"], "includeDirs": ["inc"], "daslangRoot": "/d", "daslib": "/d/daslib", "modules": {"geometry": "g"}, "defines": ["A=1"], "limits": {"uniform-blocks": 16}, "strictLimits": true});
    for k in &keys {
        assert!(example.get(k).is_some(), "setting umbrac.{k} is no initialization option");
        assert!(bundle.contains(&format!("\"{k}\"")), "the extension does not send {k}");
    }
    let (opts, problems) = umbrac::lsp::options_from(Some(&example));
    assert!(problems.is_empty(), "{problems:?}");
    assert!(opts.strict_limits && opts.limits.len() == 1 && opts.modules.len() == 1 && opts.daslib.is_some());
}
