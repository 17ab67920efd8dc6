//! A language server's client for the tests and the benchmark: the
//! protocol's framing on the server's stdin and stdout, one request after
//! another.
#![allow(dead_code)] // each user takes what it needs

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

use serde_json::{json, Value};

pub struct Client {
    child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    next_id: u64,
    /// Messages received while another was awaited: the server publishes
    /// findings from a thread of its own, in between its answers.
    pending: std::collections::VecDeque<Value>,
}

impl Client {
    /// The cache folder the servers of this test process are given.
    pub fn cache() -> std::path::PathBuf {
        std::env::temp_dir().join(format!("sinuprep-lsp-cache-{}", std::process::id()))
    }

    /// The server of this package's binary (the build of the test or the
    /// benchmark), initialized with `capabilities`. Its cache folder (where
    /// it writes the rules' pages) is [`Self::cache`], not the user's.
    pub fn start(capabilities: Value) -> (Self, Value) {
        let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .arg("lsp")
            .env("XDG_CACHE_HOME", Self::cache())
            .env("LOCALAPPDATA", Self::cache())
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the server starts");
        let stdin = child.stdin.take().expect("stdin");
        let stdout = BufReader::new(child.stdout.take().expect("stdout"));
        let mut client = Self {
            child,
            stdin,
            stdout,
            next_id: 0,
            pending: std::collections::VecDeque::new(),
        };
        let initialized = client.request("initialize", json!({ "capabilities": capabilities }));
        client.notify("initialized", json!({}));
        (client, initialized)
    }

    pub fn write(&mut self, body: &[u8]) {
        write!(self.stdin, "Content-Length: {}\r\n\r\n", body.len()).expect("write");
        self.stdin.write_all(body).expect("write");
        self.stdin.flush().expect("flush");
    }

    pub fn send(&mut self, message: Value) {
        self.write(message.to_string().as_bytes());
    }

    pub fn receive(&mut self) -> Value {
        let mut length = None;
        loop {
            let mut header = String::new();
            self.stdout.read_line(&mut header).expect("a header");
            assert!(header.ends_with("\r\n"), "header {header:?}");
            if header == "\r\n" {
                break;
            }
            if let Some(value) = header.strip_prefix("Content-Length: ") {
                length = Some(value.trim().parse::<usize>().expect("a length"));
            }
        }
        let mut body = vec![0; length.expect("Content-Length")];
        self.stdout.read_exact(&mut body).expect("a body");
        serde_json::from_slice(&body).expect("JSON")
    }

    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({ "jsonrpc": "2.0", "method": method, "params": params }));
    }

    /// The response to a request: its result, or its error.
    pub fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(json!({ "jsonrpc": "2.0", "id": id, "method": method, "params": params }));
        let message = self.next(|message| message["id"] == json!(id));
        match message.get("error") {
            Some(error) => json!({ "error": error }),
            None => message["result"].clone(),
        }
    }

    /// The next diagnostics published for `uri`.
    pub fn diagnostics(&mut self, uri: &str) -> Vec<Value> {
        let message = self.next(|message| {
            message["method"] == "textDocument/publishDiagnostics"
                && message["params"]["uri"] == uri
        });
        message["params"]["diagnostics"]
            .as_array()
            .expect("a list")
            .clone()
    }

    /// The first message, received or kept from before, that `wanted`
    /// takes; the others are kept for later.
    pub fn next(&mut self, wanted: impl Fn(&Value) -> bool) -> Value {
        if let Some(at) = self.pending.iter().position(&wanted) {
            return self.pending.remove(at).expect("found");
        }
        loop {
            let message = self.receive();
            if wanted(&message) {
                return message;
            }
            self.pending.push_back(message);
        }
    }

    /// How many of the messages kept from before `wanted` takes.
    pub fn kept(&self, wanted: impl Fn(&Value) -> bool) -> usize {
        self.pending
            .iter()
            .filter(|message| wanted(message))
            .count()
    }

    pub fn open(&mut self, uri: &str, text: &str) -> Vec<Value> {
        self.notify(
            "textDocument/didOpen",
            json!({ "textDocument": { "uri": uri, "languageId": "sinumerik", "version": 1, "text": text } }),
        );
        self.diagnostics(uri)
    }

    /// The server's peak resident memory so far, where the system says
    /// (Linux's `/proc`).
    pub fn peak_memory_kib(&self) -> Option<u64> {
        self.status_kib("VmHWM:")
    }

    /// The server's resident memory now (Linux's `/proc`).
    #[allow(dead_code)] // Only the bench reads it.
    pub fn memory_kib(&self) -> Option<u64> {
        self.status_kib("VmRSS:")
    }

    fn status_kib(&self, field: &str) -> Option<u64> {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.child.id())).ok()?;
        let line = status.lines().find(|line| line.starts_with(field))?;
        line.split_whitespace().nth(1)?.parse().ok()
    }

    /// How many threads the server runs now, where the system says
    /// (Linux's `/proc`).
    pub fn threads(&self) -> Option<usize> {
        let tasks = std::fs::read_dir(format!("/proc/{}/task", self.child.id())).ok()?;
        Some(tasks.count())
    }

    /// Shuts the server down as the protocol says; its exit status and stderr.
    pub fn stop(mut self) -> (Option<i32>, String) {
        assert_eq!(self.request("shutdown", Value::Null), Value::Null);
        self.notify("exit", Value::Null);
        self.finish()
    }

    pub fn finish(mut self) -> (Option<i32>, String) {
        drop(self.stdin);
        let status = self.child.wait().expect("the server ends");
        let mut stderr = String::new();
        if let Some(mut pipe) = self.child.stderr.take() {
            pipe.read_to_string(&mut stderr).expect("stderr");
        }
        (status.code(), stderr)
    }
}
