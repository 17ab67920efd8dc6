//! `workspace/symbol`: the names of the workspace that hold the query (any
//! case): the PROCs, labels and DEF variables of every open document, then
//! what the control finds beyond them, as their settings read it: the
//! subprograms of the programs' folders and the cycle directories, and the
//! GUD variables and macros of the definition files.

use std::collections::{BTreeMap, HashSet};
use std::path::PathBuf;

use lsp_types as lsp;

use super::{convert, Open};
use crate::document::text::Text;
use crate::span::{ColumnUnit, Span};

/// A name defined in a file no document holds open.
struct Beyond {
    span: Span,
    kind: lsp::SymbolKind,
}

/// The symbols matching `query` of `documents` (sorted by URI) and beyond.
#[allow(deprecated)] // `SymbolInformation::deprecated` must still be written.
pub fn find(
    documents: &[(lsp::Uri, Open)],
    query: &str,
    unit: ColumnUnit,
) -> Vec<lsp::SymbolInformation> {
    let query = query.to_uppercase();
    let matches = |name: &str| name.to_uppercase().contains(&query);
    let mut out = Vec::new();
    for (uri, open) in documents {
        let symbols = open
            .with_snapshot(unit, |s| s.symbols())
            .unwrap_or_default();
        out.extend(
            symbols
                .into_iter()
                .filter(|symbol| matches(&symbol.name))
                .map(|symbol| lsp::SymbolInformation {
                    name: symbol.name,
                    kind: symbol.kind,
                    tags: None,
                    deprecated: None,
                    location: lsp::Location::new(uri.clone(), symbol.selection_range),
                    container_name: None,
                }),
        );
    }
    // Each file's names once, however many documents' settings reach it.
    let open_files: HashSet<PathBuf> = documents
        .iter()
        .filter_map(|(uri, _)| convert::path(uri))
        .collect();
    let mut beyond: BTreeMap<PathBuf, BTreeMap<String, Beyond>> = BTreeMap::new();
    let mut add = |file: &PathBuf, name: &str, span: Span, kind: lsp::SymbolKind| {
        if matches(name) && !open_files.contains(file) {
            let names = beyond.entry(file.clone()).or_default();
            names
                .entry(name.to_string())
                .or_insert(Beyond { span, kind });
        }
    };
    for (_, open) in documents {
        let environment = &open.settings.environment;
        for (name, procedure) in environment.procedures.iter() {
            if let Some((file, span)) = &procedure.defined {
                add(file, name, *span, lsp::SymbolKind::FUNCTION);
            }
        }
        for (name, (file, span)) in &environment.defined_in {
            let kind = match environment.macros.contains_key(name) {
                true => lsp::SymbolKind::CONSTANT,
                false => lsp::SymbolKind::VARIABLE,
            };
            add(file, name, *span, kind);
        }
    }
    for (file, names) in beyond {
        // A file gone or unreadable since the settings were read is left out.
        let Ok(bytes) = crate::workspace::file::read(&file) else {
            continue;
        };
        let uri = convert::uri(&file);
        let Some(uri) = uri else {
            continue;
        };
        let text = Text::new(bytes);
        let container = file.file_name().map(|n| n.to_string_lossy().into_owned());
        for (name, found) in names {
            // An archive's member: the span is in the archive, not a file.
            if found.span.end > text.bytes().len() {
                continue;
            }
            out.push(lsp::SymbolInformation {
                name,
                kind: found.kind,
                tags: None,
                deprecated: None,
                location: lsp::Location::new(uri.clone(), convert::range(&text, found.span, unit)),
                container_name: container.clone(),
            });
        }
    }
    out
}
