//! What the server answers about one document, read from one analysis of
//! it (the model, the CYCLE600 walk and the table of uses): one file a
//! request, each a method of the [`Snapshot`] the request is answered from.

use lsp_types as lsp;

use crate::diagnostic::Diagnostic;
use crate::document::held;
use crate::document::text::Text;
use crate::lint::Settings;
use crate::semantic::uses::{Namespace, Role, Use, Uses};
use crate::semantic::{Analysis, Model};
use crate::span::{ColumnUnit, Span};

use super::convert;

mod code_actions;
mod definition;
mod diagnostics;
mod folding;
mod hover;
mod inlay_hints;
mod references;
mod rename;
mod semantic_tokens;
mod symbols;

pub(super) use rename::refuse_new_name;

/// The kind of the action that makes every safe fix at once, as ruff names
/// its own (`source.fixAll.ruff`).
pub const FIX_ALL: &str = "source.fixAll.sinuprep";

/// The most findings an editor is given for one document: the rest are
/// counted, not sent. A finding costs a few hundred bytes of JSON, so a
/// program with one on each of its millions of lines would cost gigabytes
/// for no editor to show.
pub const MOST_SHOWN_FINDINGS: usize = 10_000;

/// The most bytes of a program whose words are coloured in one answer: the
/// words of 10 MB of CAM program are megabytes of JSON, asked for again
/// after every change.
pub const MOST_COLOURED_BYTES: usize = 10_000_000;

/// One version of a document, analysed, for the requests about it.
pub struct Snapshot<'a, 't> {
    pub(super) text: &'t Text,
    name: &'a str,
    pub(super) model: &'a Model<'t>,
    walk: Option<&'a Analysis>,
    findings: &'a [Diagnostic],
    analysis: held::Analysis<'a, 't>,
    pub(super) unit: ColumnUnit,
    pub(super) settings: &'a Settings,
    /// Why the document's settings could not be read (it is not checked).
    refused: Option<&'a str>,
}

impl<'a, 't> Snapshot<'a, 't> {
    pub fn new(
        analysis: held::Analysis<'a, 't>,
        name: &'a str,
        settings: &'a Settings,
        unit: ColumnUnit,
        refused: Option<&'a str>,
    ) -> Self {
        let analyzed = analysis.analyzed;
        Self {
            text: analysis.text,
            name,
            model: &analyzed.model,
            walk: analyzed.walk.as_ref(),
            findings: &analyzed.findings,
            analysis,
            unit,
            settings,
            refused,
        }
    }

    pub(super) fn uses(&self) -> &Uses {
        self.analysis.uses()
    }

    fn calls(&self) -> impl Iterator<Item = &crate::semantic::CallSite> {
        self.walk.into_iter().flat_map(|walk| &walk.calls)
    }

    pub(super) fn offset(&self, position: lsp::Position) -> usize {
        convert::offset(self.text, position, self.unit)
    }

    pub(super) fn range(&self, span: Span) -> lsp::Range {
        convert::range(self.text, span, self.unit)
    }

    fn line_text(&self, row: usize) -> String {
        let content = self.model.lines.raw(row).content;
        String::from_utf8_lossy(content.of(self.text.bytes()))
            .trim()
            .to_string()
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

    /// Where a name the program does not define is defined, as the control
    /// finds it: a subprogram's PROC in the program's folder or the cycle
    /// directories, a GUD variable or a macro in the definition files.
    fn defined_elsewhere(&self, found: &Use) -> Option<&(std::path::PathBuf, Span)> {
        let environment = &self.settings.environment;
        match found.namespace {
            Namespace::Subprogram => environment.procedures.get(&found.name)?.defined.as_ref(),
            Namespace::Variable => environment.defined_in.get(&found.name),
            Namespace::Label => None,
        }
    }
}

fn is_block_number(name: &str) -> bool {
    name.strip_prefix('N').is_some_and(is_number)
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
