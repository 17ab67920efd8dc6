//! `textDocument/semanticTokens` (whole, a range, or what changed since the
//! tokens last sent, `tokens_sent.rs`): each word's class, for the client
//! to colour.

use lsp_types as lsp;

use super::{Snapshot, MOST_COLOURED_BYTES};
use crate::lsp::convert;

impl Snapshot<'_, '_> {
    /// The class of each word, for the client to colour: of the lines
    /// `range` touches, or of the whole document; refused past
    /// [`MOST_COLOURED_BYTES`], the editor's own colours staying.
    pub fn semantic_tokens(
        &self,
        range: Option<lsp::Range>,
    ) -> Result<Vec<lsp::SemanticToken>, String> {
        let lines = self.model.lines.len();
        let rows = match range {
            Some(range) => range.start.line as usize..(range.end.line as usize + 1).min(lines),
            None => 0..lines,
        };
        let bytes = match (rows.start, rows.end.checked_sub(1)) {
            (first, Some(last)) if first <= last => {
                self.model.lines.raw(last).full().end - self.model.lines.raw(first).content.start
            }
            _ => 0,
        };
        if bytes > MOST_COLOURED_BYTES {
            return Err(format!(
                "sinuprep colours at most {} MB of a program at once; {:.1} MB were asked for \
                 (the editor's own highlighting stays; a range of lines is coloured)",
                MOST_COLOURED_BYTES / 1_000_000,
                bytes as f64 / 1e6
            ));
        }
        let tokens = crate::semantic::highlight::tokens(self.model, self.uses(), rows);
        Ok(convert::semantic_tokens(self.text, &tokens, self.unit))
    }
}
