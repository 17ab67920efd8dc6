//! `path:line:col: severity[CODE] message`, one line a finding, for
//! problem matchers and people reading a terminal's width.

use super::emitter::TextFormat;
use super::{printable, FileReport, COLUMNS};
use crate::span::{LineIndex, Position};

/// `path:line:col: severity[CODE] message`, one per line.
pub fn short(report: &FileReport, out: &mut String) {
    let index = LineIndex::new(report.source);
    let name = printable(report.name);
    for diagnostic in report.diagnostics {
        let Position { row, column } = index.position_in(diagnostic.span.start, COLUMNS);
        out.push_str(&format!(
            "{name}:{row}:{column}: {}[{}] {}\n",
            diagnostic.severity.as_str(),
            diagnostic.code(),
            diagnostic.message
        ));
    }
}

/// `check --output-format short`.
pub struct ShortEmitter;

impl TextFormat for ShortEmitter {
    fn render(&self, report: &FileReport, out: &mut String) {
        short(report, out);
    }

    fn for_people(&self) -> bool {
        true
    }
}
