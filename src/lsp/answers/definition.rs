//! `textDocument/definition`: a name's definition in the program, or where
//! the control finds a name the program does not define.

use lsp_types as lsp;

use crate::document::text::Text;

use super::Snapshot;
use crate::lsp::convert;

impl Snapshot<'_, '_> {
    /// The definition in this program, or for a subprogram it does not
    /// define, the PROC of the file the control would call.
    pub fn definition(&self, uri: &lsp::Uri, position: lsp::Position) -> Option<lsp::Location> {
        let found = self.uses().at(self.offset(position))?;
        match self.uses().definition(self.model, found) {
            Some(definition) => Some(lsp::Location::new(uri.clone(), self.range(definition.span))),
            None => {
                let (file, span) = self.defined_elsewhere(found)?;
                let text = Text::new(crate::workspace::file::read(file).ok()?);
                let uri = convert::uri(file)?;
                Some(lsp::Location::new(
                    uri,
                    convert::range(&text, *span, self.unit),
                ))
            }
        }
    }
}
