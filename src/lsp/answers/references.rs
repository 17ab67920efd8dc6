//! `textDocument/references`: every use of a name in the program.

use lsp_types as lsp;

use crate::semantic::uses::Role;

use super::Snapshot;

impl Snapshot<'_, '_> {
    pub fn references(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        with_declaration: bool,
    ) -> Vec<lsp::Location> {
        let Some(found) = self.uses().at(self.offset(position)) else {
            return Vec::new();
        };
        self.uses()
            .references(found)
            .filter(|u| with_declaration || u.role != Role::Defines)
            .map(|u| lsp::Location::new(uri.clone(), self.range(u.span)))
            .collect()
    }
}
