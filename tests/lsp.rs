//! `sinuprep lsp` spoken to as an editor speaks to it: the protocol's
//! framing on stdin and stdout, one request after another.

use serde_json::{json, Value};

mod support;
use support::scratch;

#[path = "support/lsp_client.rs"]
mod lsp_client;
use lsp_client::Client;

fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({ "textDocument": { "uri": uri }, "position": { "line": line, "character": character } })
}

fn codes(diagnostics: &[Value]) -> Vec<&str> {
    diagnostics
        .iter()
        .map(|d| d["code"].as_str().expect("a code"))
        .collect()
}

const URI: &str = "untitled:PART.MPF";

/// `ü` and `😀` in the comment make UTF-8, UTF-16 and characters differ.
const PART: &str = "\
; ü😀 probe part
DEF REAL _DEPTH=5
START:
G17 G90 F500 S1000 M3
IF _DEPTH>0
G1 Z=-_DEPTH
ENDIF
GOTOB START
M30
";

#[test]
fn the_server_answers_what_an_editor_asks() {
    let (mut client, initialized) = Client::start(json!({}));
    let capabilities = &initialized["capabilities"];
    assert_eq!(capabilities["positionEncoding"], "utf-16");
    assert_eq!(capabilities["textDocumentSync"]["change"], 2, "incremental");
    let found = client.open(URI, PART);
    assert!(codes(&found).iter().all(|c| *c != "N004"), "{found:?}");

    // Hover on the jump's label names where it lands.
    let hover = client.request("textDocument/hover", at(URI, 7, 7));
    let text = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        text.contains("defined on line 3") && text.contains("START:"),
        "{text}"
    );

    // The variable read on line 6 is defined on line 2, after `DEF REAL `.
    let definition = client.request("textDocument/definition", at(URI, 5, 8));
    assert_eq!(
        definition["range"]["start"],
        json!({ "line": 1, "character": 9 })
    );
    let references = client.request(
        "textDocument/references",
        json!({ "textDocument": { "uri": URI }, "position": { "line": 1, "character": 10 },
                "context": { "includeDeclaration": true } }),
    );
    let lines: Vec<u64> = references
        .as_array()
        .expect("a list")
        .iter()
        .map(|r| r["range"]["start"]["line"].as_u64().expect("a line"))
        .collect();
    assert_eq!(lines, [1, 4, 5]);

    let symbols = client.request(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": URI } }),
    );
    let names: Vec<&str> = symbols
        .as_array()
        .expect("a list")
        .iter()
        .map(|s| s["name"].as_str().expect("a name"))
        .collect();
    assert_eq!(names, ["_DEPTH", "START"]);
    let folding = client.request(
        "textDocument/foldingRange",
        json!({ "textDocument": { "uri": URI } }),
    );
    assert_eq!(folding, json!([{ "startLine": 4, "endLine": 6 }]));

    // An incremental change: ENDIF deleted, the IF is reported unclosed.
    client.notify(
        "textDocument/didChange",
        json!({ "textDocument": { "uri": URI, "version": 2 },
                "contentChanges": [{ "range": { "start": { "line": 6, "character": 0 },
                                                "end": { "line": 7, "character": 0 } }, "text": "" }] }),
    );
    let found = client.diagnostics(URI);
    let unclosed = found.iter().find(|d| d["code"] == "N004").expect("N004");
    assert_eq!(
        unclosed["range"]["start"],
        json!({ "line": 4, "character": 0 })
    );
    let (status, stderr) = client.stop();
    assert_eq!(status, Some(0), "{stderr}");
}

#[test]
fn positions_count_in_the_unit_agreed() {
    // The jump's label stands after `ü` (2 bytes, 1 UTF-16 unit) and `😀`
    // (4 bytes, 2 units): byte 20, UTF-16 unit 17.
    let text = "MSG(\"ü😀\") GOTOF ENDE\nENDE:\nM30\n";
    let uri = "untitled:UNITS.MPF";
    for (offered, unit, character) in [
        (json!(["utf-16"]), "utf-16", 17),
        (json!(["utf-8", "utf-16"]), "utf-8", 20),
    ] {
        let (mut client, initialized) =
            Client::start(json!({ "general": { "positionEncodings": offered } }));
        assert_eq!(initialized["capabilities"]["positionEncoding"], unit);
        client.open(uri, text);
        let hover = client.request("textDocument/hover", at(uri, 0, character + 1));
        let range = &hover["range"];
        assert_eq!(
            range["start"],
            json!({ "line": 0, "character": character }),
            "{unit}"
        );
        assert_eq!(
            range["end"],
            json!({ "line": 0, "character": character + 4 }),
            "{unit}"
        );
        let (status, stderr) = client.stop();
        assert_eq!(status, Some(0), "{stderr}");
    }
}

#[test]
fn a_cycle600_hover_shows_what_eval_computes() {
    let (mut client, _) = Client::start(json!({}));
    let text = "N120 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nM30\n";
    client.open(URI, text);
    let hover = client.request("textDocument/hover", at(URI, 0, 8));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    // Example 3 of the CYCLE600 paper: extrinsic X, Y, Z 30/45/60 is
    // intrinsic Z, X', Y'' 37.792346, 20.704811, 49.106605.
    assert!(shown.contains("37.792346  20.704811  49.106605"), "{shown}");
    let symbols = client.request(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": URI } }),
    );
    assert_eq!(symbols[0]["name"], "CYCLE600");
    client.stop();
}

#[test]
fn a_fix_is_a_code_action() {
    let (mut client, _) = Client::start(json!({}));
    let text = "START:\nG1 X1 F100\nGOTOB STRAT\nM30\n";
    let found = client.open(URI, text);
    assert_eq!(codes(&found), ["N001"]);
    let actions = client.request(
        "textDocument/codeAction",
        json!({ "textDocument": { "uri": URI },
                "range": { "start": { "line": 2, "character": 8 }, "end": { "line": 2, "character": 8 } },
                "context": { "diagnostics": [] } }),
    );
    assert_eq!(actions[0]["title"], "jump to `START`");
    let edits = &actions[0]["edit"]["changes"][URI];
    assert_eq!(
        edits,
        &json!([{ "range": { "start": { "line": 2, "character": 6 }, "end": { "line": 2, "character": 11 } },
                  "newText": "START" }])
    );
    // Elsewhere, nothing to fix.
    let none = client.request(
        "textDocument/codeAction",
        json!({ "textDocument": { "uri": URI },
                "range": { "start": { "line": 0, "character": 0 }, "end": { "line": 0, "character": 3 } },
                "context": { "diagnostics": [] } }),
    );
    assert_eq!(none, json!([]));
    client.stop();
}

/// "Fix all" (`source.fixAll.sinuprep`, what an editor asks for to fix
/// on save) makes every safe fix at once, the same edits `check --fix`
/// writes; it is offered only when source actions are asked for.
#[test]
fn fix_all_makes_what_check_fix_writes() {
    let (mut client, _) = Client::start(json!({}));
    let text = "G1 X1 F100 ; sinuprep: ignore N001\nG1 X2 ; sinuprep: ignore N002\nM30\n";
    let found = client.open(URI, text);
    assert_eq!(codes(&found), ["N099", "N099"]);
    let ask = |client: &mut Client, only: Value| {
        client.request(
            "textDocument/codeAction",
            json!({ "textDocument": { "uri": URI },
                    "range": { "start": { "line": 2, "character": 0 }, "end": { "line": 2, "character": 0 } },
                    "context": { "diagnostics": [], "only": only } }),
        )
    };
    assert_eq!(ask(&mut client, Value::Null), json!([]));
    let actions = ask(&mut client, json!(["source.fixAll"]));
    assert_eq!(actions[0]["kind"], "source.fixAll.sinuprep", "{actions}");
    assert_eq!(actions[0]["title"], "Fix all: 2 findings (sinuprep)");
    let mut edits: Vec<(usize, usize, usize, String)> = actions[0]["edit"]["changes"][URI]
        .as_array()
        .expect("edits")
        .iter()
        .map(|edit| {
            let at =
                |end: &str, key: &str| edit["range"][end][key].as_u64().expect("position") as usize;
            assert_eq!(at("start", "line"), at("end", "line"));
            (
                at("start", "line"),
                at("start", "character"),
                at("end", "character"),
                edit["newText"].as_str().expect("text").to_string(),
            )
        })
        .collect();
    // Applied from the end, on an ASCII text: what `check --fix` writes.
    edits.sort();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    for (line, start, end, new) in edits.into_iter().rev() {
        lines[line].replace_range(start..end, &new);
    }
    let fixed = lines.join("\n") + "\n";
    let dir = scratch("lsp-fix-all");
    let path = dir.join("FIX.MPF");
    std::fs::write(&path, text).expect("write");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--fix", "--quiet"])
        .arg(&path)
        .output()
        .expect("check runs");
    assert_eq!(status.status.code(), Some(0));
    assert_eq!(std::fs::read_to_string(&path).expect("fixed"), fixed);
    assert_eq!(fixed, "G1 X1 F100\nG1 X2\nM30\n");
    let _ = std::fs::remove_dir_all(&dir);
    client.stop();
}

/// A finding's code links to its rule's documentation: with no repository
/// named in Cargo.toml, the page `sinuprep rule CODE` prints, written into
/// the server's cache folder.
#[test]
fn a_findings_code_links_to_its_rules_page() {
    let (mut client, _) = Client::start(json!({}));
    let found = client.open(URI, "START:\nGOTOB STRAT\nM30\n");
    assert_eq!(codes(&found), ["N001"]);
    let href = found[0]["codeDescription"]["href"]
        .as_str()
        .expect("a link");
    let page = Client::cache().join(format!(
        "sinuprep/{}/rules/N001.md",
        env!("CARGO_PKG_VERSION")
    ));
    assert!(
        href.starts_with("file:///") && href.ends_with("/rules/N001.md"),
        "{href}"
    );
    let rule = std::process::Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["rule", "N001"])
        .output()
        .expect("rule runs");
    assert_eq!(std::fs::read(&page).expect("the page"), rule.stdout);
    client.stop();
}

#[test]
fn no_message_breaks_the_server() {
    let (mut client, _) = Client::start(json!({}));
    let unknown = client.request("sinuprep/unknown", json!({}));
    assert_eq!(unknown["error"]["code"], -32601);
    let not_open = client.request("textDocument/hover", at("untitled:NEVER.MPF", 0, 0));
    assert_eq!(not_open["error"]["code"], -32602);
    let bad_params = client.request("textDocument/hover", json!({ "position": "here" }));
    assert_eq!(bad_params["error"]["code"], -32602);
    // A change to a document never opened is said on stderr and dropped.
    client.notify(
        "textDocument/didChange",
        json!({ "textDocument": { "uri": "untitled:NEVER.MPF", "version": 2 },
                "contentChanges": [{ "text": "M30\n" }] }),
    );
    client.open(URI, "G1 X1\nM30\n");
    let far = client.request("textDocument/hover", at(URI, 999, 999));
    assert_eq!(far, Value::Null);
    // Half a UTF-16 pair, as an editor sends one: read as U+FFFD, the
    // session goes on.
    let lone = "untitled:LONE.MPF";
    client.write(
        format!(r#"{{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{{"textDocument":{{"uri":"{lone}","languageId":"sinumerik","version":1,"text":"; \ud800\nGOTOF NOWHERE\nM30\n"}}}}}}"#)
            .as_bytes(),
    );
    let found = client.diagnostics(lone);
    assert_eq!(codes(&found), ["N001"], "{found:?}");
    let (status, stderr) = client.stop();
    assert_eq!(status, Some(0));
    assert!(stderr.contains("not open"), "{stderr}");

    // Malformed JSON ends the session with an error, never a panic.
    let (mut client, _) = Client::start(json!({}));
    client.write(b"{ not json");
    let (status, stderr) = client.finish();
    assert_ne!(status, Some(0));
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_rename_changes_every_use_or_says_why_not() {
    let (mut client, _) = Client::start(json!({}));
    let text = "DEF REAL _DEPTH, _FEED\nN10 _DEPTH=5\nG1 Z=-_depth F=_FEED\nGOTOB N10\nM30\n";
    client.open(URI, text);
    let prepared = client.request("textDocument/prepareRename", at(URI, 1, 6));
    assert_eq!(prepared["start"], json!({ "line": 1, "character": 4 }));
    let rename = |client: &mut Client, line, character, name: &str| {
        let mut params = at(URI, line, character);
        params["newName"] = json!(name);
        client.request("textDocument/rename", params)
    };
    let renamed = rename(&mut client, 2, 8, "_DEEP");
    let lines: Vec<(u64, u64)> = renamed["changes"][URI]
        .as_array()
        .expect("edits")
        .iter()
        .map(|e| {
            let start = &e["range"]["start"];
            (
                start["line"].as_u64().expect("line"),
                start["character"].as_u64().expect("character"),
            )
        })
        .collect();
    assert_eq!(lines, [(0, 9), (1, 4), (2, 6)], "{renamed}");
    for (line, character, name, why) in [
        (1, 6, "_FEED", "already a name"),
        (1, 6, "1X", "not a name the control takes"),
        (1, 6, "IF", "a word of the language"),
        (1, 6, "gotof", "a word of the language"),
        (1, 6, "DEF", "a word of the language"),
        (1, 6, "REAL", "a word of the language"),
        (1, 6, "SIN", "a word of the language"),
        (1, 6, "TRUE", "a word of the language"),
        (1, 6, "CYCLE800", "a word of the language"),
        (1, 6, "AX1", "a word of the language"),
        (1, 6, "STOPRE", "a word of the language"),
        (3, 7, "N20", "renumbered"),
        (4, 1, "_X", "no name"),
    ] {
        let refused = rename(&mut client, line, character, name);
        let message = refused["error"]["message"].as_str().unwrap_or_default();
        assert!(message.contains(why), "{name}: {refused}");
    }
    client.stop();
}

#[test]
fn inlay_hints_give_a_cycle600_its_angles_and_a_cycle800_its_mode() {
    let (mut client, _) = Client::start(json!({}));
    let text = "N120 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nCYCLE800(1,\"TC1\",0,39,0,0,0,10,20,30,0,0,0,-1)\nM30\n";
    client.open(URI, text);
    let hints = client.request(
        "textDocument/inlayHint",
        json!({ "textDocument": { "uri": URI },
                "range": { "start": { "line": 0, "character": 0 }, "end": { "line": 2, "character": 0 } } }),
    );
    assert_eq!(hints[0]["label"], "→ intrinsic:ZXY 37.7923 20.7048 49.1066");
    assert_eq!(
        hints[0]["position"],
        json!({ "line": 0, "character": text.find(')').expect("end") + 1 })
    );
    // A CYCLE800's `_MODE` 39, after the argument: Z, then X', then Y''.
    assert_eq!(hints[1]["label"], "axis by axis: Z, then X', then Y''");
    assert_eq!(
        hints[1]["position"],
        json!({ "line": 1, "character": "CYCLE800(1,\"TC1\",0,39".len() })
    );
    client.stop();
}

/// Whether the editor `name` is there to run its test: when it is not, the
/// test is skipped with a note, but never under CI (`.ci/run` installs it).
fn editor_present(name: &str, present: bool) -> bool {
    if !present {
        assert_ne!(
            std::env::var("CI").as_deref(),
            Ok("true"),
            "CI must run the {name} test"
        );
        eprintln!("NOTE: {name} not found: the {name} test was SKIPPED");
    }
    present
}

/// Runs `editor` with `script` (saved as `script_name`) in a folder of its
/// own holding the paper's sample as PART.MPF, alone (no HEAD_DEF beside
/// it, so C610 is reported), the server's binary in `SINUPREP_BIN`: its
/// output and what the script wrote to out.txt.
fn run_editor(
    mut editor: std::process::Command,
    script_name: &str,
    script: &str,
) -> (std::process::Output, String) {
    let dir = scratch(&format!("editor-{script_name}"));
    let sample = concat!(env!("CARGO_MANIFEST_DIR"), "/samples/PAPER_EXAMPLE3.MPF");
    std::fs::copy(sample, dir.join("PART.MPF")).expect("the sample");
    std::fs::write(dir.join(script_name), script).expect("the script");
    let output = editor
        .current_dir(&dir)
        .env("SINUPREP_BIN", env!("CARGO_BIN_EXE_sinuprep"))
        .env("XDG_CACHE_HOME", Client::cache())
        .stdin(std::process::Stdio::null())
        .output()
        .expect("the editor runs");
    let shown = std::fs::read_to_string(dir.join("out.txt")).unwrap_or_default();
    let _ = std::fs::remove_dir_all(&dir);
    (output, shown)
}

/// Neovim's own client (Debian's `neovim`, 0.7 or later) starts the server,
/// opens a program and reads its findings and a hover on its CYCLE600.
/// Required under CI (`.ci/run` installs it); skipped elsewhere without it.
#[test]
fn neovim_shows_the_findings_and_a_hover() {
    let present = std::process::Command::new("nvim")
        .arg("--version")
        .output()
        .is_ok();
    if !editor_present("Neovim", present) {
        return;
    }
    let script = r#"
local out = {}
local id = vim.lsp.start_client({ cmd = { os.getenv("SINUPREP_BIN"), "lsp" },
                                  root_dir = vim.fn.getcwd(), name = "sinuprep" })
vim.cmd("edit PART.MPF")
local buf = vim.api.nvim_get_current_buf()
vim.lsp.buf_attach_client(buf, id)
vim.wait(20000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
for _, d in ipairs(vim.diagnostic.get(buf)) do
  table.insert(out, "diagnostic " .. (d.lnum + 1) .. " " .. tostring(d.code))
end
local position = { line = 13, character = 8 }
local params = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = position }
local response = vim.lsp.get_client_by_id(id).request_sync("textDocument/hover", params, 20000, buf)
if response and response.result then
  for line in response.result.contents.value:gmatch("[^\n]+") do
    table.insert(out, "hover " .. line)
  end
end
vim.fn.writefile(out, "out.txt")
vim.lsp.get_client_by_id(id).stop()
vim.wait(5000, function() return vim.lsp.get_client_by_id(id) == nil end, 50)
vim.cmd("qa!")
"#;
    let mut nvim = std::process::Command::new("nvim");
    nvim.args([
        "--headless",
        "--clean",
        "-u",
        "NONE",
        "-c",
        "luafile test.lua",
    ]);
    let (status, shown) = run_editor(nvim, "test.lua", script);
    assert!(status.status.success(), "{status:?}");
    assert!(shown.contains("diagnostic 1 C610"), "{shown}");
    assert!(
        shown.contains("hover   output   intrinsic:ZXY (code 39)  37.792346  20.704811  49.106605"),
        "{shown}"
    );
}

/// Neovim's own client completes and helps with signatures as a user
/// sees it: what its omnifunc inserts (its conversion of the items, which
/// keeps those that go on from the word typed, case and all, and turns a
/// snippet into text), and the parameter its signature window highlights.
#[test]
fn neovim_completes_and_shows_the_parameter_being_written() {
    let present = std::process::Command::new("nvim")
        .arg("--version")
        .output()
        .is_ok();
    if !editor_present("Neovim", present) {
        return;
    }
    let script = r#"
local out = {}
local id = vim.lsp.start_client({ cmd = { os.getenv("SINUPREP_BIN"), "lsp" },
                                  root_dir = vim.fn.getcwd(), name = "sinuprep" })
vim.cmd("edit PART.MPF")
local buf = vim.api.nvim_get_current_buf()
vim.api.nvim_buf_set_lines(buf, 0, -1, false, {
  "START:", "G17", "GOTOB ST", "cycle80", "CYCLE800(0,\"TC1\",200000,", "M30" })
vim.lsp.buf_attach_client(buf, id)
local client = vim.lsp.get_client_by_id(id)
vim.wait(20000, function() return client.initialized end, 50)
local function at(line)
  local text = vim.api.nvim_buf_get_lines(buf, line, line + 1, false)[1]
  return { textDocument = { uri = vim.uri_from_bufnr(buf) },
           position = { line = line, character = #text } }, text
end
for _, line in ipairs({ 2, 3 }) do
  local params, text = at(line)
  -- As the omnifunc: the word typed is the keyword before the cursor.
  local prefix = vim.fn.matchstr(text, "\\k*$")
  local response = client.request_sync("textDocument/completion", params, 20000, buf)
  local items = vim.lsp.util.text_document_completion_list_to_complete_items(response.result, prefix)
  for _, item in ipairs(items) do
    table.insert(out, "complete " .. line .. " " .. item.word)
  end
end
local params = at(4)
local response = client.request_sync("textDocument/signatureHelp", params, 20000, buf)
local lines, hl = vim.lsp.util.convert_signature_help_to_markdown_lines(response.result)
table.insert(out, "signature " .. lines[1])
table.insert(out, "active " .. lines[1]:sub(hl[1] + 1, hl[2]))
vim.fn.writefile(out, "out.txt")
client.stop()
vim.wait(5000, function() return vim.lsp.get_client_by_id(id) == nil end, 50)
vim.cmd("qa!")
"#;
    let mut nvim = std::process::Command::new("nvim");
    nvim.args([
        "--headless",
        "--clean",
        "-u",
        "NONE",
        "-c",
        "luafile test.lua",
    ]);
    let (status, shown) = run_editor(nvim, "test.lua", script);
    assert!(status.status.success(), "{status:?}");
    assert!(shown.contains("complete 2 START\n"), "{shown}");
    // Neovim 0.7 takes no snippets: the name and the bracket.
    assert!(shown.contains("complete 3 cycle800(\n"), "{shown}");
    assert!(
        shown.contains("signature CYCLE800(_FR, _TC, _ST, _MODE,"),
        "{shown}"
    );
    assert!(shown.contains("active _MODE"), "{shown}");
}

/// Emacs with eglot (Debian's `emacs-nox` and `elpa-eglot`, eglot 1.9 or
/// later) starts the server, opens a program, and reads its findings through
/// flymake and two hovers: on a CYCLE600 and on a result read after it.
/// Required under CI (`.ci/run` installs them); skipped elsewhere without them.
#[test]
fn emacs_shows_the_findings_and_a_hover() {
    let has_eglot = std::process::Command::new("emacs")
        .args(["--batch", "--eval", "(require 'eglot)"])
        .stdin(std::process::Stdio::null())
        .output()
        .is_ok_and(|output| output.status.success());
    if !editor_present("Emacs with eglot", has_eglot) {
        return;
    }
    // The README's recipe (a mode for the files, the server for the mode),
    // then what a user would do by hand: open, wait, hover.
    let script = r#"
(require 'eglot)
(define-derived-mode sinumerik-mode prog-mode "Sinumerik")
(add-to-list 'auto-mode-alist '("\\.[ms]pf\\'" . sinumerik-mode))
(add-to-list 'eglot-server-programs
             `(sinumerik-mode . (,(getenv "SINUPREP_BIN") "lsp")))
(add-hook 'sinumerik-mode-hook #'eglot-ensure)
(defvar out nil)
(defun hover-at (line word)
  (goto-char (point-min))
  (forward-line line)
  (search-forward word)
  (backward-char 2)
  (let ((hover (jsonrpc-request (eglot--current-server-or-lose) :textDocument/hover
                                (eglot--TextDocumentPositionParams))))
    (dolist (text (split-string (plist-get (plist-get hover :contents) :value) "\n"))
      (push (concat "hover " text) out))))
(find-file "PART.MPF")
;; eglot-ensure connects after the command that opened the file.
(run-hooks 'post-command-hook)
(let ((tries 0))
  (while (and (null (flymake-diagnostics)) (< tries 200))
    (accept-process-output nil 0.1)
    (flymake-start)
    (setq tries (1+ tries))))
(dolist (d (flymake-diagnostics))
  (push (format "diagnostic %d %s" (line-number-at-pos (flymake-diagnostic-beg d))
                (flymake-diagnostic-text d))
        out))
(hover-at 13 "CYCLE600")
(hover-at 27 "_CYC600_2")
(with-temp-file "out.txt" (insert (mapconcat #'identity (reverse out) "\n")))
(eglot-shutdown (eglot-current-server))
(kill-emacs 0)
"#;
    let mut emacs = std::process::Command::new("emacs");
    emacs.args(["--batch", "-l", "test.el"]);
    let (status, shown) = run_editor(emacs, "test.el", script);
    assert!(status.status.success(), "{status:?}");
    assert!(shown.contains("diagnostic 1 sinuprep [C610]: "), "{shown}");
    assert!(
        shown.contains("hover   output   intrinsic:ZXY (code 39)  37.792346  20.704811  49.106605"),
        "{shown}"
    );
    assert!(
        shown.contains("hover Value here: `39.639272238`, result of the CYCLE600 on line 26"),
        "{shown}"
    );
}

#[test]
fn a_client_that_pulls_diagnostics_gets_them_once() {
    let capabilities = json!({ "textDocument": { "diagnostic": { "dynamicRegistration": false } },
                               "workspace": { "diagnostics": { "refreshSupport": true } } });
    let (mut client, initialized) = Client::start(capabilities);
    assert_eq!(
        initialized["capabilities"]["diagnosticProvider"]["interFileDependencies"],
        true
    );
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": URI, "languageId": "sinumerik", "version": 1,
                                  "text": "START:\nG1 X1 F100\nGOTOB STRAT\nM30\n" } }),
    );
    client.send(
        json!({ "jsonrpc": "2.0", "id": 99, "method": "textDocument/diagnostic",
                        "params": { "textDocument": { "uri": URI } } }),
    );
    // The answer is the next message: nothing was pushed before it.
    let answer = client.receive();
    assert_eq!(answer["id"], 99, "{answer}");
    assert_eq!(answer["result"]["kind"], "full", "{answer}");
    let items = answer["result"]["items"].as_array().expect("items");
    assert_eq!(codes(items), ["N001"]);
    // A settings or definition file changed: the client is asked to pull
    // again (it said it can be).
    client.notify("workspace/didChangeWatchedFiles", json!({ "changes": [] }));
    let asked = client.next(|message| message["method"] == "workspace/diagnostic/refresh");
    client.send(json!({ "jsonrpc": "2.0", "id": asked["id"], "result": null }));
    client.stop();
}

#[test]
fn a_finding_can_be_ignored_and_a_cycle600_rewritten_from_the_editor() {
    let (mut client, _) = Client::start(json!({}));
    let text = "DEF REAL DEPTH=5\nG1 Z=DEPHT F100 ; feed\nN120 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nM30\n";
    client.open(URI, text);
    let actions = |client: &mut Client, line: u32| {
        client.request(
            "textDocument/codeAction",
            json!({ "textDocument": { "uri": URI },
                    "range": { "start": { "line": line, "character": 5 }, "end": { "line": line, "character": 5 } },
                    "context": { "diagnostics": [] } }),
        )
    };
    let on_first = actions(&mut client, 1);
    let ignore = on_first
        .as_array()
        .expect("actions")
        .iter()
        .find(|a| a["title"] == "Ignore N005 on this line")
        .unwrap_or_else(|| panic!("{on_first}"));
    // Into the comment the line has, at its end.
    assert_eq!(
        ignore["edit"]["changes"][URI],
        json!([{ "range": { "start": { "line": 1, "character": 22 }, "end": { "line": 1, "character": 22 } },
                 "newText": " sinuprep: ignore N005" }])
    );
    let on_call = actions(&mut client, 2);
    let rewrite = on_call
        .as_array()
        .expect("actions")
        .iter()
        .find(|a| a["kind"] == "refactor.rewrite")
        .unwrap_or_else(|| panic!("{on_call}"));
    assert_eq!(rewrite["title"], "Rewrite this CYCLE600 as a CYCLE800 call");
    let edits = rewrite["edit"]["changes"][URI].to_string();
    assert!(edits.contains("_CYC600_2=37.792346"), "{edits}");
    client.stop();
}

/// A hover on a CYCLE800 reads its parameters as the control does, gives the
/// new plane's tool axis, and with a machine in sinuprep.toml the positions
/// of the record's rotary axes.
#[test]
fn a_cycle800_hover_says_what_the_call_asks_for() {
    let dir = scratch("lsp-cycle800");
    let samples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("samples");
    std::fs::copy(samples.join("MACHINE.SPF"), dir.join("MACHINE.SPF")).expect("machine");
    std::fs::write(dir.join("sinuprep.toml"), "machine = \"MACHINE.SPF\"\n").expect("toml");
    let path = dir.join("SWIVEL.MPF");
    let uri = format!("file://{}", path.display());
    let (mut client, _) = Client::start(json!({}));
    client.open(
        &uri,
        "CYCLE800(1,\"HEAD_CA\",0,57,0,0,0,0,-30,0,0,0,0,-1,100,1)\nM30\n",
    );
    let hover = client.request("textDocument/hover", at(&uri, 0, 3));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    for expected in [
        "| `_FR` | 1 | retract machine Z |",
        "| `_TC` | \"HEAD_CA\" | swivel data record `HEAD_CA` |",
        "| `_MODE` | 57 | axis by axis: X, then Y', then Z'' |",
        "| `_B` | -30 | second turn, about Y' (degrees) |",
        "| `_DIR` | -1 | minus:",
        // Y turned by -30°: Z goes to (-sin 30°, 0, cos 30°).
        "in the frame before it: (-0.5, 0, 0.866025)",
        "On `",
    ] {
        assert!(shown.contains(expected), "{expected}\n{shown}");
    }
    assert_eq!(hover["range"]["start"]["character"], 0);
    // The call without arguments takes the plane back: not a swivel whose
    // arguments are all 0.
    client.open(&uri, "CYCLE800()\nM30\n");
    let hover = client.request("textDocument/hover", at(&uri, 0, 3));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.starts_with("**CYCLE800()**, without arguments: takes the swivel plane back"),
        "{shown}"
    );
    assert!(!shown.contains("_MODE"), "{shown}");
    // A CYCLE600 on the same machine: eval's table, and where the axes go.
    client.open(
        &uri,
        "CYCLE600(0,\"HEAD_CA\",0,57,0,0,0,0,-30,0,0,0,0,0,1,39,0,0,0)\nM30\n",
    );
    let hover = client.request("textDocument/hover", at(&uri, 0, 3));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("MACHINE.SPF`: record 1 (HEAD_CA): C="),
        "{shown}"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// With a machine whose data describe its axes, a hover on a block gives
/// where the dry run takes the machine axes by its end and the time so far,
/// and a block past a software limit says so.
#[test]
fn a_block_hover_shows_the_dry_run() {
    let dir = scratch("lsp-run");
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/run");
    std::fs::copy(fixtures.join("MACHINE.INI"), dir.join("MACHINE.INI")).expect("machine");
    std::fs::write(dir.join("sinuprep.toml"), "machine = \"MACHINE.INI\"\n").expect("toml");
    let uri = format!("file://{}", dir.join("P.MPF").display());
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, "G54 G0 X0 Y0 Z0\nG60 G0 X100\nG0 Z400\nM30\n");
    let hover = client.request("textDocument/hover", at(&uri, 1, 9));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    // G54 shifts X by 250: X1 at 350; 100 mm at G0 exact stop, 0.4 s.
    assert!(shown.contains("X1 350 · Y1 120 · Z1 -380"), "{shown}");
    assert!(shown.contains("0.4 s so far"), "{shown}");
    let beyond = client.request("textDocument/hover", at(&uri, 2, 5));
    let shown = beyond["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("**Z1 past its software limit** 0.5 (reaches 20)"),
        "{shown}"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A folder of the control's data files named by sinuprep.toml is one
/// machine to the server as to `check` and `run`: the axis file read after
/// INITIAL_INI wins (Z1's limit 1.5, not 0.5), and a program's read of a
/// machine datum has the value the data give.
#[test]
fn a_folder_of_machine_data_is_read_as_the_command_line_reads_it() {
    let dir = scratch("lsp-machine-folder");
    let folder =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/machine/folder");
    std::fs::create_dir_all(dir.join("data")).expect("folder");
    for entry in std::fs::read_dir(&folder).expect("fixture") {
        let path = entry.expect("entry").path();
        std::fs::copy(
            &path,
            dir.join("data").join(path.file_name().expect("name")),
        )
        .expect("copy");
    }
    std::fs::write(dir.join("sinuprep.toml"), "machine = \"data\"\n").expect("toml");
    let uri = format!("file://{}", dir.join("P.MPF").display());
    let (mut client, _) = Client::start(json!({}));
    let found = client.open(&uri, "R3=$MA_POS_LIMIT_PLUS[AX2]\nG0 X10 Z1\nM30\n");
    assert!(found.is_empty(), "{found:?}");
    let hover = client.request("textDocument/hover", at(&uri, 1, 4));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(shown.contains("X1 10") && shown.contains("Z1 1"), "{shown}");
    assert!(!shown.contains("past its software limit"), "{shown}");
    let value = client.request("textDocument/hover", at(&uri, 0, 0));
    let shown = value["contents"]["value"].as_str().expect("markdown");
    assert!(shown.contains("1.5"), "{shown}");
    // A block past a software limit is a K007 finding on it, as `run` says.
    let beyond = format!("file://{}", dir.join("BEYOND.MPF").display());
    let found = client.open(&beyond, "G0 X10 Z1\nG0 Z3\nM30\n");
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0]["code"], "K007", "{found:?}");
    assert_eq!(found[0]["range"]["start"]["line"], 1, "{found:?}");
    let message = found[0]["message"].as_str().expect("a message");
    assert!(
        message.contains("Z1 reaches 3, 1.5 past its plus software limit 1.5"),
        "{message}"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A call of a subprogram the program does not define goes to the PROC of
/// the file beside it, as the control finds it (any case).
#[test]
fn a_call_goes_to_the_subprogram_beside_the_program() {
    let dir = scratch("lsp-subprogram");
    std::fs::write(
        dir.join("pocket.spf"),
        ";pocket\nPROC POCKET(REAL _DEPTH, INT _N)\nM17\n",
    )
    .expect("subprogram");
    let uri = format!("file://{}", dir.join("MAIN.MPF").display());
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, "G17\nPOCKET(5, 2)\nM30\n");
    let definition = client.request("textDocument/definition", at(&uri, 1, 2));
    let expected = format!("file://{}", dir.join("pocket.spf").display());
    assert_eq!(definition["uri"], expected.as_str(), "{definition}");
    assert_eq!(
        definition["range"],
        json!({ "start": { "line": 1, "character": 5 }, "end": { "line": 1, "character": 11 } })
    );
    let hover = client.request("textDocument/hover", at(&uri, 1, 2));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(shown.contains("PROC in `"), "{shown}");
    assert!(shown.contains("pocket.spf`, 2 parameter(s)"), "{shown}");
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A GUD variable and a macro of the definition files sinuprep.toml names
/// go to their DEF and DEFINE there.
#[test]
fn a_global_variable_goes_to_its_definition_file() {
    let dir = scratch("lsp-gud");
    std::fs::write(
        dir.join("GUD7.DEF"),
        "; globals\nDEF NCK REAL _OFFSET_Z\nM30\n",
    )
    .expect("gud");
    std::fs::write(dir.join("sinuprep.toml"), "definitions = [\"GUD7.DEF\"]\n").expect("toml");
    let uri = format!("file://{}", dir.join("MAIN.MPF").display());
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, "G1 Z=_OFFSET_Z F100\nM30\n");
    let definition = client.request("textDocument/definition", at(&uri, 0, 7));
    let expected = format!("file://{}", dir.join("GUD7.DEF").display());
    assert_eq!(definition["uri"], expected.as_str(), "{definition}");
    assert_eq!(
        definition["range"],
        json!({ "start": { "line": 1, "character": 13 }, "end": { "line": 1, "character": 22 } })
    );
    let hover = client.request("textDocument/hover", at(&uri, 0, 7));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("defined in `") && shown.contains("GUD7.DEF`"),
        "{shown}"
    );
    // The workspace's symbols reach beyond the open documents: the GUD
    // variable in its definition file, the subprogram beside the program.
    std::fs::write(
        dir.join("FACE_OFFSET.SPF"),
        "PROC FACE_OFFSET(REAL _Z)\nM17\n",
    )
    .expect("spf");
    client.notify("workspace/didChangeWatchedFiles", json!({ "changes": [] }));
    let found = client.request("workspace/symbol", json!({ "query": "offset" }));
    let found: Vec<(&str, u64, &str, &str)> = found
        .as_array()
        .expect("symbols")
        .iter()
        .map(|s| {
            (
                s["name"].as_str().expect("a name"),
                s["kind"].as_u64().expect("a kind"),
                s["containerName"].as_str().expect("its file"),
                s["location"]["uri"].as_str().expect("a uri"),
            )
        })
        .collect();
    let face = format!("file://{}", dir.join("FACE_OFFSET.SPF").display());
    assert_eq!(
        found,
        [
            ("FACE_OFFSET", 12, "FACE_OFFSET.SPF", face.as_str()),
            ("_OFFSET_Z", 13, "GUD7.DEF", expected.as_str())
        ]
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// Semantic tokens colour a program in every editor, with no grammar of
/// its own: each word's line, column and length in the agreed unit
/// (UTF-16 here), and its type in the server's legend.
#[test]
fn semantic_tokens_give_each_word_its_class() {
    let (mut client, initialized) = Client::start(json!({}));
    let legend = &initialized["capabilities"]["semanticTokensProvider"]["legend"]["tokenTypes"];
    let types: Vec<&str> = legend
        .as_array()
        .expect("legend")
        .iter()
        .map(|t| t.as_str().expect("type"))
        .collect();
    client.open(URI, "G1 X10 ; ü😀\nIF R1>0 GOTOF END\nEND: M30\n");
    let tokens = client.request(
        "textDocument/semanticTokens/full",
        json!({ "textDocument": { "uri": URI } }),
    );
    let data: Vec<u64> = tokens["data"]
        .as_array()
        .expect("data")
        .iter()
        .map(|n| n.as_u64().expect("number"))
        .collect();
    let (mut line, mut start) = (0, 0);
    let mut decoded = Vec::new();
    for token in data.chunks(5) {
        if token[0] > 0 {
            start = 0;
        }
        line += token[0];
        start += token[1];
        decoded.push((line, start, token[2], types[token[3] as usize], token[4]));
    }
    assert_eq!(
        decoded,
        [
            (0, 0, 2, "keyword", 0),
            (0, 3, 1, "property", 0),
            (0, 4, 2, "number", 0),
            // `ü` is one UTF-16 unit, `😀` two.
            (0, 7, 5, "comment", 0),
            (1, 0, 2, "keyword", 0),
            (1, 3, 2, "variable", 1),
            (1, 6, 1, "number", 0),
            (1, 8, 5, "keyword", 0),
            (1, 14, 3, "label", 0),
            (2, 0, 3, "label", 0),
            (2, 5, 3, "keyword", 0),
        ]
    );
    let range = client.request(
        "textDocument/semanticTokens/range",
        json!({ "textDocument": { "uri": URI },
                "range": { "start": { "line": 2, "character": 0 }, "end": { "line": 2, "character": 3 } } }),
    );
    assert_eq!(range["data"], json!([2, 0, 3, 7, 0, 0, 5, 3, 3, 0]));
    client.stop();
}

/// A program with more findings than an editor can show gets the first
/// 10,000 by position, and one more that says how many there are.
#[test]
fn findings_past_the_most_shown_are_counted_not_sent() {
    let (mut client, _) = Client::start(json!({}));
    let uri = "untitled:MANY.MPF";
    let found = client.open(uri, &("G1 F100 X1 X2\n".repeat(10_005) + "M30\n"));
    assert_eq!(found.len(), 10_001);
    assert!(found[..10_000].iter().all(|d| d["code"] == "N022"));
    assert_eq!(found[9_999]["range"]["start"]["line"], 9_999);
    let last = &found[10_000];
    assert_eq!(last["severity"], 3, "{last}");
    assert_eq!(
        last["range"]["start"],
        json!({ "line": 10_000, "character": 11 })
    );
    let message = last["message"].as_str().expect("a message");
    assert!(
        message.starts_with("10000 of the 10005 findings are shown")
            && message.ends_with(
                "`sinuprep check` of the saved file (and `sinuprep run` for K007) lists every one"
            ),
        "{message}"
    );
    client.stop();
}

/// After a change the client is sent what changed in the words' colours
/// (`semanticTokens/full/delta`): applied to the tokens it had, the edits
/// give exactly the tokens a whole request gives, and they are a few
/// tokens, not the program's. A result id that is not the last sent gets
/// every token.
#[test]
fn semantic_tokens_after_a_change_are_sent_as_what_changed() {
    let (mut client, initialized) = Client::start(json!({}));
    let full = &initialized["capabilities"]["semanticTokensProvider"]["full"];
    assert_eq!(full, &json!({ "delta": true }));
    let lines: String = (0..2_000)
        .map(|i| format!("N{i} G1 X=R{} Y{i} F800 ; pass {i}\n", i % 90))
        .collect();
    client.open(URI, &lines);
    let tokens = |client: &mut Client, method: &str, previous: Option<&str>| {
        let mut params = json!({ "textDocument": { "uri": URI } });
        if let Some(previous) = previous {
            params["previousResultId"] = json!(previous);
        }
        client.request(&format!("textDocument/semanticTokens/{method}"), params)
    };
    let first = tokens(&mut client, "full", None);
    let mut id = first["resultId"].as_str().expect("a result id").to_string();
    let mut data: Vec<Value> = first["data"].as_array().expect("tokens").clone();
    let stale = id.clone();
    for (version, line) in [(2, 700), (3, 0), (4, 2_000), (5, 1_200)] {
        let change = if version == 5 {
            // A line's words removed.
            json!({ "range": { "start": { "line": line, "character": 0 },
                               "end": { "line": line + 1, "character": 0 } }, "text": "" })
        } else {
            json!({ "range": { "start": { "line": line, "character": 0 },
                               "end": { "line": line, "character": 0 } },
                    "text": "DEF REAL _NEW=1\nIF _NEW>R3 GOTOF END\n" })
        };
        client.notify(
            "textDocument/didChange",
            json!({ "textDocument": { "uri": URI, "version": version },
                    "contentChanges": [change] }),
        );
        let delta = tokens(&mut client, "full/delta", Some(&id));
        let edits = delta["edits"].as_array().expect("edits, not every token");
        let mut sent = 0;
        for edit in edits.iter().rev() {
            let start = edit["start"].as_u64().expect("start") as usize;
            let deleted = edit["deleteCount"].as_u64().expect("count") as usize;
            let inserted = edit["data"].as_array().cloned().unwrap_or_default();
            sent += inserted.len();
            data.splice(start..start + deleted, inserted);
        }
        assert!(
            sent <= 5 * 20,
            "{sent} integers sent for a change of two lines"
        );
        let whole = tokens(&mut client, "full", None);
        assert_eq!(
            Some(&data),
            whole["data"].as_array(),
            "the delta after version {version} applied"
        );
        id = whole["resultId"].as_str().expect("a result id").to_string();
    }
    let again = tokens(&mut client, "full/delta", Some(&stale));
    assert_eq!(
        again["data"].as_array(),
        Some(&data),
        "every token for a stale id"
    );
    client.stop();
}

/// Past 10 MB the words are not coloured at once: the request is refused
/// with the reason, and a range of lines is still coloured; one long line
/// counts by its bytes.
#[test]
fn semantic_tokens_of_a_huge_program_are_refused_with_the_reason() {
    let (mut client, _) = Client::start(json!({}));
    let uri = "untitled:HUGE.MPF";
    client.open(uri, &"G1 X1 Y2 Z3\n".repeat(1_000_000));
    let full = client.request(
        "textDocument/semanticTokens/full",
        json!({ "textDocument": { "uri": uri } }),
    );
    let message = full["error"]["message"].as_str().expect("refused");
    assert!(
        message.contains("at most 10 MB") && message.contains("12.0 MB were asked for"),
        "{message}"
    );
    let range = client.request(
        "textDocument/semanticTokens/range",
        json!({ "textDocument": { "uri": uri },
                "range": { "start": { "line": 5, "character": 0 }, "end": { "line": 5, "character": 5 } } }),
    );
    assert_eq!(range["data"].as_array().map(Vec::len), Some(35), "{range}");
    let long = "untitled:LONG.MPF";
    client.open(long, &format!("{}\nM30\n", "X1 ".repeat(3_400_000)));
    let line = client.request(
        "textDocument/semanticTokens/range",
        json!({ "textDocument": { "uri": long },
                "range": { "start": { "line": 0, "character": 0 }, "end": { "line": 0, "character": 5 } } }),
    );
    let message = line["error"]["message"].as_str().expect("refused");
    assert!(message.contains("10.2 MB were asked for"), "{message}");
    client.stop();
}

/// A run of comment lines folds as a comment; a lone one does not.
#[test]
fn a_run_of_comment_lines_folds() {
    let (mut client, _) = Client::start(json!({}));
    client.open(
        URI,
        "; tool list\n;  T1 drill\n  ; T2 mill\nG0 X0\n; alone\nWHILE R1<3\nR1=R1+1\nENDWHILE\nM30\n",
    );
    let folding = client.request(
        "textDocument/foldingRange",
        json!({ "textDocument": { "uri": URI } }),
    );
    assert_eq!(
        folding,
        json!([
            { "startLine": 0, "endLine": 2, "kind": "comment" },
            { "startLine": 5, "endLine": 7 }
        ])
    );
    client.stop();
}

/// A definition file open in the editor counts as typed, before it is
/// saved: the programs that read it are checked again with its text, and
/// with the file's once it is closed unsaved.
#[test]
fn an_open_definition_file_applies_before_it_is_saved() {
    let dir = scratch("lsp-buffers");
    std::fs::write(dir.join("GUD7.DEF"), "DEF NCK REAL ZERO_A\nM30\n").expect("gud");
    std::fs::write(dir.join("sinuprep.toml"), "definitions = [\"GUD7.DEF\"]\n").expect("toml");
    let program = format!("file://{}", dir.join("MAIN.MPF").display());
    let gud = format!("file://{}", dir.join("GUD7.DEF").display());
    let (mut client, _) = Client::start(json!({}));
    let found = client.open(&program, "R1=ZERO_A+ZERO_B\nM30\n");
    assert_eq!(codes(&found), ["N005"], "{found:?}");
    client.open(&gud, "DEF NCK REAL ZERO_A, ZERO_B\nM30\n");
    assert_eq!(codes(&client.diagnostics(&program)), Vec::<&str>::new());
    client.notify(
        "textDocument/didClose",
        json!({ "textDocument": { "uri": gud } }),
    );
    assert_eq!(codes(&client.diagnostics(&program)), ["N005"]);
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// Typing in a definition file reads the settings again once the typing
/// pauses, not at each keystroke (each reading analyses every open document
/// again); a request about another document reads them first.
#[test]
fn typing_in_a_definition_file_reads_the_settings_once_it_pauses() {
    let dir = scratch("lsp-settled");
    std::fs::write(dir.join("GUD7.DEF"), "DEF NCK REAL ZERO_A\nM30\n").expect("gud");
    std::fs::write(dir.join("sinuprep.toml"), "definitions = [\"GUD7.DEF\"]\n").expect("toml");
    let program = format!("file://{}", dir.join("MAIN.MPF").display());
    let gud = format!("file://{}", dir.join("GUD7.DEF").display());
    let capabilities = json!({ "textDocument": { "diagnostic": { "dynamicRegistration": false } },
                               "workspace": { "diagnostics": { "refreshSupport": true } } });
    let (mut client, _) = Client::start(capabilities);
    let refresh = |message: &Value| message["method"] == "workspace/diagnostic/refresh";
    let open = |uri: &str, text: &str| json!({ "textDocument": { "uri": uri, "languageId": "sinumerik", "version": 1, "text": text } });
    client.notify(
        "textDocument/didOpen",
        open(&program, "R1=ZERO_A+ZERO_B\nM30\n"),
    );
    client.notify(
        "textDocument/didOpen",
        open(&gud, "DEF NCK REAL ZERO_A\nM30\n"),
    );
    let keystrokes = 20;
    for version in 2..2 + keystrokes {
        let text = match version < 1 + keystrokes {
            true => format!("DEF NCK REAL ZERO_A, ZERO{}\nM30\n", &"_B"[..version % 2]),
            false => "DEF NCK REAL ZERO_A, ZERO_B\nM30\n".to_string(),
        };
        client.notify(
            "textDocument/didChange",
            json!({ "textDocument": { "uri": gud, "version": version },
                    "contentChanges": [{ "text": text }] }),
        );
    }
    let pulled = client.request(
        "textDocument/diagnostic",
        json!({ "textDocument": { "uri": program } }),
    );
    let items = pulled["items"].as_array().expect("items");
    assert_eq!(
        codes(items),
        Vec::<&str>::new(),
        "the last text counts: {pulled}"
    );
    // The opening and the reading before the pull; a slow moment between
    // two keystrokes may add one.
    let readings = client.kept(refresh);
    assert!(
        readings <= 3,
        "{readings} readings for {keystrokes} keystrokes"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// An archive is checked as `check` checks it: each program with what the
/// archive gives it (its macros here), its findings placed in the archive,
/// named by the member; not as one program (where the macros' member would
/// read as a program without its end, and the DEF as coming too late).
#[test]
fn an_archive_is_checked_program_by_program() {
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/archive");
    let (mut client, _) = Client::start(json!({}));
    let read = |name: &str| {
        let bytes = std::fs::read(fixtures.join(name)).expect("fixture");
        String::from_utf8(bytes).expect("text archive")
    };
    let macros = format!("file://{}", fixtures.join("MACROS.ARC").display());
    let found = client.open(&macros, &read("MACROS.ARC"));
    assert_eq!(codes(&found), Vec::<&str>::new(), "{found:?}");
    let shop = format!("file://{}", fixtures.join("SHOP.ARC").display());
    let found = client.open(&shop, &read("SHOP.ARC"));
    assert_eq!(codes(&found), ["N022"], "{found:?}");
    assert_eq!(
        found[0]["range"]["start"],
        json!({ "line": 57, "character": 7 })
    );
    assert!(found[0]["message"]
        .as_str()
        .expect("message")
        .starts_with("PART_MPF: "));
    client.stop();
}

/// A hover on a G or M function says what it does, in the Programming
/// Manual's terms; a machine builder's M function is not guessed at.
#[test]
fn a_g_or_m_function_or_system_variable_hover_says_what_it_is() {
    let (mut client, _) = Client::start(json!({}));
    client.open(URI, PART);
    let hover = client.request("textDocument/hover", at(URI, 3, 1));
    assert_eq!(
        hover["contents"]["value"],
        "G17: working plane X/Y, infeed along Z (G group 6)"
    );
    assert_eq!(
        hover["range"],
        json!({ "start": { "line": 3, "character": 0 }, "end": { "line": 3, "character": 3 } })
    );
    let hover = client.request("textDocument/hover", at(URI, 3, 20));
    assert_eq!(hover["contents"]["value"], "M3: spindle clockwise");
    client.open("untitled:CARR.MPF", "$TC_CARR9[1]=1\nM30\n");
    let hover = client.request("textDocument/hover", at("untitled:CARR.MPF", 0, 4));
    assert_eq!(
        hover["contents"]["value"],
        "$TC_CARR9[m]: swivel data record m, direction of rotary axis 1 (v1), z"
    );
    client.open("untitled:COOLANT.MPF", "M8\nM30\n");
    let hover = client.request("textDocument/hover", at("untitled:COOLANT.MPF", 0, 1));
    assert_eq!(hover, Value::Null);
    client.stop();
}

/// Workspace symbols: the names defined in every open document that hold
/// the query, in any case.
#[test]
fn workspace_symbols_search_every_open_document() {
    let (mut client, _) = Client::start(json!({}));
    client.open("untitled:A.MPF", "POCKET_ROUGH:\nG0 X0\nM30\n");
    client.open(
        "untitled:B.SPF",
        "PROC POCKET_FINISH\nDEF REAL _DEPTH\nM17\n",
    );
    let found = client.request("workspace/symbol", json!({ "query": "pocket" }));
    let names: Vec<(&str, &str)> = found
        .as_array()
        .expect("symbols")
        .iter()
        .map(|s| {
            (
                s["name"].as_str().expect("name"),
                s["location"]["uri"].as_str().expect("uri"),
            )
        })
        .collect();
    assert_eq!(
        names,
        [
            ("POCKET_ROUGH", "untitled:A.MPF"),
            ("POCKET_FINISH", "untitled:B.SPF")
        ]
    );
    client.stop();
}

/// A hand-written program of 75,000 lines, 15,000 labels: seconds to
/// analyse in a test build.
fn large_program() -> String {
    let mut large = String::new();
    for n in 0..15_000 {
        large.push_str(&format!(
            "LOOP{n}:\nIF R1>{n}\nR2=R2+SIN({n})*COS(R1)\nG1 X=R2 Y{n} F500\nENDIF\n"
        ));
    }
    large.push_str("M30\n");
    large
}

/// Many hovers asked while a large program is analysed take no thread
/// each: the request threads are few; a hover superseded by a newer one on
/// the same document, or cancelled, is answered `RequestCancelled` (-32800)
/// without its work, and the newest gets its answer.
#[test]
fn hovers_are_bounded_superseded_and_cancelled() {
    let (mut client, _) = Client::start(json!({}));
    let large = large_program();
    let uri = "untitled:LARGE.MPF";
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": uri, "languageId": "sinumerik",
                                  "version": 1, "text": large } }),
    );
    let hovers = 200;
    for id in 0..hovers {
        client.send(
            json!({ "jsonrpc": "2.0", "id": id, "method": "textDocument/hover",
            "params": { "textDocument": { "uri": uri },
                        "position": { "line": 2, "character": 1 } } }),
        );
    }
    // The last but one cancelled as well: superseded already, it stays so.
    client.notify("$/cancelRequest", json!({ "id": hovers - 2 }));
    if let Some(threads) = client.threads() {
        assert!(threads < 16, "{threads} threads for {hovers} hovers");
    }
    let mut cancelled = 0;
    let mut answered = Vec::new();
    for _ in 0..hovers {
        let answer = client.next(|message| message.get("id").is_some());
        if answer["error"]["code"] == -32800 {
            cancelled += 1;
        } else {
            answered.push(answer["id"].clone());
        }
    }
    assert!(answered.contains(&json!(hovers - 1)), "{answered:?}");
    assert!(cancelled >= hovers - 8, "{cancelled} of {hovers} cancelled");
    client.stop();
}

/// Formatting a large document holds up no request about another: asked
/// first, it is answered after a hover on a small one.
#[test]
fn formatting_a_large_document_holds_up_no_other() {
    let (mut client, _) = Client::start(json!({}));
    client.open(URI, PART);
    let large = "IF R1>0\nG1  X1 Y2 F500\nENDIF\n".repeat(60_000) + "M30\n";
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": "untitled:LARGE.MPF", "languageId": "sinumerik",
                                  "version": 1, "text": large } }),
    );
    client.send(
        json!({ "jsonrpc": "2.0", "id": 80, "method": "textDocument/formatting",
        "params": { "textDocument": { "uri": "untitled:LARGE.MPF" },
                    "options": { "tabSize": 2, "insertSpaces": true } } }),
    );
    client.send(
        json!({ "jsonrpc": "2.0", "id": 81, "method": "textDocument/hover",
        "params": { "textDocument": { "uri": URI }, "position": { "line": 3, "character": 1 } } }),
    );
    let first = client.next(|message| message.get("id").is_some());
    assert_eq!(first["id"], 81, "the hover is answered first: {first}");
    let formatted = client.next(|message| message["id"] == 80);
    assert!(formatted["result"]
        .as_array()
        .is_some_and(|edits| !edits.is_empty()));
    client.stop();
}

/// A large program is analysed off the main loop: a request about another
/// document is answered while its findings are still being made, even when
/// a request about the large one came first; its findings come after.
#[test]
fn a_large_program_is_analysed_while_other_requests_are_answered() {
    let (mut client, _) = Client::start(json!({}));
    client.open(URI, PART);
    let large = large_program();
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": "untitled:LARGE.MPF", "languageId": "sinumerik",
                                  "version": 1, "text": large } }),
    );
    // Asked about first, the large program is answered once analysed: on
    // a thread of its own, while the hover on the small one is answered.
    client.send(
        json!({ "jsonrpc": "2.0", "id": 76, "method": "textDocument/documentSymbol",
                        "params": { "textDocument": { "uri": "untitled:LARGE.MPF" } } }),
    );
    client.send(
        json!({ "jsonrpc": "2.0", "id": 77, "method": "textDocument/hover",
                        "params": { "textDocument": { "uri": URI },
                                    "position": { "line": 3, "character": 1 } } }),
    );
    let first = client.next(|message| message.get("id").is_some());
    assert_eq!(first["id"], 77, "the hover is answered first: {first}");
    let symbols = client.next(|message| message["id"] == 76);
    let labels = symbols["result"].as_array().map_or(0, Vec::len);
    assert_eq!(labels, 15_000, "every label is a symbol");
    let found = client.diagnostics("untitled:LARGE.MPF");
    assert!(found.is_empty(), "{found:?}");
    client.stop();
}

/// A large program changed twice while its first version is analysed: that
/// analysis stops (within a few thousand lines) and is not published; the
/// first findings published are the last version's.
#[test]
fn a_version_changed_while_analysed_is_not_published() {
    let (mut client, _) = Client::start(json!({}));
    let uri = "untitled:CHANGED.MPF";
    let large = large_program();
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": uri, "languageId": "sinumerik",
                                  "version": 1, "text": large } }),
    );
    let insert = |version: u32, end: u32, text: &str| {
        json!({ "textDocument": { "uri": uri, "version": version },
                "contentChanges": [{ "range": { "start": { "line": 0, "character": 0 },
                                                "end": { "line": end, "character": 0 } },
                                     "text": text }] })
    };
    client.notify("textDocument/didChange", insert(2, 0, "GOTOF SECOND\n"));
    client.notify("textDocument/didChange", insert(3, 1, "GOTOF THIRD\n"));
    let found = client.diagnostics(uri);
    let messages: Vec<&str> = found
        .iter()
        .map(|d| d["message"].as_str().expect("a message"))
        .collect();
    assert!(
        messages.len() == 1 && messages[0].contains("THIRD"),
        "the first findings published are the third version's: {messages:?}"
    );
    client.stop();
}

#[test]
fn formatting_gives_the_edits_of_fmt() {
    let (mut client, initialized) = Client::start(json!({}));
    let capabilities = &initialized["capabilities"];
    assert_eq!(capabilities["documentFormattingProvider"], true);
    assert_eq!(capabilities["documentRangeFormattingProvider"], true);
    client.open(URI, "; ü😀\nif r1==1\ng1  x10\nendif\n");
    let edits = client.request(
        "textDocument/formatting",
        json!({ "textDocument": { "uri": URI }, "options": { "tabSize": 4, "insertSpaces": true } }),
    );
    assert_eq!(
        edits,
        json!([
            { "range": { "start": { "line": 1, "character": 0 }, "end": { "line": 1, "character": 8 } }, "newText": "IF R1==1" },
            { "range": { "start": { "line": 2, "character": 0 }, "end": { "line": 2, "character": 7 } }, "newText": "  G1 X10" },
            { "range": { "start": { "line": 3, "character": 0 }, "end": { "line": 3, "character": 5 } }, "newText": "ENDIF" },
        ])
    );
    // A range gets the edits of the lines it touches.
    let edits = client.request(
        "textDocument/rangeFormatting",
        json!({
            "textDocument": { "uri": URI },
            "range": { "start": { "line": 2, "character": 1 }, "end": { "line": 2, "character": 2 } },
            "options": { "tabSize": 4, "insertSpaces": true },
        }),
    );
    assert_eq!(edits.as_array().map(Vec::len), Some(1), "{edits}");
    assert_eq!(edits[0]["newText"], "  G1 X10");
    let (code, _) = client.stop();
    assert_eq!(code, Some(0));
}

/// A name defined again points at its first definition (related
/// information), which the editor shows beside the finding.
#[test]
fn a_second_definition_points_at_the_first() {
    let (mut client, _) = Client::start(json!({}));
    let found = client.open(URI, "DEF REAL LENGTH\nR1=LENGTH\nDEF INT LENGTH\nM30\n");
    let again = found
        .iter()
        .find(|d| {
            d["message"]
                .as_str()
                .is_some_and(|m| m.contains("already defined"))
        })
        .expect("a finding on the second DEF");
    let related = &again["relatedInformation"][0];
    assert_eq!(related["location"]["uri"], URI);
    assert_eq!(
        related["location"]["range"],
        json!({ "start": { "line": 0, "character": 9 }, "end": { "line": 0, "character": 15 } })
    );
    assert_eq!(related["message"], "`LENGTH` is first defined here");
    client.stop();
}

/// A hover on a variable gives its type from its DEF and the value it holds
/// at that use as the walk knows it offline, with where it comes from; a
/// value that depends on a branch the walk cannot decide is said to be
/// unknown, never guessed.
#[test]
fn a_variable_hover_gives_its_type_and_its_value_there() {
    let program = "\
DEF REAL _DEPTH=5
DEF INT _N
R1=_DEPTH*2
IF R5>0
_N=1
ENDIF
G1 Z=-_DEPTH X=R1 Y=_N
R1=R1+1
M30
";
    let (mut client, _) = Client::start(json!({}));
    client.open(URI, program);
    let hover = |client: &mut Client, line, character| {
        let hover = client.request("textDocument/hover", at(URI, line, character));
        hover["contents"]["value"]
            .as_str()
            .expect("markdown")
            .to_string()
    };
    let depth = hover(&mut client, 6, 7);
    assert!(depth.contains("Type: `REAL`"), "{depth}");
    assert!(
        depth.contains("Value here: `5`, assigned on line 1"),
        "{depth}"
    );
    let r1 = hover(&mut client, 6, 15);
    assert!(r1.contains("Value here: `10`, assigned on line 3"), "{r1}");
    assert!(!r1.contains("Type"), "an R parameter has no DEF: {r1}");
    // Written in a branch the walk cannot decide: 0 or 1, so unknown.
    let n = hover(&mut client, 6, 20);
    assert!(n.contains("Type: `INT`"), "{n}");
    assert!(n.contains("Value here: unknown offline: `_N`"), "{n}");
    assert!(!n.contains("`0`") && !n.contains("`1`"), "{n}");
    // Inside the branch, the value it is given there.
    let given = hover(&mut client, 4, 0);
    assert!(
        given.contains("Value after this line: `1`, assigned on line 5"),
        "{given}"
    );
    // The read of R1 on line 8 sees 10, its target holds 11 after it.
    let read = hover(&mut client, 7, 4);
    assert!(read.contains("Value here: `10`"), "{read}");
    let written = hover(&mut client, 7, 0);
    assert!(
        written.contains("Value after this line: `11`, assigned on line 8"),
        "{written}"
    );
    // The DEF itself: what it starts with.
    let defined = hover(&mut client, 0, 10);
    assert!(defined.contains("Type: `REAL`"), "{defined}");
    assert!(defined.contains("Value after this line: `5`"), "{defined}");
    // A PROC parameter: its value is the caller's, unknown here.
    client.open(
        "untitled:DRILL.SPF",
        "PROC DRILL(INT _DEPTH)\nG1 Z=-_DEPTH\nM17\n",
    );
    let shown = client.request("textDocument/hover", at("untitled:DRILL.SPF", 0, 16));
    let shown = shown["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("Type: `INT`") && shown.contains("Value: given by the caller"),
        "{shown}"
    );
    let shown = client.request("textDocument/hover", at("untitled:DRILL.SPF", 1, 8));
    let shown = shown["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("Type: `INT`") && shown.contains("Value here: unknown offline"),
        "{shown}"
    );
    client.stop();
}

/// A value measured on the machine is unknown offline, naming the
/// measurement; with the values file of `sinuprep.toml` it is that file's
/// value, and the hover says which file and line gave it.
#[test]
fn a_variable_hover_names_the_measurement_or_the_values_file() {
    let dir = scratch("lsp-values");
    let program = "CYCLE977(1,,,1,20)\nR10=_OVR[16]\nG1 X=R10\nM30\n";
    let uri = format!("file://{}", dir.join("PROBE.MPF").display());
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, program);
    let hover = client.request("textDocument/hover", at(&uri, 2, 6));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("Value here: unknown offline: `R10` (measured on line 1"),
        "{shown}"
    );
    client.stop();

    std::fs::write(dir.join("probe.values"), "R10=0.25\n").expect("values");
    std::fs::write(dir.join("sinuprep.toml"), "values = \"probe.values\"\n").expect("toml");
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, program);
    let hover = client.request("textDocument/hover", at(&uri, 2, 6));
    let shown = hover["contents"]["value"].as_str().expect("markdown");
    assert!(
        shown.contains("Value here: `0.25`, supplied by ") && shown.contains("probe.values:1"),
        "{shown}"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// The labels of each completion at `line`, `character` of `uri`.
fn completed(client: &mut Client, uri: &str, line: u32, character: u32) -> Vec<Value> {
    let items = client.request("textDocument/completion", at(uri, line, character));
    items.as_array().expect("a list of items").clone()
}

fn labels(items: &[Value]) -> Vec<&str> {
    items
        .iter()
        .map(|item| item["label"].as_str().expect("a label"))
        .collect()
}

/// On the empty line an editor counts after the last line end (and in an
/// empty document), completion and signature help answer: the words of the
/// language, no error.
#[test]
fn completion_on_the_empty_last_line_answers() {
    let (mut client, _) = Client::start(json!({}));
    for (n, text) in ["", "G0 X1\n", "G0 X1\r\n", "G0 X1\r", "M30\n\n"]
        .into_iter()
        .enumerate()
    {
        let uri = format!("untitled:LAST{n}.MPF");
        client.open(&uri, text);
        let line = u32::try_from(
            text.matches('\n').count() + text.matches('\r').count() - text.matches("\r\n").count(),
        )
        .expect("a few lines");
        let items = client.request("textDocument/completion", at(&uri, line, 0));
        assert!(items.get("error").is_none(), "{text:?}: {items}");
        let words = items.as_array().expect("a list of items");
        assert!(labels(words).contains(&"STOPRE"), "{text:?}: {items}");
        let help = client.request("textDocument/signatureHelp", at(&uri, line, 0));
        assert!(help.get("error").is_none(), "{text:?}: {help}");
    }
    client.stop();
}

const JUMPS: &str = "\
DEF REAL _DEPTH=5, _DEPTH2
START:
G17 G90
R1=$P_U
GOTOF 
GOTOB 
STOP
G1 Z=-_DE ; GOTOF 
LATER:
cycle80
AGAIN: R1=R1+1 GOTOB 
REPEAT 
GOTOB LAxx
M30
";

/// Completion offers what may stand there: the labels a jump reaches in
/// its direction, the system variables after `$`, the language's words with
/// their meaning, the program's variables, a cycle as a snippet; nothing in
/// a comment.
#[test]
fn completion_offers_what_may_stand_there() {
    let snippets = json!({ "textDocument": { "completion": { "completionItem": { "snippetSupport": true } } } });
    let (mut client, initialized) = Client::start(snippets);
    let capabilities = &initialized["capabilities"];
    assert_eq!(
        capabilities["completionProvider"]["triggerCharacters"],
        json!(["$"])
    );
    client.open(URI, JUMPS);

    assert_eq!(
        labels(&completed(&mut client, URI, 4, 6)),
        ["LATER", "AGAIN"]
    );
    assert_eq!(labels(&completed(&mut client, URI, 5, 6)), ["START"]);
    // A GOTOB finds a label on its own line; a REPEAT those above it.
    let back = ["START", "LATER", "AGAIN"];
    assert_eq!(labels(&completed(&mut client, URI, 10, 21)), back);
    assert_eq!(labels(&completed(&mut client, URI, 11, 7)), back);
    // In the middle of a word, the item replaces all of it.
    let inside = completed(&mut client, URI, 12, 8);
    assert_eq!(labels(&inside), ["LATER"]);
    assert_eq!(
        inside[0]["textEdit"]["range"],
        json!({ "start": { "line": 12, "character": 6 }, "end": { "line": 12, "character": 10 } })
    );

    // Block numbers once an `N` is typed, those the jump reaches.
    let numbered = "untitled:NUMBERED.MPF";
    client.open(
        numbered,
        "N10 G0 X0\nN20 NEXT: GOTOF N\n/1 N30 G1 X10\nN40 GOTOB N\nM30\n",
    );
    assert_eq!(
        labels(&completed(&mut client, numbered, 1, 17)),
        ["N30", "N40"]
    );
    assert_eq!(
        labels(&completed(&mut client, numbered, 3, 11)),
        ["NEXT", "N10", "N20", "N30", "N40"]
    );

    let system = completed(&mut client, URI, 3, 7);
    assert!(labels(&system).contains(&"$P_UIFR"), "{system:?}");
    assert!(
        labels(&system).iter().all(|l| l.starts_with("$P_U")),
        "{system:?}"
    );
    // The item replaces what is typed, `$` included.
    let edit = &system[0]["textEdit"];
    assert_eq!(
        edit["range"],
        json!({ "start": { "line": 3, "character": 3 }, "end": { "line": 3, "character": 7 } })
    );

    let words = completed(&mut client, URI, 6, 4);
    let stopre = words
        .iter()
        .find(|item| item["label"] == "STOPRE")
        .expect("STOPRE offered");
    let meaning = stopre["documentation"]["value"].as_str().expect("markdown");
    assert!(meaning.contains("preprocessing"), "{meaning}");

    let variables = completed(&mut client, URI, 7, 9);
    assert_eq!(labels(&variables), ["_DEPTH", "_DEPTH2"]);
    assert!(completed(&mut client, URI, 7, 18).is_empty(), "a comment");

    // Typed in lower case, the cycle comes in lower case, its parameters
    // as the snippet's placeholders.
    let cycles = completed(&mut client, URI, 9, 7);
    let cycle800 = cycles
        .iter()
        .find(|item| item["label"] == "CYCLE800")
        .expect("CYCLE800 offered");
    assert_eq!(cycle800["insertTextFormat"], 2, "a snippet");
    let text = cycle800["textEdit"]["newText"].as_str().expect("text");
    assert!(
        text.starts_with("cycle800(${1:_FR},${2:_TC},${3:_ST},"),
        "{text}"
    );
    assert!(text.ends_with("${16:_DMODE})$0"), "{text}");
    client.stop();

    // A client without snippets gets the name and the bracket.
    let (mut client, _) = Client::start(json!({}));
    client.open(URI, JUMPS);
    let cycles = completed(&mut client, URI, 9, 7);
    let cycle800 = cycles
        .iter()
        .find(|item| item["label"] == "CYCLE800")
        .expect("CYCLE800 offered");
    assert_eq!(cycle800["textEdit"]["newText"], "cycle800(");
    assert_eq!(cycle800.get("insertTextFormat"), None);
    client.stop();
}

/// Signature help names the parameter being written: a cycle's with its
/// meaning, a PROC's of this program and of the file beside it as their
/// headers declare them.
#[test]
fn signature_help_names_the_parameter_being_written() {
    let dir = scratch("lsp-signature");
    std::fs::write(
        dir.join("pocket.spf"),
        ";pocket\nPROC POCKET(REAL _DEPTH, VAR INT _N[2])\nM17\n",
    )
    .expect("subprogram");
    let uri = format!("file://{}", dir.join("MAIN.SPF").display());
    let offsets = json!({ "textDocument": { "signatureHelp": { "signatureInformation": {
        "parameterInformation": { "labelOffsetSupport": true } } } } });
    let (mut client, _) = Client::start(offsets);
    let text = "PROC MAIN(REAL _A, STRING[8] _B) SAVE\nCYCLE800(0,\"TC1\",SIN(3),\nMAIN(1, \nPOCKET(5, \"a,b\", \nM17\n";
    client.open(&uri, text);
    let help = |client: &mut Client, line: u32, character: u32| {
        client.request("textDocument/signatureHelp", at(&uri, line, character))
    };

    let cycle = help(&mut client, 1, 24);
    let signature = &cycle["signatures"][0];
    let label = signature["label"].as_str().expect("a label");
    assert!(
        label.starts_with("CYCLE800(_FR, _TC, _ST, _MODE,"),
        "{label}"
    );
    assert_eq!(cycle["activeParameter"], 3);
    let third = &signature["parameters"][2];
    let [start, end] = [0, 1].map(|i| third["label"][i].as_u64().expect("an offset") as usize);
    assert_eq!(&label[start..end], "_ST");
    assert!(third["documentation"].as_str().is_some(), "{third}");
    // Inside SIN( the cycle is still the call shown, and inside a string.
    let inside = help(&mut client, 1, 22);
    assert_eq!(inside["activeParameter"], 2);
    let in_string = help(&mut client, 1, 13);
    assert_eq!(in_string["activeParameter"], 1);

    let own = help(&mut client, 2, 8);
    assert_eq!(own["signatures"][0]["label"], "MAIN(REAL _A, STRING[8] _B)");
    assert_eq!(own["activeParameter"], 1);

    let beside = help(&mut client, 3, 17);
    assert_eq!(
        beside["signatures"][0]["label"],
        "POCKET(REAL _DEPTH, VAR INT _N[2])"
    );
    assert_eq!(
        beside["activeParameter"], 2,
        "the comma in the string counts not"
    );

    assert_eq!(help(&mut client, 4, 3), Value::Null, "outside any call");
    client.stop();

    // A client without offsets finds each parameter by its text's first
    // occurrence in the label: CYCLE84's PIT must not be found inside MPIT.
    let (mut client, _) = Client::start(json!({}));
    client.open(&uri, "CYCLE84(1, 2, 3, 4, 5, 6, 7, 8, \n");
    let thread = help(&mut client, 0, 30);
    let signature = &thread["signatures"][0];
    let label = signature["label"].as_str().expect("a label");
    let parameters = signature["parameters"].as_array().expect("parameters");
    let names: Vec<&str> = label["CYCLE84(".len()..label.len() - 1]
        .split(", ")
        .collect();
    assert_eq!(parameters.len(), names.len(), "{label}");
    assert!(names.contains(&"MPIT") && names.contains(&"PIT"), "{label}");
    let mut end = "CYCLE84(".len();
    for (parameter, name) in parameters.iter().zip(&names) {
        end = label[end..]
            .find(name)
            .map(|at| end + at + name.len())
            .expect("in order");
        let text = parameter["label"].as_str().expect("a parameter's text");
        assert_eq!(text.trim_start_matches([' ', ',']), *name, "{label}");
        assert_eq!(
            label.find(text).map(|at| at + text.len()),
            Some(end),
            "{text} in {label}"
        );
    }
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A sinuprep.toml that cannot be read is shown on itself, on its line,
/// and the programs it governs say they are not checked (not findings made
/// with settings they do not have); mended, both clear.
#[test]
fn a_broken_settings_file_is_shown_on_itself() {
    let dir = scratch("lsp-broken-settings");
    let broken = "# the rules\nselect = [\"N\"]\nselcet = [\"C\"]\n";
    std::fs::write(dir.join("sinuprep.toml"), broken).expect("settings");
    let program = format!("file://{}", dir.join("PART.MPF").display());
    let settings = format!("file://{}", dir.join("sinuprep.toml").display());
    let (mut client, _) = Client::start(json!({}));
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": program, "languageId": "sinumerik", "version": 1,
                                  "text": "G1 X1 F100\nGOTOB STRAT\nM30\n" } }),
    );
    let on_settings = client.diagnostics(&settings);
    assert_eq!(on_settings.len(), 1, "{on_settings:?}");
    assert_eq!(
        on_settings[0]["range"]["start"]["line"], 2,
        "{on_settings:?}"
    );
    let said = on_settings[0]["message"].as_str().expect("a message");
    assert!(said.contains("selcet"), "{said}");
    let on_program = client.diagnostics(&program);
    assert_eq!(on_program.len(), 1, "{on_program:?}");
    let said = on_program[0]["message"].as_str().expect("a message");
    assert!(
        said.starts_with("the settings cannot be read, so this file is not checked: ")
            && said.contains("sinuprep.toml:3"),
        "{said}"
    );

    // Mended and saved: the editor says the file changed.
    std::fs::write(dir.join("sinuprep.toml"), "select = [\"N\"]\n").expect("settings");
    client.notify(
        "workspace/didChangeWatchedFiles",
        json!({ "changes": [{ "uri": settings, "type": 2 }] }),
    );
    assert_eq!(client.diagnostics(&settings), Vec::<Value>::new());
    let found = client.next(|message| {
        message["method"] == "textDocument/publishDiagnostics"
            && message["params"]["uri"] == program.as_str()
            && message["params"]["diagnostics"][0]["code"] == "N001"
    });
    assert_eq!(
        found["params"]["diagnostics"].as_array().map(Vec::len),
        Some(1)
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A subprogram's and a GUD variable's references and rename reach every
/// file of the workspace: the PROC, the calls in programs not open, the
/// DEF in the definition file; the subprogram's file is renamed with it
/// (the control calls it by that name), where the editor can rename files.
#[test]
fn shared_names_are_found_and_renamed_across_the_workspace() {
    let dir = scratch("lsp-across");
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).expect(name);
    write("POCKET.SPF", "PROC POCKET(REAL _D)\nG1 Z=-_D F100\nM17\n");
    write("DRILL.SPF", "PROC DRILL\nM17\n");
    write("OTHER.MPF", "G0 X0\nPOCKET(2)\nM30\n");
    write("GUD7.DEF", "DEF NCK REAL _OFFSET_Z\nM30\n");
    write("sinuprep.toml", "definitions = [\"GUD7.DEF\"]\n");
    let uri = |name: &str| format!("file://{}", dir.join(name).display());
    let main = uri("MAIN.MPF");
    let renames = json!({ "workspace": { "workspaceEdit": {
        "documentChanges": true, "resourceOperations": ["create", "rename", "delete"] } } });
    let (mut client, _) = Client::start(renames);
    client.open(&main, "POCKET(5)\nG1 Z=_OFFSET_Z F100\nPOCKET(7)\nM30\n");

    let references = |client: &mut Client, line: u32, character: u32, declaration: bool| {
        let found = client.request(
            "textDocument/references",
            json!({ "textDocument": { "uri": main }, "position": { "line": line, "character": character },
                    "context": { "includeDeclaration": declaration } }),
        );
        let mut places: Vec<(String, u64)> = (found.as_array().expect("locations").iter())
            .map(|l| {
                let file = l["uri"]
                    .as_str()
                    .expect("a uri")
                    .rsplit('/')
                    .next()
                    .expect("a name");
                (
                    file.to_string(),
                    l["range"]["start"]["line"].as_u64().expect("a line"),
                )
            })
            .collect();
        places.sort();
        places
    };
    let place = |file: &str, line: u64| (file.to_string(), line);
    assert_eq!(
        references(&mut client, 0, 2, true),
        [
            place("MAIN.MPF", 0),
            place("MAIN.MPF", 2),
            place("OTHER.MPF", 1),
            place("POCKET.SPF", 0)
        ]
    );
    assert_eq!(
        references(&mut client, 0, 2, false),
        [
            place("MAIN.MPF", 0),
            place("MAIN.MPF", 2),
            place("OTHER.MPF", 1)
        ]
    );
    assert_eq!(
        references(&mut client, 1, 8, true),
        [place("GUD7.DEF", 0), place("MAIN.MPF", 1)]
    );

    let prepared = client.request("textDocument/prepareRename", at(&main, 0, 2));
    assert_eq!(
        prepared["start"],
        json!({ "line": 0, "character": 0 }),
        "{prepared}"
    );
    let rename = |client: &mut Client, line: u32, character: u32, name: &str| {
        client.request(
            "textDocument/rename",
            json!({ "textDocument": { "uri": main }, "position": { "line": line, "character": character },
                    "newName": name }),
        )
    };
    let taken = rename(&mut client, 0, 2, "DRILL");
    assert!(
        taken["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("already a name")),
        "{taken}"
    );
    let edit = rename(&mut client, 0, 2, "FACE");
    let operations = edit["documentChanges"].as_array().expect("operations");
    let mut edited: Vec<(String, usize)> = operations
        .iter()
        .filter(|o| o.get("textDocument").is_some())
        .map(|o| {
            let file = o["textDocument"]["uri"]
                .as_str()
                .expect("a uri")
                .rsplit('/')
                .next()
                .expect("a name");
            (file.to_string(), o["edits"].as_array().map_or(0, Vec::len))
        })
        .collect();
    edited.sort();
    assert_eq!(
        edited,
        [
            ("MAIN.MPF".to_string(), 2),
            ("OTHER.MPF".to_string(), 1),
            ("POCKET.SPF".to_string(), 1)
        ]
    );
    let renamed = operations.last().expect("the file renamed");
    assert_eq!(renamed["kind"], "rename");
    assert_eq!(renamed["oldUri"], uri("POCKET.SPF").as_str());
    assert_eq!(renamed["newUri"], uri("FACE.SPF").as_str());

    let edit = rename(&mut client, 1, 8, "_ZERO_Z");
    let changes = edit["changes"].as_object().expect("changes");
    assert_eq!(
        changes[&uri("GUD7.DEF")][0]["range"]["start"],
        json!({ "line": 0, "character": 13 })
    );
    assert_eq!(changes[&main][0]["newText"], "_ZERO_Z");
    client.stop();

    // An editor that cannot rename files is told which file to rename.
    let (mut client, _) = Client::start(json!({}));
    client.open(&main, "POCKET(5)\nM30\n");
    let refused = rename(&mut client, 0, 2, "FACE");
    let said = refused["error"]["message"].as_str().expect("refused");
    assert!(
        said.contains("cannot rename files") && said.contains("POCKET.SPF"),
        "{said}"
    );
    client.stop();
    let _ = std::fs::remove_dir_all(&dir);
}
