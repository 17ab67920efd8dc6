//! Diagnostics rendered for people (miette), for problem matchers (short
//! lines) and for tools (JSON, schema in the README).

use std::fmt;

use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan, NamedSource, SourceCode};

use crate::diagnostic::{Diagnostic, Severity};
use crate::span::{LineIndex, Position};

/// One file's diagnostics, ready to render.
pub struct FileReport<'a> {
    pub name: &'a str,
    pub source: &'a [u8],
    pub diagnostics: &'a [Diagnostic],
}

/// `path:line:col: severity[CODE] message`, one per line.
pub fn short(report: &FileReport, out: &mut String) {
    let index = LineIndex::new(report.source);
    for diagnostic in report.diagnostics {
        let Position { row, column } = index.position(diagnostic.span.start);
        out.push_str(&format!(
            "{}:{row}:{column}: {}[{}] {}\n",
            report.name,
            diagnostic.severity.as_str(),
            diagnostic.code,
            diagnostic.message
        ));
    }
}

/// The miette report: source line, label and help, without colour when
/// `colour` is false (files, pipes, snapshots).
pub fn human(report: &FileReport, colour: bool, out: &mut String) {
    if report.diagnostics.is_empty() {
        return;
    }
    let text = TextSource::new(report.source);
    let named = NamedSource::new(report.name, text.text.clone());
    let theme = if colour {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme).with_width(100);
    for diagnostic in report.diagnostics {
        let shown = Shown {
            diagnostic,
            source: &named,
            text: &text,
        };
        // Rendering into a String cannot fail.
        let _ = handler.render_report(out, &shown);
        out.push('\n');
    }
}

/// The source as text for miette. A file that is not UTF-8 is read as
/// Latin-1 (one byte, one character), and spans are moved to match.
struct TextSource {
    text: String,
    latin1: bool,
    source: Vec<u8>,
}

impl TextSource {
    fn new(source: &[u8]) -> Self {
        match std::str::from_utf8(source) {
            Ok(text) => Self {
                text: text.to_string(),
                latin1: false,
                source: Vec::new(),
            },
            Err(_) => Self {
                text: source.iter().map(|&b| b as char).collect(),
                latin1: true,
                source: source.to_vec(),
            },
        }
    }

    /// A byte offset of the source as a byte offset of `text`.
    fn offset(&self, offset: usize) -> usize {
        if self.latin1 {
            offset
                + self.source[..offset.min(self.source.len())]
                    .iter()
                    .filter(|&&b| b >= 0x80)
                    .count()
        } else {
            offset
        }
    }
}

struct Shown<'a> {
    diagnostic: &'a Diagnostic,
    source: &'a NamedSource<String>,
    text: &'a TextSource,
}

impl fmt::Debug for Shown<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.diagnostic, f)
    }
}

impl fmt::Display for Shown<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.diagnostic.message)
    }
}

impl std::error::Error for Shown<'_> {}

impl miette::Diagnostic for Shown<'_> {
    fn code<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        Some(Box::new(format!(
            "{}({})",
            self.diagnostic.code, self.diagnostic.name
        )))
    }

    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.diagnostic.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
            Severity::Info => miette::Severity::Advice,
        })
    }

    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.diagnostic
            .help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(self.source)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let span = self.diagnostic.span;
        let start = self.text.offset(span.start);
        let len = self.text.offset(span.end) - start;
        Some(Box::new(std::iter::once(LabeledSpan::new(
            Some(self.diagnostic.label.clone()),
            start,
            len,
        ))))
    }
}

#[derive(serde::Serialize)]
struct JsonDocument<'a> {
    version: u32,
    files: Vec<JsonFile<'a>>,
}

#[derive(serde::Serialize)]
struct JsonFile<'a> {
    path: &'a str,
    diagnostics: Vec<JsonDiagnostic<'a>>,
}

#[derive(serde::Serialize)]
struct JsonDiagnostic<'a> {
    code: &'a str,
    name: &'a str,
    severity: Severity,
    message: &'a str,
    help: Option<&'a str>,
    location: Position,
    end_location: Position,
    offset: usize,
    length: usize,
}

/// One JSON document for all files.
pub fn json(reports: &[FileReport]) -> String {
    let files = reports
        .iter()
        .map(|report| {
            let index = LineIndex::new(report.source);
            let diagnostics = report
                .diagnostics
                .iter()
                .map(|d| JsonDiagnostic {
                    code: d.code,
                    name: d.name,
                    severity: d.severity,
                    message: &d.message,
                    help: d.help.as_deref(),
                    location: index.position(d.span.start),
                    end_location: index.position(d.span.end),
                    offset: d.span.start,
                    length: d.span.len(),
                })
                .collect();
            JsonFile {
                path: report.name,
                diagnostics,
            }
        })
        .collect();
    let mut text =
        serde_json::to_string_pretty(&JsonDocument { version: 1, files }).unwrap_or_default();
    text.push('\n');
    text
}
