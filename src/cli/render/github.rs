//! GitHub Actions workflow commands: annotations on the changed files.

use super::emitter::TextFormat;
use super::{printable, FileReport, COLUMNS};
use crate::diagnostic::Severity;
use crate::span::LineIndex;

/// GitHub Actions workflow commands: one `::error file=...::message` line
/// each, which the runner shows as annotations on the changed files.
pub fn github(report: &FileReport, out: &mut String) {
    let index = LineIndex::new(report.source);
    for d in report.diagnostics {
        let start = index.position_in(d.span.start, COLUMNS);
        let end = index.position_in(d.span.end, COLUMNS);
        let level = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "notice",
        };
        out.push_str(&format!(
            "::{level} file={},line={},col={},endLine={},endColumn={},title={}::{}\n",
            printable(&escape_property(report.name)),
            start.row,
            start.column,
            end.row,
            end.column,
            escape_property(&format!("{} {}", d.code(), d.name())),
            escape_data(&d.message)
        ));
    }
}

/// `check --output-format github`.
pub struct GithubEmitter;

impl TextFormat for GithubEmitter {
    fn render(&self, report: &FileReport, out: &mut String) {
        github(report, out);
    }

    fn names_archives(&self) -> bool {
        true
    }
}

/// Workflow-command data: `%`, CR and LF are percent-encoded.
fn escape_data(text: &str) -> String {
    text.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// Workflow-command properties: also `:` and `,`.
fn escape_property(text: &str) -> String {
    escape_data(text).replace(':', "%3A").replace(',', "%2C")
}
