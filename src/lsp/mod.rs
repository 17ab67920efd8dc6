//! `sinuprep lsp`: the language server, over stdio with `lsp-server`
//! (synchronous: rust-analyzer's and ruff's choice). It holds the open
//! documents and turns the protocol's requests into the library's calls and
//! the answers back (`answers`, `convert`); every finding and every answer
//! comes from the same analysis as `check` and `eval`. The main loop takes
//! the messages in order; the findings are made by a worker, and a request
//! that must wait for a document's analysis, or work through the whole
//! program (a hover's walk, the words' classes), is answered on a thread of
//! its own, so that a large document holds up no other. It writes protocol messages only to stdout; what it has to
//! say otherwise goes to stderr.

// `lsp_types::Uri` caches its parsed parts in a `Cell`; its `Hash` and `Eq`
// read only its text, so it is a sound key.
#![allow(clippy::mutable_key_type)]

mod across_files;
mod answers;
mod completion;
mod convert;
mod cursor;
mod formatting;
mod requests;
mod rule_pages;
mod signature;
mod tokens_sent;
mod transport;
mod worker;
mod workspace_symbols;
mod workspace_uses;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::time::Duration;

use crossbeam_channel::RecvTimeoutError;

use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types as lsp;
use lsp_types::notification::Notification as _;
use lsp_types::request::Request as _;

use crate::document::held::Held;
use crate::document::text::Text;
use crate::lint::Settings;
use crate::span::ColumnUnit;
use crate::workspace::{Given, Workspace};

use answers::Snapshot;

/// Serves one client on stdin and stdout until it says `exit`.
pub fn run() -> Result<(), String> {
    let (connection, transport) = transport::stdio();
    let served = serve(&connection);
    drop(connection);
    let joined = transport.join().map_err(|e| e.to_string());
    joined.and(served)
}

fn serve(connection: &Connection) -> Result<(), String> {
    let (id, raw) = connection.initialize_start().map_err(|e| e.to_string())?;
    let supports = ClientSupports::of(&raw);
    let params: lsp::InitializeParams =
        serde_json::from_value(raw).map_err(|e| format!("initialize: {e}"))?;
    let (encoding, unit) = convert::encoding(&params.capabilities);
    // A client that asks for diagnostics is answered, not also pushed to:
    // it would show each finding twice.
    let pull = params
        .capabilities
        .text_document
        .as_ref()
        .is_some_and(|text| text.diagnostic.is_some());
    let capabilities = lsp::ServerCapabilities {
        position_encoding: Some(encoding),
        text_document_sync: Some(lsp::TextDocumentSyncCapability::Options(
            lsp::TextDocumentSyncOptions {
                open_close: Some(true),
                change: Some(lsp::TextDocumentSyncKind::INCREMENTAL),
                save: Some(lsp::TextDocumentSyncSaveOptions::Supported(true)),
                ..lsp::TextDocumentSyncOptions::default()
            },
        )),
        hover_provider: Some(lsp::HoverProviderCapability::Simple(true)),
        completion_provider: Some(lsp::CompletionOptions {
            trigger_characters: Some(vec!["$".to_string()]),
            ..lsp::CompletionOptions::default()
        }),
        signature_help_provider: Some(lsp::SignatureHelpOptions {
            trigger_characters: Some(vec!["(".to_string(), ",".to_string()]),
            retrigger_characters: None,
            work_done_progress_options: lsp::WorkDoneProgressOptions::default(),
        }),
        definition_provider: Some(lsp::OneOf::Left(true)),
        references_provider: Some(lsp::OneOf::Left(true)),
        document_symbol_provider: Some(lsp::OneOf::Left(true)),
        folding_range_provider: Some(lsp::FoldingRangeProviderCapability::Simple(true)),
        code_action_provider: Some(lsp::CodeActionProviderCapability::Options(
            lsp::CodeActionOptions {
                code_action_kinds: Some(vec![
                    lsp::CodeActionKind::QUICKFIX,
                    lsp::CodeActionKind::REFACTOR_REWRITE,
                    lsp::CodeActionKind::new(answers::FIX_ALL),
                ]),
                ..lsp::CodeActionOptions::default()
            },
        )),
        rename_provider: Some(lsp::OneOf::Right(lsp::RenameOptions {
            prepare_provider: Some(true),
            work_done_progress_options: lsp::WorkDoneProgressOptions::default(),
        })),
        inlay_hint_provider: Some(lsp::OneOf::Left(true)),
        workspace_symbol_provider: Some(lsp::OneOf::Left(true)),
        semantic_tokens_provider: Some(
            lsp::SemanticTokensServerCapabilities::SemanticTokensOptions(
                lsp::SemanticTokensOptions {
                    legend: convert::legend(),
                    full: Some(lsp::SemanticTokensFullOptions::Delta { delta: Some(true) }),
                    range: Some(true),
                    work_done_progress_options: lsp::WorkDoneProgressOptions::default(),
                },
            ),
        ),
        document_formatting_provider: Some(lsp::OneOf::Left(true)),
        document_range_formatting_provider: Some(lsp::OneOf::Left(true)),
        diagnostic_provider: pull.then(|| {
            lsp::DiagnosticServerCapabilities::Options(lsp::DiagnosticOptions {
                identifier: Some("sinuprep".to_string()),
                // HEAD_DEF, definition files and settings are other files.
                inter_file_dependencies: true,
                workspace_diagnostics: false,
                work_done_progress_options: lsp::WorkDoneProgressOptions::default(),
            })
        }),
        ..lsp::ServerCapabilities::default()
    };
    let initialized = serde_json::json!({
        "capabilities": capabilities,
        "serverInfo": { "name": "sinuprep", "version": env!("CARGO_PKG_VERSION") },
    });
    connection
        .initialize_finish(id, initialized)
        .map_err(|e| e.to_string())?;
    let mut server = Server {
        connection,
        documents: HashMap::new(),
        workspace: Workspace::with_buffers(Given::default(), HashMap::new()),
        settings_errors: HashSet::new(),
        refreshes: 0,
        settings_changed: false,
        unit,
        pull,
        supports,
        worker: (!pull).then(|| worker::Worker::start(connection.sender.clone())),
        requests: requests::Requests::start(connection.sender.clone()),
        tokens_sent: Arc::default(),
    };
    let served = serve_messages(&mut server);
    // What is queued is published before the connection closes.
    if let Some(worker) = server.worker.take() {
        worker.finish();
    }
    served
}

/// How long the typing in a file the settings read pauses before the
/// settings are read again.
const SETTLED: Duration = Duration::from_millis(250);

/// The messages of the session, until `exit` or the end of the input.
fn serve_messages(server: &mut Server) -> Result<(), String> {
    let connection = server.connection;
    // After `shutdown` the protocol allows only `exit`; a client that
    // closes the connection instead has still ended the session in order.
    let mut shut_down = false;
    loop {
        let received = match server.settings_changed {
            true => connection.receiver.recv_timeout(SETTLED),
            false => (connection.receiver.recv()).map_err(|_| RecvTimeoutError::Disconnected),
        };
        let message = match received {
            Ok(message) => message,
            Err(RecvTimeoutError::Timeout) => {
                server.refresh_settings();
                continue;
            }
            Err(RecvTimeoutError::Disconnected) => break,
        };
        match message {
            Message::Request(request) if shut_down => {
                let refused = "the server is shut down: only `exit` is expected".to_string();
                let code = ErrorCode::InvalidRequest as i32;
                server.send(Message::Response(Response::new_err(
                    request.id, code, refused,
                )));
            }
            Message::Request(request) if request.method == lsp::request::Shutdown::METHOD => {
                shut_down = true;
                server.send(Message::Response(Response::new_ok(request.id, ())));
            }
            Message::Request(request) => {
                if server.settings_changed && !server.is_about_settings(&request) {
                    server.refresh_settings();
                }
                server.request(request);
            }
            Message::Notification(notification)
                if notification.method == lsp::notification::Exit::METHOD =>
            {
                return match shut_down {
                    true => Ok(()),
                    false => Err("`exit` before `shutdown`".to_string()),
                };
            }
            Message::Notification(notification) => server.notification(notification),
            Message::Response(_) => {}
        }
    }
    match shut_down {
        true => Ok(()),
        false => Err("the client closed the connection without `shutdown`".to_string()),
    }
}

/// A document the client has open; shared with the worker that publishes
/// its findings.
#[derive(Clone)]
struct Open {
    /// Its text, and the analysis every request about this version reads.
    held: Arc<Held>,
    /// The path or URI its settings are found by and its findings named by.
    name: Arc<str>,
    settings: Arc<Settings>,
    /// Why its settings could not be read: it is then not checked, and
    /// its findings say only that.
    refused: Option<Arc<str>>,
}

impl Open {
    /// The held document, to be changed: the worker's copy, if it still
    /// reads one, keeps the old text, and stops analysing it.
    fn take_held(held: Arc<Held>) -> Held {
        Arc::try_unwrap(held).unwrap_or_else(|shared| {
            shared.stop();
            Held::open(shared.text().clone())
        })
    }

    /// Answers from this version's analysis, made by the first question;
    /// `None` for a version another took the place of before its analysis
    /// was made.
    fn with_snapshot<R>(&self, unit: ColumnUnit, answer: impl FnOnce(&Snapshot) -> R) -> Option<R> {
        self.held
            .with_analysis(&self.name, &self.settings, |analysis| {
                let refused = self.refused.as_deref();
                answer(&Snapshot::new(
                    analysis,
                    &self.name,
                    &self.settings,
                    unit,
                    refused,
                ))
            })
    }
}

struct Server<'c> {
    connection: &'c Connection,
    documents: HashMap<lsp::Uri, Open>,
    /// Settings files, HEAD_DEF and definitions read so far: read again
    /// when the client saves or changes a file.
    workspace: Workspace,
    unit: ColumnUnit,
    /// The client pulls diagnostics (`textDocument/diagnostic`).
    pull: bool,
    /// What the client takes beyond the protocol's minimum.
    supports: ClientSupports,
    /// The files a settings error was published on (a broken
    /// sinuprep.toml): cleared when the settings read again.
    settings_errors: HashSet<lsp::Uri>,
    /// `workspace/diagnostic/refresh` requests sent, for their ids.
    refreshes: u64,
    /// A file the settings read was changed in the editor and not yet read
    /// again: it is once the typing pauses ([`SETTLED`]), or before a
    /// request about another document is answered.
    settings_changed: bool,
    /// Publishes the findings of the documents that change (none for a
    /// client that pulls them).
    worker: Option<worker::Worker>,
    /// Answers the requests that wait for an analysis or work of their own.
    requests: requests::Requests,
    /// The semantic tokens last sent per document, for a delta from them.
    tokens_sent: Arc<tokens_sent::TokensSent>,
}

impl Server<'_> {
    fn send(&self, message: Message) {
        // A client gone away ends the loop through the receiver.
        let _ = self.connection.sender.send(message);
    }

    fn notification(&mut self, notification: Notification) {
        use lsp::notification as n;
        match notification.method.as_str() {
            n::Cancel::METHOD => {
                if let Some(params) = extract::<lsp::CancelParams>(notification) {
                    let id = match params.id {
                        lsp::NumberOrString::Number(n) => lsp_server::RequestId::from(n),
                        lsp::NumberOrString::String(s) => lsp_server::RequestId::from(s),
                    };
                    self.requests.cancel(id);
                }
            }
            n::DidOpenTextDocument::METHOD => {
                if let Some(params) = extract::<lsp::DidOpenTextDocumentParams>(notification) {
                    let document = params.text_document;
                    let text = Text::new(document.text.into_bytes());
                    let reads_settings = self.is_read_by_settings(&document.uri);
                    self.open(document.uri, Held::open(text));
                    if reads_settings {
                        self.refresh_settings();
                    }
                }
            }
            n::DidChangeTextDocument::METHOD => {
                if let Some(params) = extract::<lsp::DidChangeTextDocumentParams>(notification) {
                    self.change(params);
                }
            }
            n::DidCloseTextDocument::METHOD => {
                if let Some(params) = extract::<lsp::DidCloseTextDocumentParams>(notification) {
                    let uri = params.text_document.uri;
                    self.documents.remove(&uri);
                    self.tokens_sent.forget(&uri);
                    // Its findings cleared, after any still queued.
                    if let Some(worker) = &self.worker {
                        let (uri, unit) = (uri.clone(), self.unit);
                        worker.publish(worker::Job {
                            uri,
                            open: None,
                            unit,
                        });
                    }
                    // Its unsaved text no longer counts: the file does.
                    if self.is_read_by_settings(&uri) {
                        self.refresh_settings();
                    }
                }
            }
            // A saved or changed file may be a settings file, a HEAD_DEF or
            // a definition file that every open document reads.
            n::DidSaveTextDocument::METHOD | n::DidChangeWatchedFiles::METHOD => {
                self.refresh_settings();
            }
            _ => {}
        }
    }

    /// Whether the document at `uri` is a file the settings were read from
    /// (sinuprep.toml, HEAD_DEF, definitions, machine, values, a subprogram).
    fn is_read_by_settings(&self, uri: &lsp::Uri) -> bool {
        convert::path(uri).is_some_and(|path| self.workspace.has_read(&path))
    }

    /// Whether `request` is about a document the settings read (a keystroke's
    /// requests on the file being typed), which it may answer before the
    /// settings are read again.
    fn is_about_settings(&self, request: &Request) -> bool {
        let uri = request.params["textDocument"]["uri"].as_str();
        uri.and_then(|uri| uri.parse::<lsp::Uri>().ok())
            .is_some_and(|uri| self.is_read_by_settings(&uri))
    }

    /// Reads the settings of every open document again, the open
    /// documents' unsaved text in place of their files, and reports anew.
    fn refresh_settings(&mut self) {
        self.settings_changed = false;
        self.workspace = Workspace::with_buffers(Given::default(), self.buffers());
        let published = std::mem::take(&mut self.settings_errors);
        let open: Vec<(lsp::Uri, Held)> = self
            .documents
            .drain()
            .map(|(uri, open)| (uri, Open::take_held(open.held).forget()))
            .collect();
        for (uri, held) in open {
            self.open(uri, held);
        }
        for mended in published.difference(&self.settings_errors) {
            if !self.documents.contains_key(mended) {
                self.publish_on(mended.clone(), Vec::new());
            }
        }
        // A client that pulls asks again, where it lets the server say so.
        if self.pull && self.supports.diagnostic_refresh {
            self.refreshes += 1;
            let id = format!("sinuprep-refresh-{}", self.refreshes);
            let method = lsp::request::WorkspaceDiagnosticRefresh::METHOD.to_string();
            self.send(Message::Request(Request::new(id.into(), method, ())));
        }
    }

    /// The open documents' texts by path, in place of their files.
    fn buffers(&self) -> workspace_uses::Buffers {
        self.documents
            .iter()
            .filter_map(|(uri, open)| {
                let path = convert::path(uri)?;
                Some((path, Arc::from(open.held.text().bytes())))
            })
            .collect()
    }

    /// Pushes `diagnostics` for `uri` from here (a file the worker does not
    /// check: a settings file).
    fn publish_on(&self, uri: lsp::Uri, diagnostics: Vec<lsp::Diagnostic>) {
        let params = lsp::PublishDiagnosticsParams::new(uri, diagnostics, None);
        let method = lsp::notification::PublishDiagnostics::METHOD.to_string();
        self.send(Message::Notification(Notification::new(method, params)));
    }

    fn open(&mut self, uri: lsp::Uri, held: Held) {
        let path = convert::path(&uri);
        let (settings, refused) = match path.as_deref().map(|p| self.workspace.for_check(p)) {
            Some(Ok(resolved)) => (resolved.settings, None),
            Some(Err(error)) => (Settings::default(), Some(self.settings_error(&error))),
            None => (Settings::default(), None),
        };
        let name = path.map_or_else(
            || uri.as_str().to_string(),
            |p| p.to_string_lossy().into_owned(),
        );
        let open = Open {
            held: Arc::new(held),
            name: name.into(),
            settings: Arc::new(settings),
            refused,
        };
        self.documents.insert(uri.clone(), open);
        self.publish(uri);
    }

    /// What a program whose settings cannot be read is told, as `check`
    /// would say it; the error is also published on the file it is in.
    fn settings_error(&mut self, error: &crate::workspace::SettingsError) -> Arc<str> {
        use miette::Diagnostic as _;
        let help = error.help().map(|h| format!("\n\n{h}")).unwrap_or_default();
        let said = format!("{error}{help}");
        let file = error.place().and_then(|(path, line, _)| {
            let uri = convert::uri(path)?;
            Some((uri, line))
        });
        if let Some((uri, line)) = file {
            // The whole line: the column's unit is not the client's.
            let row = u32::try_from(line.saturating_sub(1)).unwrap_or(u32::MAX);
            let diagnostic = lsp::Diagnostic {
                range: lsp::Range::new(lsp::Position::new(row, 0), lsp::Position::new(row + 1, 0)),
                severity: Some(lsp::DiagnosticSeverity::ERROR),
                source: Some("sinuprep".to_string()),
                message: said.clone(),
                ..lsp::Diagnostic::default()
            };
            // Once a reading, and not on an open document: its own findings
            // (this error) are the worker's to publish.
            if !self.documents.contains_key(&uri) && self.settings_errors.insert(uri.clone()) {
                self.publish_on(uri, vec![diagnostic]);
            }
        }
        format!("the settings cannot be read, so this file is not checked: {said}").into()
    }

    fn change(&mut self, params: lsp::DidChangeTextDocumentParams) {
        let uri = params.text_document.uri;
        let Some(mut open) = self.documents.remove(&uri) else {
            eprintln!(
                "sinuprep lsp: a change to {} which is not open",
                uri.as_str()
            );
            return;
        };
        let unit = self.unit;
        open.held = Arc::new(Open::take_held(open.held).edit(|text| {
            for change in params.content_changes {
                match change.range {
                    Some(range) => {
                        let span = convert::span(text, range, unit);
                        text.replace(span.range(), change.text.as_bytes());
                    }
                    None => *text = Text::new(change.text.into_bytes()),
                }
            }
        }));
        self.documents.insert(uri.clone(), open);
        self.publish(uri.clone());
        // An edit of a settings file applies to every open document as it
        // is typed, before it is saved: once the typing pauses, since each
        // reading analyses every open document again.
        if self.is_read_by_settings(&uri) {
            self.settings_changed = true;
        }
    }

    /// Pushes the findings of an open document to a client that does not
    /// pull them.
    fn publish(&self, uri: lsp::Uri) {
        if self.pull {
            return;
        }
        let Some(open) = self.documents.get(&uri) else {
            return;
        };
        if let Some(worker) = &self.worker {
            let (open, unit) = (open.clone(), self.unit);
            worker.publish(worker::Job {
                uri,
                open: Some(open),
                unit,
            });
        }
    }

    fn request(&mut self, request: Request) {
        let id = request.id.clone();
        // A request that fails inside sinuprep is answered with the error,
        // and the editor keeps its server (and the other documents).
        let answer = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            self.answer_request(request)
        }))
        .unwrap_or_else(|_| Some(Err(failed())));
        if let Some(answer) = answer {
            self.send(response(id, answer));
        }
    }

    /// The answer to `request`; `None` for one answered on a thread of its
    /// own ([`Self::answer_when`]).
    fn answer_request(&self, request: Request) -> Option<Answer> {
        use lsp::request as r;
        match request.method.as_str() {
            // A hover on a variable walks the program for its value.
            r::HoverRequest::METHOD => {
                self.answer_document(request, Waits::Work, |s, p: lsp::HoverParams| {
                    Ok(s.hover(p.text_document_position_params.position))
                })
            }
            // Completion and signature help read the table of uses, made
            // once a version over the whole program: off the main loop.
            r::Completion::METHOD => {
                let snippets = self.supports.snippets;
                self.answer_document(request, Waits::Work, move |s, p: lsp::CompletionParams| {
                    let at = p.text_document_position.position;
                    Ok(lsp::CompletionResponse::Array(s.completion(at, snippets)))
                })
            }
            r::SignatureHelpRequest::METHOD => {
                let offsets = self.supports.label_offsets;
                self.answer_document(
                    request,
                    Waits::Work,
                    move |s, p: lsp::SignatureHelpParams| {
                        let at = p.text_document_position_params.position;
                        Ok(s.signature_help(at, offsets))
                    },
                )
            }
            r::GotoDefinition::METHOD => self.answer_document(
                request,
                Waits::Analysis,
                |s, p: lsp::GotoDefinitionParams| {
                    let at = p.text_document_position_params;
                    Ok(s.definition(&at.text_document.uri, at.position))
                },
            ),
            // A shared name's references and rename read the workspace's
            // other files.
            r::References::METHOD => {
                let buffers = self.buffers();
                self.answer_document(request, Waits::Work, move |s, p: lsp::ReferenceParams| {
                    let (uri, at) = (
                        &p.text_document_position.text_document.uri,
                        p.text_document_position.position,
                    );
                    let with_declaration = p.context.include_declaration;
                    let mut found = s.references(uri, at, with_declaration);
                    found.extend(s.references_elsewhere(uri, at, with_declaration, &buffers));
                    Ok(found)
                })
            }
            r::DocumentSymbolRequest::METHOD => self.answer_document(
                request,
                Waits::Analysis,
                |s, _: lsp::DocumentSymbolParams| {
                    Ok(lsp::DocumentSymbolResponse::Nested(s.symbols()))
                },
            ),
            r::WorkspaceSymbolRequest::METHOD => self.workspace_symbols(request),
            r::FoldingRangeRequest::METHOD => {
                self.answer_document(request, Waits::Analysis, |s, _: lsp::FoldingRangeParams| {
                    Ok(s.folding())
                })
            }
            // With a machine in the settings the findings include a dry run
            // as long as the program: made off the main loop.
            r::DocumentDiagnosticRequest::METHOD => self.answer_document(
                request,
                Waits::Work,
                |s, p: lsp::DocumentDiagnosticParams| {
                    let report = lsp::FullDocumentDiagnosticReport {
                        result_id: None,
                        items: s.diagnostics(&p.text_document.uri),
                    };
                    Ok(lsp::DocumentDiagnosticReportResult::Report(
                        lsp::DocumentDiagnosticReport::Full(
                            lsp::RelatedFullDocumentDiagnosticReport {
                                related_documents: None,
                                full_document_diagnostic_report: report,
                            },
                        ),
                    ))
                },
            ),
            r::InlayHintRequest::METHOD => {
                self.answer_document(request, Waits::Analysis, |s, p: lsp::InlayHintParams| {
                    Ok(s.inlay_hints(p.range))
                })
            }
            r::SemanticTokensFullRequest::METHOD => {
                let sent = self.tokens_sent.clone();
                self.answer_document(
                    request,
                    Waits::Work,
                    move |s, p: lsp::SemanticTokensParams| {
                        Ok(sent.full(&p.text_document.uri, s.semantic_tokens(None)?))
                    },
                )
            }
            r::SemanticTokensFullDeltaRequest::METHOD => {
                let sent = self.tokens_sent.clone();
                self.answer_document(
                    request,
                    Waits::Work,
                    move |s, p: lsp::SemanticTokensDeltaParams| {
                        let tokens = s.semantic_tokens(None)?;
                        Ok(sent.delta(&p.text_document.uri, &p.previous_result_id, tokens))
                    },
                )
            }
            r::SemanticTokensRangeRequest::METHOD => self.answer_document(
                request,
                Waits::Work,
                |s, p: lsp::SemanticTokensRangeParams| {
                    Ok(lsp::SemanticTokens {
                        result_id: None,
                        data: s.semantic_tokens(Some(p.range))?,
                    })
                },
            ),
            // Edits are made on the version the request names, whenever
            // they are answered: the client applies them to that version.
            r::CodeActionRequest::METHOD => {
                self.answer_document(request, Waits::Analysis, |s, p: lsp::CodeActionParams| {
                    let only = p.context.only.as_deref();
                    Ok(s.code_actions(&p.text_document.uri, p.range, only))
                })
            }
            r::PrepareRenameRequest::METHOD => self.answer_document(
                request,
                Waits::Analysis,
                |s, p: lsp::TextDocumentPositionParams| {
                    s.prepare_rename(p.position)
                        .map(lsp::PrepareRenameResponse::Range)
                },
            ),
            r::Rename::METHOD => {
                let buffers = self.buffers();
                let renames_files = self.supports.file_renames;
                self.answer_document(request, Waits::Work, move |s, p: lsp::RenameParams| {
                    let (uri, at) = (
                        &p.text_document_position.text_document.uri,
                        p.text_document_position.position,
                    );
                    match s.shared_name(at) {
                        Some(_) => s.rename_across(uri, at, &p.new_name, &buffers, renames_files),
                        None => s.rename(uri, at, &p.new_name),
                    }
                })
            }
            r::Formatting::METHOD => self.format(request, |p: lsp::DocumentFormattingParams| {
                (p.text_document.uri, None)
            }),
            r::RangeFormatting::METHOD => self
                .format(request, |p: lsp::DocumentRangeFormattingParams| {
                    (p.text_document.uri, Some(p.range))
                }),
            method => Some(Err((
                ErrorCode::MethodNotFound,
                format!("sinuprep does not answer `{method}`"),
            ))),
        }
    }

    /// The workspace's names that hold the query ([`workspace_symbols`]),
    /// the open documents' in their order by URI.
    fn workspace_symbols(&self, request: Request) -> Option<Answer> {
        let id = request.id.clone();
        let params: lsp::WorkspaceSymbolParams = match serde_json::from_value(request.params) {
            Ok(params) => params,
            Err(error) => return Some(Err((ErrorCode::InvalidParams, error.to_string()))),
        };
        let mut documents: Vec<(lsp::Uri, Open)> = self
            .documents
            .iter()
            .map(|(uri, open)| (uri.clone(), open.clone()))
            .collect();
        documents.sort_by(|(a, _), (b, _)| a.as_str().cmp(b.as_str()));
        let ready = documents.iter().all(|(_, open)| open.held.is_analysed());
        let unit = self.unit;
        self.answer_when(id, None, ready, move || {
            let found = workspace_symbols::find(&documents, &params.query, unit);
            serde_json::to_value(lsp::WorkspaceSymbolResponse::Flat(found))
                .map_err(|e| (ErrorCode::InternalError, e.to_string()))
        })
    }

    /// The edits `sinuprep fmt` would make to a document (or the lines of a
    /// range), with the `[format]` settings of its `sinuprep.toml`: made
    /// here for a small document, by the request threads for a large one,
    /// so that formatting it holds up no other document.
    fn format<P: serde::de::DeserializeOwned>(
        &self,
        request: Request,
        target: impl FnOnce(P) -> (lsp::Uri, Option<lsp::Range>),
    ) -> Option<Answer> {
        let id = request.id.clone();
        let method = request.method.clone();
        let params: P = match serde_json::from_value(request.params) {
            Ok(params) => params,
            Err(error) => return Some(Err((ErrorCode::InvalidParams, error.to_string()))),
        };
        let (uri, range) = target(params);
        let Some(open) = self.documents.get(&uri).cloned() else {
            let why = format!("{} is not open", uri.as_str());
            return Some(Err((ErrorCode::InvalidParams, why)));
        };
        let settings = match convert::path(&uri) {
            Some(path) => match self.workspace.for_format(&path) {
                Ok(settings) => settings,
                Err(error) => return Some(Err((ErrorCode::RequestFailed, error.to_string()))),
            },
            None => crate::format::Settings::default(),
        };
        let unit = self.unit;
        let ready = open.held.text().bytes().len() < FORMATTED_HERE;
        self.answer_when(id, Some((uri, method)), ready, move || {
            let edits = formatting::edits(open.held.text(), &open.name, &settings, range, unit);
            serde_json::to_value(edits).map_err(|e| (ErrorCode::InternalError, e.to_string()))
        })
    }

    /// The answer to a request about one open document, made from its
    /// analysis, or why the server will not do what it asks; answered here
    /// when the analysis is made and the answer `waits` for nothing else.
    fn answer_document<P, R>(
        &self,
        request: Request,
        waits: Waits,
        answer: impl FnOnce(&Snapshot, P) -> Result<R, String> + Send + 'static,
    ) -> Option<Answer>
    where
        P: serde::de::DeserializeOwned + HasDocument + Send + 'static,
        R: serde::Serialize,
    {
        let id = request.id.clone();
        let method = request.method.clone();
        let (open, params) = match self.about::<P>(request) {
            Ok(about) => about,
            Err(refused) => return Some(Err(refused)),
        };
        let ready = waits == Waits::Analysis && open.held.is_analysed();
        let unit = self.unit;
        let about = Some((params.document().clone(), method));
        self.answer_when(id, about, ready, move || {
            answer_from(&open, unit, params, answer)
        })
    }

    /// `work`'s answer: made here when `ready`, else by the request threads
    /// (`None` once it is queued), so that a document still being analysed,
    /// or work through a whole large program, holds up no other request.
    /// Its answer may then come after later ones: the protocol allows it,
    /// and it is made from the version the request named. What is ready is
    /// answered here: handing it to a thread costs more than the answer.
    fn answer_when(
        &self,
        id: lsp_server::RequestId,
        about: Option<(lsp::Uri, String)>,
        ready: bool,
        work: impl FnOnce() -> Answer + Send + 'static,
    ) -> Option<Answer> {
        if ready {
            return Some(work());
        }
        self.requests.answer(requests::Job {
            id,
            about,
            work: Box::new(work),
        });
        None
    }

    /// The open document a request is about, and its parameters.
    fn about<P>(&self, request: Request) -> Result<(Open, P), (ErrorCode, String)>
    where
        P: serde::de::DeserializeOwned + HasDocument,
    {
        let params: P = serde_json::from_value(request.params)
            .map_err(|e| (ErrorCode::InvalidParams, e.to_string()))?;
        match self.documents.get(params.document()) {
            Some(open) => Ok((open.clone(), params)),
            None => Err((
                ErrorCode::InvalidParams,
                format!("{} is not open", params.document().as_str()),
            )),
        }
    }
}

/// Documents up to this size (bytes) are formatted on the main loop, in a
/// few milliseconds; larger ones by the request threads.
const FORMATTED_HERE: usize = 1 << 20;

/// What a client takes that the protocol leaves optional.
#[derive(Clone, Copy, Default)]
struct ClientSupports {
    /// Completions as snippets (placeholders to fill).
    snippets: bool,
    /// A signature's parameters as offsets into its label.
    label_offsets: bool,
    /// `workspace/diagnostic/refresh`: asked to pull diagnostics again.
    diagnostic_refresh: bool,
    /// A workspace edit that renames a file.
    file_renames: bool,
}

impl ClientSupports {
    /// Read from the `initialize` request's parameters as sent: lsp-types
    /// reads `workspace.diagnostic`, where the protocol (3.17) and the
    /// clients write `workspace.diagnostics`.
    fn of(initialize: &serde_json::Value) -> Self {
        let capabilities = &initialize["capabilities"];
        let text = &capabilities["textDocument"];
        let workspace = &capabilities["workspace"];
        let yes = |value: &serde_json::Value| value == &serde_json::Value::Bool(true);
        let edit = &workspace["workspaceEdit"];
        let operations = edit["resourceOperations"].as_array();
        Self {
            snippets: yes(&text["completion"]["completionItem"]["snippetSupport"]),
            label_offsets: yes(&text["signatureHelp"]["signatureInformation"]
                ["parameterInformation"]["labelOffsetSupport"]),
            diagnostic_refresh: yes(&workspace["diagnostics"]["refreshSupport"])
                || yes(&workspace["diagnostic"]["refreshSupport"]),
            file_renames: yes(&edit["documentChanges"])
                && operations.is_some_and(|o| o.iter().any(|op| op == "rename")),
        }
    }
}

/// What answering a request may wait for.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Waits {
    /// Only the document's analysis.
    Analysis,
    /// Work of its own as long as the program, or through other files: a
    /// hover's walk, the classes of every word, a shared name's uses in
    /// the workspace.
    Work,
}

/// A request's result, or the error code and message it is refused with.
type Answer = Result<serde_json::Value, (ErrorCode, String)>;

/// What `answer` makes of `open`'s analysis.
fn answer_from<P, R>(
    open: &Open,
    unit: ColumnUnit,
    params: P,
    answer: impl FnOnce(&Snapshot, P) -> Result<R, String>,
) -> Answer
where
    R: serde::Serialize,
{
    let answer = open
        .with_snapshot(unit, |snapshot| answer(snapshot, params))
        .ok_or_else(|| {
            let why = "the document changed while it was analysed";
            (ErrorCode::ContentModified, why.to_string())
        })?
        .map_err(|why| (ErrorCode::RequestFailed, why))?;
    serde_json::to_value(answer).map_err(|e| (ErrorCode::InternalError, e.to_string()))
}

fn response(id: lsp_server::RequestId, answer: Answer) -> Message {
    Message::Response(match answer {
        Ok(result) => Response::new_ok(id, result),
        Err((code, message)) => Response::new_err(id, code as i32, message),
    })
}

/// The error of a request that failed inside sinuprep (the panic said on
/// stderr what failed).
fn failed() -> (ErrorCode, String) {
    (
        ErrorCode::InternalError,
        "sinuprep failed on this request (said on stderr); please report it".to_string(),
    )
}

/// The document a request is about.
trait HasDocument {
    fn document(&self) -> &lsp::Uri;
}

macro_rules! has_document {
    ($($params:ty => |$p:ident| $uri:expr;)*) => {
        $(impl HasDocument for $params {
            fn document(&self) -> &lsp::Uri {
                let $p = self;
                $uri
            }
        })*
    };
}

has_document! {
    lsp::HoverParams => |p| &p.text_document_position_params.text_document.uri;
    lsp::CompletionParams => |p| &p.text_document_position.text_document.uri;
    lsp::SignatureHelpParams => |p| &p.text_document_position_params.text_document.uri;
    lsp::GotoDefinitionParams => |p| &p.text_document_position_params.text_document.uri;
    lsp::ReferenceParams => |p| &p.text_document_position.text_document.uri;
    lsp::DocumentSymbolParams => |p| &p.text_document.uri;
    lsp::FoldingRangeParams => |p| &p.text_document.uri;
    lsp::CodeActionParams => |p| &p.text_document.uri;
    lsp::TextDocumentPositionParams => |p| &p.text_document.uri;
    lsp::RenameParams => |p| &p.text_document_position.text_document.uri;
    lsp::InlayHintParams => |p| &p.text_document.uri;
    lsp::DocumentDiagnosticParams => |p| &p.text_document.uri;
    lsp::SemanticTokensParams => |p| &p.text_document.uri;
    lsp::SemanticTokensRangeParams => |p| &p.text_document.uri;
    lsp::SemanticTokensDeltaParams => |p| &p.text_document.uri;
}

/// A notification's parameters; one that does not parse is said on stderr
/// and ignored, as the protocol asks of notifications.
fn extract<P: serde::de::DeserializeOwned>(notification: Notification) -> Option<P> {
    let method = notification.method.clone();
    match serde_json::from_value(notification.params) {
        Ok(params) => Some(params),
        Err(error) => {
            eprintln!("sinuprep lsp: {method}: {error}");
            None
        }
    }
}
