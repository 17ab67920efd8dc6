//! Document and range formatting: the edits `sinuprep fmt` makes, as the
//! protocol's text edits. A program with syntax errors gets none, as on
//! the command line; a range gets the edits of the lines it touches, and
//! only those lines are laid out (the protocol's lines are the program's:
//! CR, LF and CRLF end one in both).

use lsp_types as lsp;

use crate::document::text::Text;
use crate::format::{format, format_rows, Settings};
use crate::lsp::convert;
use crate::span::ColumnUnit;
use crate::syntax::program_kind;

/// The edits that format `text` (or the lines `range` touches).
pub fn edits(
    text: &Text,
    name: &str,
    settings: &Settings,
    range: Option<lsp::Range>,
    unit: ColumnUnit,
) -> Vec<lsp::TextEdit> {
    let source = text.bytes();
    let kind = program_kind(Some(name), source);
    let formatted = match range {
        Some(range) => {
            let rows = range.start.line as usize..range.end.line as usize + 1;
            format_rows(name, source, kind, settings, rows)
        }
        None => format(name, source, kind, settings),
    };
    formatted
        .edits
        .into_iter()
        .map(|edit| lsp::TextEdit {
            range: convert::range(text, edit.span, unit),
            new_text: String::from_utf8_lossy(&edit.text).into_owned(),
        })
        .collect()
}
