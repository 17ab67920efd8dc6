//! `textDocument/documentSymbol`: PROCs, labels, DEF variables and CYCLE600 calls.

use lsp_types as lsp;

use crate::semantic::uses::{Namespace, Role};

use super::{is_block_number, Snapshot};

impl Snapshot<'_, '_> {
    /// PROCs, labels and DEF variables, and the CYCLE600 calls.
    #[allow(deprecated)] // `DocumentSymbol::deprecated` must still be written.
    pub fn symbols(&self) -> Vec<lsp::DocumentSymbol> {
        let defined = self.uses().all().iter().filter(|u| u.role == Role::Defines);
        let mut symbols: Vec<lsp::DocumentSymbol> = defined
            .filter_map(|u| {
                let kind = match u.namespace {
                    Namespace::Subprogram => lsp::SymbolKind::FUNCTION,
                    Namespace::Variable => lsp::SymbolKind::VARIABLE,
                    // Block numbers are every line's: only labels are named.
                    Namespace::Label if is_block_number(&u.name) => return None,
                    Namespace::Label => lsp::SymbolKind::KEY,
                };
                Some(symbol(
                    u.name.clone(),
                    kind,
                    self.range(u.span),
                    self.range(u.span),
                ))
            })
            .collect();
        for site in self.calls() {
            let range = self.range(site.statement);
            symbols.push(symbol(
                "CYCLE600".to_string(),
                lsp::SymbolKind::EVENT,
                range,
                range,
            ));
        }
        symbols.sort_by_key(|s| (s.range.start.line, s.range.start.character));
        symbols
    }
}

#[allow(deprecated)] // `DocumentSymbol::deprecated` must still be written.
fn symbol(
    name: String,
    kind: lsp::SymbolKind,
    range: lsp::Range,
    selection_range: lsp::Range,
) -> lsp::DocumentSymbol {
    lsp::DocumentSymbol {
        name,
        detail: None,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range,
        children: None,
    }
}
