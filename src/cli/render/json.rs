//! For tools: one JSON document, written a file at a time (schema in
//! docs/guide.md).

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

/// The JSON document for all files, written a file at a time: this, then
/// each file's [`json_file`] (after [`JSON_BETWEEN`] from the second on),
/// then [`json_end`]. The text is what one pretty-printed document would be.
pub const JSON_START: &str = "{\n  \"version\": 1,\n  \"files\": [";
pub const JSON_BETWEEN: &str = ",";

/// One file's entry of the JSON document, indented for its place there,
/// preceded by its line break.
pub fn json_file(report: &Located) -> String {
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
pub fn json_failed(name: &str, error: &str) -> String {
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

/// The end of the JSON document, after `files` entries.
pub fn json_end(files: usize) -> &'static str {
    match files {
        0 => "]\n}\n",
        _ => "\n  ]\n}\n",
    }
}
