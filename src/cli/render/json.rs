//! For tools: one JSON document, written a file at a time (schema in
//! docs/guide.md).

use std::io::{self, Write};

use super::emitter::{Emitter, Program};
use super::{indented, Located};
use crate::diagnostic::{Applicability, Fix, Severity};
use crate::span::Position;

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
    #[serde(skip_serializing_if = "Option::is_none")]
    fix: Option<JsonFix<'a>>,
}

#[derive(serde::Serialize)]
struct JsonFix<'a> {
    title: &'a str,
    applicability: Applicability,
    /// Byte offsets into the file as read; the text replaces `length` bytes.
    edits: Vec<JsonEdit>,
}

#[derive(serde::Serialize)]
struct JsonEdit {
    offset: usize,
    length: usize,
    text: String,
}

impl<'a> JsonFix<'a> {
    fn of(fix: &'a Fix) -> Self {
        Self {
            title: &fix.title,
            applicability: fix.applicability,
            edits: fix
                .edits
                .iter()
                .map(|edit| JsonEdit {
                    offset: edit.span.start,
                    length: edit.span.len(),
                    text: String::from_utf8_lossy(&edit.text).into_owned(),
                })
                .collect(),
        }
    }
}

/// `check --output-format json`: one document, written a file at a time
/// (its text is what one pretty-printed document would be).
pub struct JsonEmitter;

impl Emitter for JsonEmitter {
    /// The file's entries of `files`.
    type Part = String;
    /// The entries written so far.
    type Kept = usize;

    fn start(&self, out: &mut dyn Write) -> io::Result<()> {
        out.write_all(b"{\n  \"version\": 1,\n  \"files\": [")
    }

    fn add(&self, part: &mut String, program: Program) {
        if !part.is_empty() {
            part.push_str(BETWEEN);
        }
        let located = Located::new(program.name, program.source, program.diagnostics);
        part.push_str(&file(&located));
    }

    fn write(&self, entries: &mut usize, part: String, out: &mut dyn Write) -> io::Result<()> {
        // An archive without programs, a binary file skipped: no entry.
        if part.is_empty() {
            return Ok(());
        }
        if *entries > 0 {
            out.write_all(BETWEEN.as_bytes())?;
        }
        *entries += 1;
        out.write_all(part.as_bytes())
    }

    fn failed(
        &self,
        entries: &mut usize,
        name: &str,
        error: &str,
        out: &mut dyn Write,
    ) -> io::Result<()> {
        self.write(entries, failed(name, error), out)
    }

    fn end(&self, entries: usize, out: &mut dyn Write) -> io::Result<()> {
        out.write_all(match entries {
            0 => b"]\n}\n",
            _ => b"\n  ]\n}\n",
        })
    }
}

/// What separates two entries of `files`.
const BETWEEN: &str = ",";

/// One file's entry of the JSON document, indented for its place there,
/// preceded by its line break.
fn file(report: &Located) -> String {
    let diagnostics = report
        .each()
        .map(|(d, start, end)| JsonDiagnostic {
            code: d.code(),
            name: d.name(),
            severity: d.severity,
            message: &d.message,
            help: d.help.as_deref(),
            location: start,
            end_location: end,
            offset: d.span.start,
            length: d.span.len(),
            fix: d.fix.as_deref().map(JsonFix::of),
        })
        .collect();
    let file = JsonFile {
        path: &report.name,
        diagnostics,
    };
    indented(&serde_json::to_string_pretty(&file).unwrap_or_default(), 4)
}

/// The entry of the JSON document for a file that could not be checked
/// (not found, unreadable, a directory, a damaged archive): its path, the
/// error, and no diagnostics, so that a reader of `files` sees it without
/// reading stderr.
fn failed(name: &str, error: &str) -> String {
    #[derive(serde::Serialize)]
    struct Failed<'a> {
        path: &'a str,
        error: &'a str,
        diagnostics: [(); 0],
    }
    let file = Failed {
        path: name,
        error,
        diagnostics: [],
    };
    indented(&serde_json::to_string_pretty(&file).unwrap_or_default(), 4)
}
