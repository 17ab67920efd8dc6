//! Linting never panics, every finding points inside the input, and the
//! plain-line shortcut and the lines read ahead on a thread of their own
//! find exactly what parsing every line finds; every
//! finding renders in the human and short formats, also where the input's
//! first line starts 70,000 columns further right (past miette's 16 bits).
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::cli::render::{human, short, FileReport};
use sinuprep::diagnostic::Diagnostic;
use sinuprep::lint::{check, check_read_ahead, check_with, Settings};
use sinuprep::span::Span;
use sinuprep::semantic::Heads;
use sinuprep::syntax::plain::PlainScanner;
use sinuprep::syntax::program_kind;

fuzz_target!(|data: &[u8]| {
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let kind = program_kind(None, data);
    let settings = Settings {
        heads: Some(heads),
        ..Settings::default()
    };
    let findings = check(data, "FUZZ.MPF", kind, &settings);
    let every_line = PlainScanner::ParseEveryLine;
    let reference = check_with(every_line, data, "FUZZ.MPF", kind, &settings);
    assert_eq!(findings, reference);
    assert_eq!(check_read_ahead(data, "FUZZ.MPF", kind, &settings), reference);
    for finding in &findings {
        assert!(
            finding.span.start <= finding.span.end && finding.span.end <= data.len(),
            "{}",
            finding.code()
        );
    }
    render(data, &findings);
    const PAD: usize = 70_000;
    let mut padded = vec![b' '; PAD];
    padded.extend_from_slice(data);
    // Only the first line's findings move right.
    let first_line = first_line_end(data);
    let shifted: Vec<Diagnostic> = findings
        .into_iter()
        .filter(|d| d.span.start <= first_line)
        .map(|mut d| {
            d.span = Span::new(d.span.start + PAD, d.span.end + PAD);
            d
        })
        .collect();
    if !shifted.is_empty() {
        render(&padded, &shifted);
    }
});

fn first_line_end(data: &[u8]) -> usize {
    data.iter()
        .position(|&b| b == b'\n' || b == b'\r')
        .unwrap_or(data.len())
}

fn render(source: &[u8], diagnostics: &[Diagnostic]) {
    let report = FileReport {
        name: "FUZZ.MPF",
        source,
        diagnostics,
    };
    let mut text = String::new();
    human(&report, false, &mut text);
    short(&report, &mut text);
}
