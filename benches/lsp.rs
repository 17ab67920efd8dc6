//! The language server as an editor meets it: the release binary's
//! `sinuprep lsp` over its pipes, on a hand-written program of 10,000 lines
//! (DEF, IF/ELSE/ENDIF, WHILE, R-parameter arithmetic, labels and jumps,
//! subprogram calls, a CYCLE600 in the middle). Prints, over 40 rounds each,
//! the minimum, median and maximum of: an incremental change to its
//! diagnostics published, a hover on the CYCLE600 answered, the document's
//! symbols answered. `cargo bench --bench lsp`; nothing is asserted.

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
    let (text, cycle600) = program(10_000);
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
    }
    figures("change to diagnostics", changes);
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
    let document = json!({ "textDocument": { "uri": URI } });
    figures(
        "document symbols",
        timed(&mut client, "textDocument/documentSymbol", document),
    );
    client.stop();
}
