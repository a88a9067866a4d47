//! `umbrac lsp`: a Language Server Protocol server over stdio for `.das`
//! shader files (feature `lsp`), built on rust-analyzer's `lsp-server`
//! and `lsp-types`, with no async runtime: one thread answers messages in
//! order, and compiles through [`crate::workspace`].
//!
//! Diagnostics are the compiler's own (one source of truth with the CLI).
//! Edits are coalesced: a document is checked once no message is waiting,
//! and a result is never published while a newer version of its document
//! waits to be read. A request cancelled (`$/cancelRequest`) before it is
//! answered answers `RequestCanceled`. A panic while answering a request
//! answers it with an error; the server goes on.

use std::collections::{HashMap, HashSet, VecDeque};
use std::error::Error;
use std::path::{Path, PathBuf};

use crossbeam_channel::TryRecvError;
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, RequestId, Response};
use lsp_types as lt;

use crate::diag::Severity;
use crate::workspace::{self, Workspace};
use crate::{Options, Target};

type Result<T> = std::result::Result<T, Box<dyn Error + Send + Sync>>;

/// Serves over stdin/stdout until the client says `exit`.
pub fn run_stdio() -> Result<()> {
    let (connection, io) = Connection::stdio();
    // On a compiler thread, checks run on it directly, keeping what the
    // thread holds between compilations (the validator, the SPIR-V writer).
    std::thread::scope(|s| match crate::spawn_compiler_thread(s, || serve(connection).map_err(|e| e.to_string())) {
        Ok(h) => h.join().unwrap_or_else(|_| Err("the server's thread panicked".into())),
        Err(e) => Err(format!("cannot start the server's thread: {e}")),
    })?;
    io.join()?;
    Ok(())
}

/// What the server announces.
fn capabilities() -> lt::ServerCapabilities {
    lt::ServerCapabilities {
        text_document_sync: Some(lt::TextDocumentSyncCapability::Kind(lt::TextDocumentSyncKind::FULL)),
        hover_provider: Some(lt::HoverProviderCapability::Simple(true)),
        definition_provider: Some(lt::OneOf::Left(true)),
        references_provider: Some(lt::OneOf::Left(true)),
        document_symbol_provider: Some(lt::OneOf::Left(true)),
        rename_provider: Some(lt::OneOf::Left(true)),
        inlay_hint_provider: Some(lt::OneOf::Left(true)),
        signature_help_provider: Some(lt::SignatureHelpOptions { trigger_characters: Some(vec!["(".into(), ",".into(), ";".into()]), ..Default::default() }),
        code_action_provider: Some(lt::CodeActionProviderCapability::Simple(true)),
        semantic_tokens_provider: Some(lt::SemanticTokensServerCapabilities::SemanticTokensOptions(lt::SemanticTokensOptions {
            legend: lt::SemanticTokensLegend { token_types: TOKEN_TYPES.to_vec(), token_modifiers: TOKEN_MODIFIERS.to_vec() },
            full: Some(lt::SemanticTokensFullOptions::Bool(true)),
            ..Default::default()
        })),
        completion_provider: Some(lt::CompletionOptions { trigger_characters: Some(vec![".".into(), "@".into()]), ..Default::default() }),
        position_encoding: Some(lt::PositionEncodingKind::UTF16),
        execute_command_provider: Some(lt::ExecuteCommandOptions { commands: vec![OUTPUT_COMMAND.into()], ..Default::default() }),
        ..Default::default()
    }
}

/// `workspace/executeCommand` `umbrac.output` with arguments `[URI,
/// TARGET]`: what the target writes for the document as it is now,
/// `{"files": [{"name", "text"}]}` (the VS Code extension's "Show a
/// target's output").
pub const OUTPUT_COMMAND: &str = "umbrac.output";

/// The semantic token types, indexed by `token_type`.
const TOKEN_TYPES: [lt::SemanticTokenType; 5] =
    [lt::SemanticTokenType::VARIABLE, lt::SemanticTokenType::FUNCTION, lt::SemanticTokenType::STRUCT, lt::SemanticTokenType::PROPERTY, lt::SemanticTokenType::ENUM_MEMBER];
/// Bits of `token_modifiers_bitset`: 1 declaration, 2 readonly, 4 defaultLibrary.
const TOKEN_MODIFIERS: [lt::SemanticTokenModifier; 3] = [lt::SemanticTokenModifier::DECLARATION, lt::SemanticTokenModifier::READONLY, lt::SemanticTokenModifier::DEFAULT_LIBRARY];

/// A token's type index and modifier bits.
fn token_type(t: &workspace::SemanticToken) -> (u32, u32) {
    use workspace::TokenKind as K;
    let (ty, mods) = match t.kind {
        K::Variable => (0, 0),
        K::Constant => (0, 2),
        K::Function => (1, 0),
        K::Struct => (2, 0),
        K::Field => (3, 0),
        K::BuiltinVariable => (0, 4),
        K::BuiltinFunction => (1, 4),
    };
    (ty, mods | u32::from(t.declaration))
}

/// Runs the protocol on a connection (stdio, or in memory in tests):
/// the initialize handshake, then messages until `shutdown` and `exit`.
pub fn serve(connection: Connection) -> Result<()> {
    let caps = serde_json::to_value(capabilities())?;
    let params = connection.initialize(caps)?;
    let init: lt::InitializeParams = serde_json::from_value(params).unwrap_or_default();
    let (options, problems) = options_from(init.initialization_options.as_ref());
    let mut server = Server {
        connection: &connection,
        ws: Workspace::new(options),
        dirty: HashSet::new(),
        reads: HashMap::new(),
        published: HashMap::new(),
        pending: VecDeque::new(),
        current: None,
        cancelled: HashSet::new(),
    };
    for p in problems {
        server.show_message(lt::MessageType::WARNING, format!("umbrac: {p}"));
    }
    server.main_loop()
}

struct Server<'a> {
    connection: &'a Connection,
    ws: Workspace,
    /// Open documents to check once no message waits.
    dirty: HashSet<PathBuf>,
    /// The files each open document's last check read.
    reads: HashMap<PathBuf, Vec<PathBuf>>,
    /// What was last published for each document: its own check's
    /// diagnostics with its version, and by root, those of the programs
    /// that include or require it, at their place in it.
    published: HashMap<PathBuf, Published>,
    /// Messages read off the connection but not yet handled (read ahead
    /// to see cancellations and newer versions), in order.
    pending: VecDeque<Message>,
    /// The request being answered.
    current: Option<RequestId>,
    /// Requests cancelled before they were answered.
    cancelled: HashSet<RequestId>,
}

#[derive(Default)]
struct Published {
    version: Option<i32>,
    own: Vec<lt::Diagnostic>,
    from_roots: HashMap<PathBuf, Vec<lt::Diagnostic>>,
}

impl Server<'_> {
    fn main_loop(&mut self) -> Result<()> {
        loop {
            let msg = match self.pending.pop_front() {
                Some(m) => m,
                None if self.dirty.is_empty() => match self.connection.receiver.recv() {
                    Ok(m) => {
                        self.take(m);
                        continue;
                    }
                    Err(_) => return Ok(()),
                },
                None => match self.connection.receiver.try_recv() {
                    Ok(m) => {
                        self.take(m);
                        continue;
                    }
                    Err(TryRecvError::Empty) => {
                        self.check_dirty()?;
                        continue;
                    }
                    Err(TryRecvError::Disconnected) => return Ok(()),
                },
            };
            match msg {
                Message::Request(req) if req.method == "shutdown" => {
                    self.connection.sender.send(Message::Response(Response::new_ok(req.id, ())))?;
                    return self.await_exit();
                }
                Message::Request(req) => {
                    self.current = Some(req.id.clone());
                    let resp = self.answer_unless_cancelled(req)?;
                    self.current = None;
                    self.connection.sender.send(Message::Response(resp))?;
                }
                Message::Notification(n) => {
                    // A bug while taking a notification in costs that notification, not the server.
                    let method = n.method.clone();
                    if let Err(payload) = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.notification(n))) {
                        self.show_message(lt::MessageType::ERROR, format!("umbrac panicked on `{method}`: {}", crate::diag::panic_message(&*payload)));
                    }
                }
                Message::Response(_) => {}
            }
        }
    }

    /// After `shutdown`: waits for `exit` (or the client hanging up).
    fn await_exit(&mut self) -> Result<()> {
        loop {
            let m = match self.pending.pop_front() {
                Some(m) => m,
                None => match self.connection.receiver.recv() {
                    Ok(m) => m,
                    Err(_) => return Ok(()),
                },
            };
            match m {
                Message::Notification(n) if n.method == "exit" => return Ok(()),
                Message::Request(r) => {
                    let resp = Response::new_err(r.id, ErrorCode::InvalidRequest as i32, "the server is shutting down".into());
                    self.connection.sender.send(Message::Response(resp))?;
                }
                _ => {}
            }
        }
    }

    /// A message read off the connection: a cancellation is noted (when
    /// its request is still to be answered), anything else waits its turn.
    fn take(&mut self, m: Message) {
        if let Message::Notification(n) = &m {
            if n.method == <lt::notification::Cancel as lt::notification::Notification>::METHOD {
                if let Ok(p) = serde_json::from_value::<lt::CancelParams>(n.params.clone()) {
                    let id = match p.id {
                        lt::NumberOrString::Number(n) => RequestId::from(n),
                        lt::NumberOrString::String(s) => RequestId::from(s),
                    };
                    let waiting = self.current.as_ref() == Some(&id) || self.pending.iter().any(|m| matches!(m, Message::Request(r) if r.id == id));
                    if waiting {
                        self.cancelled.insert(id);
                    }
                }
                return;
            }
        }
        self.pending.push_back(m);
    }

    /// Reads ahead every message already sent.
    fn read_ahead(&mut self) {
        while let Ok(m) = self.connection.receiver.try_recv() {
            self.take(m);
        }
    }

    /// Answers a request from analyses brought up to date, or with
    /// `RequestCanceled` when it was cancelled before or while they were.
    fn answer_unless_cancelled(&mut self, req: Request) -> Result<Response> {
        let canceled = |id: RequestId| Response::new_err(id, ErrorCode::RequestCanceled as i32, "cancelled".into());
        self.read_ahead();
        if self.cancelled.remove(&req.id) {
            return Ok(canceled(req.id));
        }
        // Queries answer from the last analysis: bring it up to date.
        self.check_dirty()?;
        self.read_ahead();
        if self.cancelled.remove(&req.id) {
            return Ok(canceled(req.id));
        }
        Ok(self.answer(req))
    }

    /// The documents a message read ahead changes, opens or closes: what
    /// is published of them now would be stale.
    fn superseded(&self) -> HashSet<PathBuf> {
        use lt::notification::{DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, Notification as _};
        self.pending
            .iter()
            .filter_map(|m| match m {
                Message::Notification(n) if [DidChangeTextDocument::METHOD, DidCloseTextDocument::METHOD, DidOpenTextDocument::METHOD].contains(&n.method.as_str()) => {
                    let uri: lt::Uri = serde_json::from_value(n.params.get("textDocument")?.get("uri")?.clone()).ok()?;
                    Some(crate::syntax::overlay::normalize(&path_of(&uri)?))
                }
                _ => None,
            })
            .collect()
    }

    /// Answers one request; a panic is an error response.
    fn answer(&mut self, req: Request) -> Response {
        let id = req.id.clone();
        let method = req.method.clone();
        let ws = &self.ws;
        match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| dispatch(ws, req))) {
            Ok(Ok(Some(value))) => Response { id, result: Some(value), error: None },
            Ok(Ok(None)) => Response { id, result: Some(serde_json::Value::Null), error: None },
            Ok(Err((code, msg))) => Response::new_err(id, code as i32, msg),
            Err(payload) => Response::new_err(id, ErrorCode::InternalError as i32, format!("umbrac panicked answering `{method}`: {}", crate::diag::panic_message(&*payload))),
        }
    }

    fn notification(&mut self, n: Notification) {
        use lt::notification::*;
        let path_of_doc = |uri: &lt::Uri| path_of(uri);
        match n.method.as_str() {
            DidOpenTextDocument::METHOD => {
                if let Ok(p) = serde_json::from_value::<lt::DidOpenTextDocumentParams>(n.params) {
                    if let Some(path) = path_of_doc(&p.text_document.uri) {
                        self.ws.set_document(&path, p.text_document.text, p.text_document.version);
                        self.changed(&path);
                    }
                }
            }
            DidChangeTextDocument::METHOD => {
                if let Ok(p) = serde_json::from_value::<lt::DidChangeTextDocumentParams>(n.params) {
                    // Full sync: the last change holds the whole text.
                    if let (Some(path), Some(change)) = (path_of_doc(&p.text_document.uri), p.content_changes.into_iter().last()) {
                        self.ws.set_document(&path, change.text, p.text_document.version);
                        self.changed(&path);
                    }
                }
            }
            DidCloseTextDocument::METHOD => {
                if let Ok(p) = serde_json::from_value::<lt::DidCloseTextDocumentParams>(n.params) {
                    if let Some(path) = path_of_doc(&p.text_document.uri) {
                        self.ws.close_document(&path);
                        self.ws.forget(&path);
                        let path = crate::syntax::overlay::normalize(&path);
                        self.dirty.remove(&path);
                        self.reads.remove(&path);
                        self.published.remove(&path);
                        for p in self.published.values_mut() {
                            p.from_roots.remove(&path);
                        }
                        // Its diagnostics go with it; the disk counts again for the others.
                        self.publish(&path, None, Vec::new());
                        self.changed(&path);
                    }
                }
            }
            DidSaveTextDocument::METHOD | DidChangeWatchedFiles::METHOD => {
                let docs: Vec<PathBuf> = self.ws.documents().map(Path::to_path_buf).collect();
                self.dirty.extend(docs);
            }
            _ => {}
        }
    }

    /// `path` changed: it and every open document that read it are checked again.
    fn changed(&mut self, path: &Path) {
        let path = crate::syntax::overlay::normalize(path);
        if self.ws.version(&path).is_some() {
            self.dirty.insert(path.clone());
        }
        for (doc, read) in &self.reads {
            if read.iter().any(|r| crate::syntax::overlay::normalize(r) == path) {
                self.dirty.insert(doc.clone());
            }
        }
    }

    fn check_dirty(&mut self) -> Result<()> {
        let mut dirty: Vec<PathBuf> = self.dirty.drain().collect();
        dirty.sort();
        // Published once all are checked: a document is never shown what
        // a program that includes it found in an older version of it.
        let mut touched: Vec<PathBuf> = Vec::new();
        for path in dirty {
            let Some(text) = self.ws.text(&path) else { continue };
            let checked = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.ws.check(&path))) {
                Ok(c) => c,
                Err(payload) => {
                    self.show_message(lt::MessageType::ERROR, format!("umbrac panicked checking `{}`: {}", path.display(), crate::diag::panic_message(&*payload)));
                    continue;
                }
            };
            self.reads.insert(path.clone(), checked.files_read.clone());
            let own = checked.diagnostics.iter().map(|d| to_lsp_diagnostic(d, &text, &self.ws)).collect();
            // Diagnostics inside other open documents also show there.
            let mut elsewhere: HashMap<PathBuf, Vec<lt::Diagnostic>> = HashMap::new();
            for d in &checked.diagnostics {
                let Some((file, start, end, message)) = &d.origin else { continue };
                let Some(t) = self.ws.version(file).and_then(|_| self.ws.text(file)) else { continue };
                let inner = workspace::FileDiagnostic { start: *start, end: *end, message: format!("{message}\n(in the program `{}`)", path.display()), origin: None, ..d.clone() };
                elsewhere.entry(file.clone()).or_default().push(to_lsp_diagnostic(&inner, &t, &self.ws));
            }
            touched.push(path.clone());
            for (file, p) in self.published.iter_mut() {
                if p.from_roots.remove(&path).is_some() {
                    touched.push(file.clone());
                }
            }
            for (file, diags) in elsewhere {
                self.published.entry(file.clone()).or_default().from_roots.insert(path.clone(), diags);
                touched.push(file);
            }
            let entry = self.published.entry(path.clone()).or_default();
            entry.own = own;
            entry.version = checked.version;
        }
        touched.sort();
        touched.dedup();
        // A document whose newer text waits is published once that is checked.
        let superseded = self.superseded();
        for file in touched.iter().filter(|f| !superseded.contains(*f)) {
            self.republish(file);
        }
        Ok(())
    }

    /// Publishes what is known of `path`: its own diagnostics and those
    /// the programs including it found in it, each once.
    fn republish(&self, path: &Path) {
        let Some(p) = self.published.get(path) else { return };
        let mut all = p.own.clone();
        let mut roots: Vec<_> = p.from_roots.iter().collect();
        roots.sort_by(|a, b| a.0.cmp(b.0));
        for d in roots.into_iter().flat_map(|(_, v)| v) {
            if !all.iter().any(|x| x.range == d.range && x.message.split('\n').next() == d.message.split('\n').next()) {
                all.push(d.clone());
            }
        }
        self.publish(path, self.ws.version(path).or(p.version), all);
    }

    fn publish(&self, path: &Path, version: Option<i32>, diagnostics: Vec<lt::Diagnostic>) {
        let Some(uri) = uri_of(path) else { return };
        let params = lt::PublishDiagnosticsParams { uri, diagnostics, version };
        let n = Notification::new(<lt::notification::PublishDiagnostics as lt::notification::Notification>::METHOD.to_string(), params);
        let _ = self.connection.sender.send(Message::Notification(n));
    }

    fn show_message(&self, typ: lt::MessageType, message: String) {
        let n = Notification::new(<lt::notification::ShowMessage as lt::notification::Notification>::METHOD.to_string(), lt::ShowMessageParams { typ, message });
        let _ = self.connection.sender.send(Message::Notification(n));
    }
}

type Answer = std::result::Result<Option<serde_json::Value>, (ErrorCode, String)>;

fn bad_params(e: impl std::fmt::Display) -> (ErrorCode, String) {
    (ErrorCode::InvalidParams, e.to_string())
}

/// The answer to one request, from the last analyses.
fn dispatch(ws: &Workspace, req: Request) -> Answer {
    use lt::request::*;
    let json = |v: serde_json::Value| Ok(Some(v));
    match req.method.as_str() {
        HoverRequest::METHOD => {
            let p: lt::HoverParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some((path, index, offset)) = locate(ws, &p.text_document_position_params) else { return Ok(None) };
            let Some(h) = index.hover(&path, offset) else { return Ok(None) };
            let text = index.text(&path).unwrap_or("");
            let hover = lt::Hover {
                contents: lt::HoverContents::Markup(lt::MarkupContent { kind: lt::MarkupKind::Markdown, value: h.text }),
                range: Some(range(text, h.start, h.end)),
            };
            json(serde_json::to_value(hover).map_err(bad_params)?)
        }
        GotoDefinition::METHOD => {
            let p: lt::GotoDefinitionParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some((path, index, offset)) = locate(ws, &p.text_document_position_params) else { return Ok(None) };
            let Some(loc) = index.definition(&path, offset).and_then(|l| location(&index, &l)) else { return Ok(None) };
            json(serde_json::to_value(lt::GotoDefinitionResponse::Scalar(loc)).map_err(bad_params)?)
        }
        References::METHOD => {
            let p: lt::ReferenceParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some((path, index, offset)) = locate(ws, &p.text_document_position) else { return Ok(None) };
            let locs: Vec<lt::Location> = index.references(&path, offset, p.context.include_declaration).iter().filter_map(|l| location(&index, l)).collect();
            json(serde_json::to_value(locs).map_err(bad_params)?)
        }
        DocumentSymbolRequest::METHOD => {
            let p: lt::DocumentSymbolParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some(path) = path_of(&p.text_document.uri) else { return Ok(None) };
            let Some(index) = ws.index(&path) else { return json(serde_json::json!([])) };
            let text = index.text(&path).unwrap_or("");
            #[allow(deprecated)] // `deprecated` is a field the type requires
            let symbols: Vec<lt::DocumentSymbol> = index
                .symbols(&path)
                .into_iter()
                .map(|s| lt::DocumentSymbol {
                    name: s.name,
                    detail: Some(s.detail),
                    kind: match s.kind {
                        workspace::SymbolKind::EntryPoint => lt::SymbolKind::EVENT,
                        workspace::SymbolKind::Function => lt::SymbolKind::FUNCTION,
                        workspace::SymbolKind::Global => lt::SymbolKind::VARIABLE,
                        workspace::SymbolKind::Constant => lt::SymbolKind::CONSTANT,
                        workspace::SymbolKind::Struct => lt::SymbolKind::STRUCT,
                    },
                    tags: None,
                    deprecated: None,
                    range: range(text, s.start, s.end),
                    selection_range: range(text, s.start, s.end),
                    children: None,
                })
                .collect();
            json(serde_json::to_value(lt::DocumentSymbolResponse::Nested(symbols)).map_err(bad_params)?)
        }
        Rename::METHOD => {
            let p: lt::RenameParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let refused = |msg: String| (ErrorCode::RequestFailed, format!("cannot rename: {msg}"));
            let Some((path, index, offset)) = locate(ws, &p.text_document_position) else { return Err(refused("the file has not been checked".into())) };
            let locs = index.rename(&path, offset, &p.new_name).map_err(refused)?;
            // `WorkspaceEdit::changes` is keyed by `Uri`, whose parse cache clippy calls mutable.
            #[allow(clippy::mutable_key_type)]
            let mut changes: HashMap<lt::Uri, Vec<lt::TextEdit>> = HashMap::new();
            for l in &locs {
                // Edits are made against the text that was analysed.
                if ws.text(&l.path).as_deref() != index.text(&l.path) {
                    return Err(refused(format!("`{}` changed since it last compiled without errors", l.path.display())));
                }
                let loc = location(&index, l).ok_or_else(|| refused(format!("`{}` has no URI", l.path.display())))?;
                changes.entry(loc.uri).or_default().push(lt::TextEdit { range: loc.range, new_text: p.new_name.clone() });
            }
            json(serde_json::to_value(lt::WorkspaceEdit { changes: Some(changes), ..Default::default() }).map_err(bad_params)?)
        }
        Completion::METHOD => {
            let p: lt::CompletionParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let tdp = &p.text_document_position;
            let Some(path) = path_of(&tdp.text_document.uri) else { return Ok(None) };
            let (Some(index), Some(text)) = (ws.index(&path), ws.text(&path)) else { return Ok(None) };
            let offset = workspace::position_to_offset(&text, tdp.position.line, tdp.position.character);
            let (here, builtins) = index.completions_here(&path, &text, offset);
            let mut items: Vec<serde_json::Value> = here.iter().map(completion_item).collect();
            if builtins {
                // The builtins, the same in every answer, as JSON once.
                static BUILTINS: std::sync::OnceLock<Vec<serde_json::Value>> = std::sync::OnceLock::new();
                items.extend(BUILTINS.get_or_init(|| workspace::builtin_completions().iter().map(completion_item).collect()).iter().cloned());
            }
            json(serde_json::Value::Array(items))
        }
        InlayHintRequest::METHOD => {
            let p: lt::InlayHintParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some(path) = path_of(&p.text_document.uri) else { return Ok(None) };
            let Some(index) = ws.index(&path) else { return Ok(None) };
            // Hints sit in the text that was analysed: none while it differs.
            if ws.text(&path).as_deref() != index.text(&path) {
                return json(serde_json::json!([]));
            }
            let text = index.text(&path).unwrap_or("");
            let hints: Vec<lt::InlayHint> = index
                .inlay_hints(&path)
                .into_iter()
                .map(|(at, label)| lt::InlayHint {
                    position: range(text, at, at).start,
                    label: lt::InlayHintLabel::String(label),
                    kind: Some(lt::InlayHintKind::TYPE),
                    text_edits: None,
                    tooltip: None,
                    padding_left: None,
                    padding_right: None,
                    data: None,
                })
                .collect();
            json(serde_json::to_value(hints).map_err(bad_params)?)
        }
        SemanticTokensFullRequest::METHOD => {
            let p: lt::SemanticTokensParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some(path) = path_of(&p.text_document.uri) else { return Ok(None) };
            let Some(index) = ws.index(&path) else { return Ok(None) };
            // Positions are in the analysed text: nothing while the document differs.
            if ws.text(&path).as_deref() != index.text(&path) {
                return Ok(None);
            }
            let text = index.text(&path).unwrap_or("");
            let mut data = Vec::new();
            let (mut line, mut col) = (0, 0);
            for t in index.semantic_tokens(&path) {
                let (l, c) = workspace::offset_to_position(text, t.start);
                let (el, ec) = workspace::offset_to_position(text, t.end);
                if el != l {
                    continue;
                }
                let (token_type, token_modifiers_bitset) = token_type(&t);
                let delta_start = if l == line { c - col } else { c };
                data.push(lt::SemanticToken { delta_line: l - line, delta_start, length: ec - c, token_type, token_modifiers_bitset });
                (line, col) = (l, c);
            }
            json(serde_json::to_value(lt::SemanticTokens { result_id: None, data }).map_err(bad_params)?)
        }
        SignatureHelpRequest::METHOD => {
            let p: lt::SignatureHelpParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let tdp = &p.text_document_position_params;
            let Some(path) = path_of(&tdp.text_document.uri) else { return Ok(None) };
            let (Some(index), Some(text)) = (ws.index(&path), ws.text(&path)) else { return Ok(None) };
            let offset = workspace::position_to_offset(&text, tdp.position.line, tdp.position.character);
            let Some((sigs, active)) = index.signature_help(&text, offset) else { return Ok(None) };
            let signatures = sigs
                .into_iter()
                .map(|(label, params)| {
                    let name = label.split('(').next().unwrap_or("");
                    let documentation = crate::sema::builtin_docs::meaning(name).filter(|_| crate::sema::builtins::signatures(name).iter().any(|(l, _)| *l == label)).map(|m| lt::Documentation::String(m.to_string()));
                    // Parameters by their place in the label: `floatN, floatN` names two.
                    let mut from = label.find('(').map_or(0, |i| i + 1);
                    let parameters = params
                        .into_iter()
                        .map(|p| {
                            let at = label[from..].find(&p).map(|i| i + from);
                            let plabel = match at {
                                Some(s) => {
                                    from = s + p.len();
                                    let utf16 = |b: usize| label[..b].encode_utf16().count() as u32;
                                    lt::ParameterLabel::LabelOffsets([utf16(s), utf16(s + p.len())])
                                }
                                None => lt::ParameterLabel::Simple(p),
                            };
                            lt::ParameterInformation { label: plabel, documentation: None }
                        })
                        .collect();
                    lt::SignatureInformation { label, documentation, parameters: Some(parameters), active_parameter: None }
                })
                .collect();
            json(serde_json::to_value(lt::SignatureHelp { signatures, active_signature: Some(0), active_parameter: Some(active as u32) }).map_err(bad_params)?)
        }
        CodeActionRequest::METHOD => {
            let p: lt::CodeActionParams = serde_json::from_value(req.params).map_err(bad_params)?;
            let Some(text) = path_of(&p.text_document.uri).and_then(|path| ws.text(&path)) else { return Ok(None) };
            let mut actions = Vec::new();
            for d in p.context.diagnostics.iter().filter(|d| d.source.as_deref() == Some("umbrac")) {
                let Some(fix) = did_you_mean(&d.message) else { continue };
                // Only where the diagnostic covers a name (not an `#include` line).
                let (s, e) = (workspace::position_to_offset(&text, d.range.start.line, d.range.start.character), workspace::position_to_offset(&text, d.range.end.line, d.range.end.character));
                let name = text.get(s..e).unwrap_or("");
                if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                    continue;
                }
                let edit = lt::TextEdit { range: d.range, new_text: fix.to_string() };
                actions.push(lt::CodeActionOrCommand::CodeAction(lt::CodeAction {
                    title: format!("Replace `{name}` with `{fix}`"),
                    kind: Some(lt::CodeActionKind::QUICKFIX),
                    diagnostics: Some(vec![d.clone()]),
                    edit: Some(lt::WorkspaceEdit { changes: Some([(p.text_document.uri.clone(), vec![edit])].into_iter().collect()), ..Default::default() }),
                    is_preferred: Some(true),
                    ..Default::default()
                }));
            }
            json(serde_json::to_value(actions).map_err(bad_params)?)
        }
        ExecuteCommand::METHOD => {
            let p: lt::ExecuteCommandParams = serde_json::from_value(req.params).map_err(bad_params)?;
            if p.command != OUTPUT_COMMAND {
                return Err((ErrorCode::InvalidParams, format!("umbrac has no command `{}`", p.command)));
            }
            let arg = |i: usize| p.arguments.get(i).and_then(|v| v.as_str());
            let usage = || bad_params(format!("`{OUTPUT_COMMAND}` takes [URI, TARGET]"));
            let uri: lt::Uri = arg(0).ok_or_else(usage)?.parse().map_err(|_| usage())?;
            let path = path_of(&uri).ok_or_else(|| bad_params(format!("`{}` is not a file", uri.as_str())))?;
            let target = arg(1).and_then(Target::from_name).ok_or_else(usage)?;
            match ws.output(&path, target) {
                Ok(files) => json(serde_json::json!({ "files": files.into_iter().map(|(name, text)| serde_json::json!({"name": name, "text": text})).collect::<Vec<_>>() })),
                Err(diags) => {
                    let first = diags.iter().find(|d| matches!(d.severity, Severity::Error | Severity::Bug)).or(diags.first()).map_or("it does not compile".to_string(), |d| d.message.clone());
                    Err((ErrorCode::RequestFailed, format!("no {} output: {first}", target.name())))
                }
            }
        }
        other => Err((ErrorCode::MethodNotFound, format!("umbrac does not answer `{other}`"))),
    }
}

/// A completion as the protocol's `CompletionItem`, in JSON.
fn completion_item(c: &workspace::Completion) -> serde_json::Value {
    let kind = match c.kind {
        workspace::CompletionKind::Local | workspace::CompletionKind::Global => lt::CompletionItemKind::VARIABLE,
        workspace::CompletionKind::Constant => lt::CompletionItemKind::CONSTANT,
        workspace::CompletionKind::Function | workspace::CompletionKind::Builtin => lt::CompletionItemKind::FUNCTION,
        workspace::CompletionKind::Struct => lt::CompletionItemKind::STRUCT,
        workspace::CompletionKind::Field => lt::CompletionItemKind::FIELD,
        workspace::CompletionKind::Annotation => lt::CompletionItemKind::KEYWORD,
        workspace::CompletionKind::Type => lt::CompletionItemKind::TYPE_PARAMETER,
    };
    serde_json::json!({ "label": c.label, "kind": kind, "detail": c.detail })
}

/// The name a diagnostic's "help: did you mean `NAME`?" suggests.
fn did_you_mean(message: &str) -> Option<&str> {
    let rest = &message[message.find("did you mean `")? + "did you mean `".len()..];
    let name = &rest[..rest.find('`')?];
    (!name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')).then_some(name)
}

/// The file, its last analysis and the byte offset a position names.
fn locate(ws: &Workspace, p: &lt::TextDocumentPositionParams) -> Option<(PathBuf, std::sync::Arc<workspace::Index>, usize)> {
    let path = path_of(&p.text_document.uri)?;
    let index = ws.index(&path)?;
    let offset = workspace::position_to_offset(index.text(&path)?, p.position.line, p.position.character);
    Some((path, index, offset))
}

fn range(text: &str, start: usize, end: usize) -> lt::Range {
    let pos = |o| {
        let (line, character) = workspace::offset_to_position(text, o);
        lt::Position { line, character }
    };
    lt::Range { start: pos(start), end: pos(end) }
}

fn location(index: &workspace::Index, l: &workspace::Location) -> Option<lt::Location> {
    Some(lt::Location { uri: uri_of(&l.path)?, range: range(index.text(&l.path)?, l.start, l.end) })
}

fn to_lsp_diagnostic(d: &workspace::FileDiagnostic, text: &str, ws: &Workspace) -> lt::Diagnostic {
    let related: Vec<lt::DiagnosticRelatedInformation> = d
        .related
        .iter()
        .filter_map(|(path, s, e, msg)| {
            let t = ws.text(path)?;
            Some(lt::DiagnosticRelatedInformation { location: lt::Location { uri: uri_of(path)?, range: range(&t, *s, *e) }, message: msg.clone() })
        })
        .collect();
    lt::Diagnostic {
        range: range(text, d.start, d.end),
        severity: Some(match d.severity {
            Severity::Warning => lt::DiagnosticSeverity::WARNING,
            Severity::Error | Severity::Bug => lt::DiagnosticSeverity::ERROR,
            Severity::Note => lt::DiagnosticSeverity::INFORMATION,
        }),
        source: Some("umbrac".into()),
        message: d.message.clone(),
        related_information: (!related.is_empty()).then_some(related),
        ..Default::default()
    }
}

/// Options from `initializationOptions`:
/// `{"targets": ["wgsl", ...], "includeDirs": [...], "daslangRoot": "...",
/// "daslib": "...", "modules": {"PREFIX": "DIR"}, "defines": ["NAME",
/// "NAME=VALUE"] | {"NAME": "VALUE"}, "limits": {"NAME": N},
/// "strictLimits": true}`, and what in them was not understood. They are
/// laid over each file's project file ([`crate::project::Project::under`]).
pub fn options_from(v: Option<&serde_json::Value>) -> (Options, Vec<String>) {
    let mut opts = Options::default();
    let mut problems = Vec::new();
    let Some(v) = v.and_then(|v| v.as_object()) else { return (opts, problems) };
    let strings = |key: &str| -> Vec<String> { v.get(key).and_then(|x| x.as_array()).into_iter().flatten().filter_map(|s| s.as_str().map(String::from)).collect() };
    for t in strings("targets") {
        match Target::from_name(&t) {
            Some(t) => opts.targets.push(t),
            None => problems.push(format!("unknown target `{t}` in initializationOptions.targets")),
        }
    }
    opts.include_dirs = strings("includeDirs").into_iter().map(PathBuf::from).collect();
    opts.daslang_root = v.get("daslangRoot").and_then(|x| x.as_str()).map(PathBuf::from);
    opts.daslib = v.get("daslib").and_then(|x| x.as_str()).map(PathBuf::from);
    if let Some(m) = v.get("modules").and_then(|x| x.as_object()) {
        opts.modules = m.iter().filter_map(|(prefix, dir)| Some((prefix.clone(), PathBuf::from(dir.as_str()?)))).collect();
    }
    if let Some(m) = v.get("limits").and_then(|x| x.as_object()) {
        for (name, n) in m {
            match (crate::Limit::from_name(name), n.as_u64()) {
                (Some(l), Some(n)) => opts.limits.push((l, n)),
                _ => problems.push(format!("initializationOptions.limits: `{name}` = {n} is not a limit and a count")),
            }
        }
    }
    opts.strict_limits = v.get("strictLimits").and_then(|x| x.as_bool()).unwrap_or(false);
    match v.get("defines") {
        Some(serde_json::Value::Object(m)) => {
            opts.defines = m.iter().map(|(k, val)| (k.clone(), val.as_str().map(String::from).or_else(|| (!val.is_null()).then(|| val.to_string())))).collect();
        }
        Some(serde_json::Value::Array(_)) => {
            opts.defines = strings("defines")
                .into_iter()
                .map(|d| match d.split_once('=') {
                    Some((n, v)) => (n.to_string(), Some(v.to_string())),
                    None => (d, None),
                })
                .collect();
        }
        Some(_) => problems.push("initializationOptions.defines is neither a list nor an object".into()),
        None => {}
    }
    (opts, problems)
}

/// The path of a `file:` URI (percent-decoded); `None` for other schemes.
pub fn path_of(uri: &lt::Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    let bytes = rest.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let Ok(b) = u8::from_str_radix(std::str::from_utf8(&bytes[i + 1..i + 3]).ok()?, 16) {
                out.push(b);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    let s = String::from_utf8(out).ok()?;
    // `file://host/path`: only the local host.
    let s = if s.starts_with('/') { s } else { s.strip_prefix("localhost")?.to_string() };
    Some(PathBuf::from(s))
}

/// The `file:` URI of an absolute path.
pub fn uri_of(path: &Path) -> Option<lt::Uri> {
    let mut s = String::from("file://");
    for b in path.to_str()?.bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    s.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_and_paths_round_trip() {
        let p = Path::new("/tmp/a b/ü#.das");
        let u = uri_of(p).unwrap();
        assert_eq!(u.as_str(), "file:///tmp/a%20b/%C3%BC%23.das");
        assert_eq!(path_of(&u).unwrap(), p);
        assert_eq!(path_of(&"untitled:x".parse().unwrap()), None);
    }

    #[test]
    fn options_read_and_complain() {
        let v = serde_json::json!({"targets": ["wgsl", "dx12"], "includeDirs": ["inc"], "defines": ["A", "B=2"]});
        let (o, problems) = options_from(Some(&v));
        assert_eq!(o.targets, [Target::Wgsl]);
        assert_eq!(o.include_dirs, [PathBuf::from("inc")]);
        assert_eq!(o.defines, [("A".to_string(), None), ("B".to_string(), Some("2".to_string()))]);
        assert_eq!(problems.len(), 1, "{problems:?}");
    }
}
