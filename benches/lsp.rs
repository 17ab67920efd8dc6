//! The language server as an editor meets it: the release binary's
//! `sinuprep lsp` over its pipes, on a hand-written program of 10,000 lines
//! (`SINUPREP_BENCH_LSP_LINES`)
//! (DEF, IF/ELSE/ENDIF, WHILE, R-parameter arithmetic, labels and jumps,
//! subprogram calls, a CYCLE600 in the middle). Prints, over 40 rounds each,
//! the minimum, median and maximum of: an incremental change to its
//! diagnostics published, then a hover on a variable (whose values at its
//! uses the first hover on it in a version walks the program for) and one
//! on another use of it, a label completion after a jump (the labels it
//! reaches), a hover on the CYCLE600 answered, a word's completion and the
//! signature help inside the CYCLE600, the semantic tokens after each change
//! as what changed (and their size) and whole, the document's symbols
//! answered.
//!
//! Then the large programs an editor may be given (size in MB:
//! `SINUPREP_BENCH_LSP_MB`, default 100): a CAM program opened while a
//! hover on the small program is asked (how long the hover waits), its
//! findings, a change to them and the memory held after, its symbols and its semantic tokens (refused past 10 MB); and
//! a program with a finding on each line (a twelfth of that size): how long
//! its findings take and how large they are; the server's peak memory.
//! `cargo bench --bench lsp`; nothing is asserted.

use std::time::Instant;

use serde_json::{json, Value};

#[path = "../tests/support/lsp_client.rs"]
mod lsp_client;
use lsp_client::Client;

const URI: &str = "untitled:HAND_WRITTEN.MPF";
const ROUNDS: usize = 40;

/// A hand-written program of `lines` lines, its CYCLE600 on line `lines / 2`.
fn program(lines: usize) -> (String, u32) {
    let mut text = String::from("DEF REAL _DEPTH=5, _STEP=0.5, _Z\nDEF INT _N, _COUNT=0\n");
    let mut row = 2;
    let mut cycle600 = 0;
    let mut section = 0;
    while row < lines - 2 {
        if cycle600 == 0 && row >= lines / 2 {
            text.push_str(
                "N120 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\n",
            );
            cycle600 = row as u32;
            row += 1;
            continue;
        }
        section += 1;
        text.push_str(&format!(
            "POCKET{section}:\n\
             _Z=0\n\
             WHILE _Z>-_DEPTH\n\
             _Z=_Z-_STEP\n\
             IF R{r}>_Z*2\n\
             G1 X=R{r}+10 Y=R{r}*0.5 Z=_Z F800\n\
             ELSE\n\
             G1 X=10 Y20 Z=_Z F400\n\
             ENDIF\n\
             ENDWHILE\n\
             _COUNT=_COUNT+1\n\
             IF _COUNT<3 GOTOB POCKET{section}\n\
             L{sub}\n",
            r = section % 99 + 1,
            sub = section % 7 + 100,
        ));
        row += 13;
    }
    text.push_str("M30\n");
    (text, cycle600)
}

fn figures(name: &str, mut times: Vec<f64>) {
    times.sort_by(f64::total_cmp);
    println!(
        "{name:<44} {:>8.2} {:>8.2} {:>8.2}",
        times[0] * 1e3,
        times[times.len() / 2] * 1e3,
        times[times.len() - 1] * 1e3
    );
}

fn main() {
    // `SINUPREP_BENCH_LSP_LINES`: the hand-written program's length.
    let lines = std::env::var("SINUPREP_BENCH_LSP_LINES")
        .ok()
        .and_then(|lines| lines.parse().ok())
        .unwrap_or(10_000);
    let (text, cycle600) = program(lines);
    let (mut client, _) = Client::start(json!({}));
    let started = Instant::now();
    client.open(URI, &text);
    let opened = started.elapsed().as_secs_f64();
    println!(
        "{} lines, {} KB; ms: {:>26} {:>8} {:>8}",
        text.lines().count(),
        text.len() / 1000,
        "min",
        "median",
        "max"
    );
    figures("open to diagnostics", vec![opened]);
    let mut changes = Vec::new();
    let mut first_hovers = Vec::new();
    let mut next_hovers = Vec::new();
    let mut label_completions = Vec::new();
    let mut token_deltas = Vec::new();
    let mut delta_bytes = Vec::new();
    let whole = client.request(
        "textDocument/semanticTokens/full",
        json!({ "textDocument": { "uri": URI } }),
    );
    let whole_bytes = whole.to_string().len();
    let mut token_id = whole["resultId"].clone();
    // `_Z=_Z-_STEP` in the first pocket: the variable read, then written.
    let variable = |character: u32| json!({ "textDocument": { "uri": URI }, "position": { "line": 5, "character": character } });
    for round in 0..ROUNDS {
        // Type a digit into a feed rate near the end, then take it out.
        let line = text.lines().count() as u32 - 10;
        let (range, new) = if round % 2 == 0 {
            (
                json!({ "start": { "line": line, "character": 0 }, "end": { "line": line, "character": 0 } }),
                "; ",
            )
        } else {
            (
                json!({ "start": { "line": line, "character": 0 }, "end": { "line": line, "character": 2 } }),
                "",
            )
        };
        let started = Instant::now();
        client.notify(
            "textDocument/didChange",
            json!({ "textDocument": { "uri": URI, "version": round + 2 },
                    "contentChanges": [{ "range": range, "text": new }] }),
        );
        client.diagnostics(URI);
        changes.push(started.elapsed().as_secs_f64());
        let asked = Instant::now();
        client.request("textDocument/hover", variable(4));
        first_hovers.push(asked.elapsed().as_secs_f64());
        let asked = Instant::now();
        client.request("textDocument/hover", variable(0));
        next_hovers.push(asked.elapsed().as_secs_f64());
        // `IF _COUNT<3 GOTOB P` in the first pocket: the labels it reaches.
        let asked = Instant::now();
        client.request(
            "textDocument/completion",
            json!({ "textDocument": { "uri": URI }, "position": { "line": 13, "character": 19 } }),
        );
        label_completions.push(asked.elapsed().as_secs_f64());
        let asked = Instant::now();
        let delta = client.request(
            "textDocument/semanticTokens/full/delta",
            json!({ "textDocument": { "uri": URI }, "previousResultId": token_id }),
        );
        token_deltas.push(asked.elapsed().as_secs_f64());
        delta_bytes.push(delta.to_string().len() as f64 / 1e3);
        token_id = delta["resultId"].clone();
    }
    figures("change to diagnostics", changes);
    figures("variable hover, first of the version", first_hovers);
    figures("variable hover, another use of it", next_hovers);
    figures("label completion after a hover", label_completions);
    figures("semantic tokens, what changed", token_deltas);
    let timed = |client: &mut Client, method: &str, params: Value| {
        (0..ROUNDS)
            .map(|_| {
                let started = Instant::now();
                client.request(method, params.clone());
                started.elapsed().as_secs_f64()
            })
            .collect::<Vec<f64>>()
    };
    let at =
        json!({ "textDocument": { "uri": URI }, "position": { "line": cycle600, "character": 8 } });
    figures(
        "hover on the CYCLE600",
        timed(&mut client, "textDocument/hover", at),
    );
    // `_Z=_Z-_S`: a variable, the language's words, the cycles.
    let word = json!({ "textDocument": { "uri": URI }, "position": { "line": 5, "character": 8 } });
    figures(
        "completion of a word",
        timed(&mut client, "textDocument/completion", word),
    );
    let inside = json!({ "textDocument": { "uri": URI }, "position": { "line": cycle600, "character": 30 } });
    figures(
        "signature help in the CYCLE600",
        timed(&mut client, "textDocument/signatureHelp", inside),
    );
    let document = json!({ "textDocument": { "uri": URI } });
    figures(
        "semantic tokens, whole",
        timed(
            &mut client,
            "textDocument/semanticTokens/full",
            document.clone(),
        ),
    );
    let median = |mut kb: Vec<f64>| {
        kb.sort_by(f64::total_cmp);
        kb[kb.len() / 2]
    };
    println!(
        "semantic tokens: {:.1} KB of JSON whole, {:.2} KB (median) for what changed",
        whole_bytes as f64 / 1e3,
        median(delta_bytes)
    );
    figures(
        "document symbols",
        timed(&mut client, "textDocument/documentSymbol", document),
    );
    large_programs(&mut client);
    client.stop();
}

/// What a large program costs the server and the editor's other requests.
fn large_programs(client: &mut Client) {
    let megabytes: usize = std::env::var("SINUPREP_BENCH_LSP_MB")
        .ok()
        .and_then(|m| m.parse().ok())
        .unwrap_or(100);
    let cam = cam_program(megabytes * 1_000_000);
    let uri = "untitled:CAM.MPF";
    let started = Instant::now();
    client.notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": uri, "languageId": "sinumerik", "version": 1, "text": cam } }),
    );
    let asked = Instant::now();
    client.request(
        "textDocument/hover",
        json!({ "textDocument": { "uri": URI }, "position": { "line": 2, "character": 1 } }),
    );
    let hover = asked.elapsed().as_secs_f64();
    let findings = client.diagnostics(uri).len();
    let analysed = started.elapsed().as_secs_f64();
    let document = json!({ "textDocument": { "uri": uri } });
    let once = |client: &mut Client, method: &str| {
        let asked = Instant::now();
        let answer = client.request(method, document.clone());
        (asked.elapsed().as_secs_f64(), answer.to_string().len())
    };
    // A comment typed into the middle and taken out again.
    let middle = cam.lines().count() / 2;
    let changes: Vec<f64> = (0..6)
        .map(|round| {
            let (end, new) = if round % 2 == 0 { (0, "; ") } else { (2, "") };
            let started = Instant::now();
            client.notify(
                "textDocument/didChange",
                json!({ "textDocument": { "uri": uri, "version": round + 2 },
                        "contentChanges": [{ "range": {
                            "start": { "line": middle, "character": 0 },
                            "end": { "line": middle, "character": end } }, "text": new }] }),
            );
            client.diagnostics(uri);
            started.elapsed().as_secs_f64()
        })
        .collect();
    let resident = client.memory_kib();
    let (symbols, symbols_size) = once(client, "textDocument/documentSymbol");
    let (tokens, tokens_size) = once(client, "textDocument/semanticTokens/full");
    let row = |what: String, figure: String| println!("  {what:<60} {figure:>12}");
    println!(
        "\n{megabytes} MB CAM program, {} lines:",
        cam.lines().count()
    );
    row(
        "a hover on the small program, asked as it opens".to_string(),
        format!("{:.1} ms", hover * 1e3),
    );
    row(
        format!("open to its findings ({findings})"),
        format!("{analysed:.2} s"),
    );
    let mut changes = changes;
    changes.sort_by(f64::total_cmp);
    row(
        "a change to its findings (6 changes: min, median, max)".to_string(),
        format!(
            "{:.0} {:.0} {:.0} ms",
            changes[0] * 1e3,
            changes[3] * 1e3,
            changes[5] * 1e3
        ),
    );
    if let Some(resident) = resident {
        row(
            "the server's memory after them".to_string(),
            format!("{} MiB", resident / 1024),
        );
    }
    row(
        format!("document symbols ({symbols_size} bytes)"),
        format!("{:.1} ms", symbols * 1e3),
    );
    row(
        format!("semantic tokens, whole ({tokens_size} bytes)"),
        format!("{:.1} ms", tokens * 1e3),
    );

    let lines = megabytes * 1_000_000 / 12 / 14;
    let many = "G1 F100 X1 X2\n".repeat(lines) + "M30\n";
    let uri = "untitled:MANY.MPF";
    let started = Instant::now();
    let found = client.open(uri, &many);
    let published = started.elapsed().as_secs_f64();
    let size = serde_json::to_string(&found).map_or(0, |text| text.len());
    println!("A finding on each of {lines} lines:");
    row(
        format!("open to its findings ({} given, {size} bytes)", found.len()),
        format!("{published:.2} s"),
    );
    if let Some(peak) = client.peak_memory_kib() {
        row(
            "the server's peak memory".to_string(),
            format!("{} MiB", peak / 1024),
        );
    }
}

/// A CAM program of about `size` bytes: numbered motion blocks, no finding.
fn cam_program(size: usize) -> String {
    let mut out =
        String::from("; generated\nN10 G17 G54 G90 G71\nN20 T1 D1 M6\nN30 G0 X0 Y0 Z50\n");
    let mut n = 30u64;
    while out.len() < size {
        n += 10;
        let v = n as f64 * 0.001;
        out.push_str(&format!(
            "N{n} G1 X{:.3} Y{:.3} Z{:.3} F2500\n",
            v.sin() * 200.0,
            v.cos() * 200.0,
            -(v % 5.0)
        ));
    }
    out.push_str("M30\n");
    out
}
