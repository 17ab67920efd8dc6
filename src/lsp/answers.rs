//! What the server answers about one document, read from one analysis of
//! it: the model, the CYCLE600 walk and the table of uses.

use lsp_types as lsp;

use crate::document::text::Text;
use crate::document::{Analyzed, Document};
use crate::lint::Settings;
use crate::semantic::uses::{Namespace, Role, Use, Uses};
use crate::span::{ColumnUnit, Span};

use super::convert;

/// One document analysed for the requests about it.
pub struct Snapshot<'t> {
    text: &'t Text,
    name: &'t str,
    analyzed: Analyzed<'t>,
    uses: Uses,
    unit: ColumnUnit,
    settings: &'t Settings,
}

impl<'t> Snapshot<'t> {
    pub fn new(text: &'t Text, name: &'t str, settings: &'t Settings, unit: ColumnUnit) -> Self {
        let analyzed = Document::new(name, text.bytes()).analyze(settings);
        let uses = Uses::of(&analyzed.model);
        Self {
            text,
            name,
            analyzed,
            uses,
            unit,
            settings,
        }
    }

    pub fn diagnostics(&self) -> Vec<lsp::Diagnostic> {
        self.analyzed
            .findings
            .iter()
            .map(|found| convert::diagnostic(self.text, found, self.unit))
            .collect()
    }

    fn offset(&self, position: lsp::Position) -> usize {
        convert::offset(self.text, position, self.unit)
    }

    fn range(&self, span: Span) -> lsp::Range {
        convert::range(self.text, span, self.unit)
    }

    fn line_text(&self, row: usize) -> String {
        let content = self.analyzed.model.lines.raw(row).content;
        String::from_utf8_lossy(content.of(self.text.bytes()))
            .trim()
            .to_string()
    }

    pub fn hover(&self, position: lsp::Position) -> Option<lsp::Hover> {
        let at = self.offset(position);
        let source = self.text.bytes();
        let walk = self.analyzed.walk.iter().flat_map(|walk| &walk.calls);
        if let Some(site) = walk.into_iter().find(|site| contains(site.statement, at)) {
            let table = crate::cli::eval::call_table(site, self.name, source, &self.settings.emit);
            return Some(markdown(
                format!("```\n{table}```"),
                self.range(site.statement),
            ));
        }
        let found = self.uses.at(at)?;
        let text = match self.uses.definition(&self.analyzed.model, found) {
            Some(definition) if definition.span == found.span => {
                let users = self.uses.references(found).count() - 1;
                format!("{}: used {users} times", self.describe(found))
            }
            Some(definition) => format!(
                "{}, defined on line {}:\n```\n{}\n```",
                self.describe(found),
                definition.row + 1,
                self.line_text(definition.row)
            ),
            None => format!("{}: not defined in this program", self.describe(found)),
        };
        Some(markdown(text, self.range(found.span)))
    }

    fn describe(&self, found: &Use) -> String {
        let what = match (found.namespace, found.role) {
            (Namespace::Label, Role::JumpsTo) => "jump to",
            (Namespace::Label, _) => "label",
            (Namespace::Variable, _) => "variable",
            (Namespace::Subprogram, Role::Defines) => "PROC",
            (Namespace::Subprogram, _) => "call of",
        };
        format!("{what} `{}`", found.name)
    }

    pub fn definition(&self, uri: &lsp::Uri, position: lsp::Position) -> Option<lsp::Location> {
        let found = self.uses.at(self.offset(position))?;
        let definition = self.uses.definition(&self.analyzed.model, found)?;
        Some(lsp::Location::new(uri.clone(), self.range(definition.span)))
    }

    pub fn references(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        with_declaration: bool,
    ) -> Vec<lsp::Location> {
        let Some(found) = self.uses.at(self.offset(position)) else {
            return Vec::new();
        };
        self.uses
            .references(found)
            .filter(|u| with_declaration || u.role != Role::Defines)
            .map(|u| lsp::Location::new(uri.clone(), self.range(u.span)))
            .collect()
    }

    /// PROCs, labels and DEF variables, and the CYCLE600 calls.
    #[allow(deprecated)] // `DocumentSymbol::deprecated` must still be written.
    pub fn symbols(&self) -> Vec<lsp::DocumentSymbol> {
        let defined = self.uses.all().iter().filter(|u| u.role == Role::Defines);
        let mut symbols: Vec<lsp::DocumentSymbol> = defined
            .filter_map(|u| {
                let kind = match u.namespace {
                    Namespace::Subprogram => lsp::SymbolKind::FUNCTION,
                    Namespace::Variable => lsp::SymbolKind::VARIABLE,
                    // Block numbers are every line's: only labels are named.
                    Namespace::Label if u.name.starts_with('N') && is_number(&u.name[1..]) => {
                        return None
                    }
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
        for site in self.analyzed.walk.iter().flat_map(|walk| &walk.calls) {
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

    /// IF ... ENDIF, WHILE, FOR, LOOP, REPEAT ... UNTIL.
    pub fn folding(&self) -> Vec<lsp::FoldingRange> {
        let mut ranges: Vec<lsp::FoldingRange> = self
            .analyzed
            .model
            .block_ends()
            .map(|(open, end)| lsp::FoldingRange {
                start_line: open as u32,
                end_line: end as u32,
                ..lsp::FoldingRange::default()
            })
            .collect();
        ranges.sort_by_key(|r| (r.start_line, r.end_line));
        ranges
    }

    /// The fixes of the findings within `range`, each a code action.
    pub fn code_actions(&self, uri: &lsp::Uri, range: lsp::Range) -> Vec<lsp::CodeActionOrCommand> {
        let wanted = convert::span(self.text, range, self.unit);
        let mut actions = Vec::new();
        for found in &self.analyzed.findings {
            let Some(fix) = &found.fix else { continue };
            if found.span.end < wanted.start || wanted.end < found.span.start {
                continue;
            }
            let edits = fix
                .edits
                .iter()
                .map(|edit| lsp::TextEdit {
                    range: self.range(edit.span),
                    new_text: String::from_utf8_lossy(&edit.text).into_owned(),
                })
                .collect();
            let changes = std::iter::once((uri.clone(), edits)).collect();
            actions.push(lsp::CodeActionOrCommand::CodeAction(lsp::CodeAction {
                title: fix.title.clone(),
                kind: Some(lsp::CodeActionKind::QUICKFIX),
                diagnostics: Some(vec![convert::diagnostic(self.text, found, self.unit)]),
                edit: Some(lsp::WorkspaceEdit {
                    changes: Some(changes),
                    ..lsp::WorkspaceEdit::default()
                }),
                is_preferred: Some(fix.applicability == crate::diagnostic::Applicability::Safe),
                ..lsp::CodeAction::default()
            }));
        }
        actions
    }
}

fn contains(span: Span, at: usize) -> bool {
    (span.start..=span.end).contains(&at)
}

fn is_number(text: &str) -> bool {
    !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit())
}

fn markdown(value: String, range: lsp::Range) -> lsp::Hover {
    lsp::Hover {
        contents: lsp::HoverContents::Markup(lsp::MarkupContent {
            kind: lsp::MarkupKind::Markdown,
            value,
        }),
        range: Some(range),
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
